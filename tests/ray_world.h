#pragma once
// A 2D world of wall segments and circles (legs, pillars) in the fixed frame, and the range a ray
// cast into it meets: the synthetic scans of the static-scene and scan-odometry tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace pedtrack::test {

struct RayWorld {
  std::vector<std::array<double, 4>> walls;    // x0, y0, x1, y1
  std::vector<std::array<double, 3>> circles;  // x, y, r
};

/// Distance along the unit direction (dx, dy) from (ox, oy) to the first wall or circle hit,
/// infinity when none.
inline double castRay(const RayWorld& w, double ox, double oy, double dx, double dy) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : w.walls) {
    const double ex = s[2] - s[0], ey = s[3] - s[1];
    const double den = dx * ey - dy * ex;
    if (std::abs(den) < 1e-12) continue;
    const double t = ((s[0] - ox) * ey - (s[1] - oy) * ex) / den;
    const double u = ((s[0] - ox) * dy - (s[1] - oy) * dx) / den;
    if (t > 1e-6 && u >= 0 && u <= 1) best = std::min(best, t);
  }
  for (const auto& c : w.circles) {
    const double fx = ox - c[0], fy = oy - c[1];
    const double b = fx * dx + fy * dy, q = fx * fx + fy * fy - c[2] * c[2];
    const double disc = b * b - q;
    if (disc < 0) continue;
    const double t = -b - std::sqrt(disc);
    if (t > 1e-6) best = std::min(best, t);
  }
  return best;
}

}  // namespace pedtrack::test
