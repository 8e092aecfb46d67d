// Bounding boxes (convex hull + rotating calipers, Zhang et al.'s L-shape) and centroids. Written
// by hand: the framework does not link OpenCV (tests/test_fit_shapes.cpp compares minAreaBox with
// cv::minAreaRect).
#include "pedtrack/fit/boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pedtrack::fit {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The rectangle with sides along (cos a, sin a) and its normal spanning the points' extents.
OrientedBox extentsBox(const Points2& pts, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  double lo1 = std::numeric_limits<double>::infinity(), hi1 = -lo1, lo2 = lo1, hi2 = -lo1;
  for (const auto& p : pts) {
    const double d1 = c * p.x() + s * p.y(), d2 = -s * p.x() + c * p.y();
    lo1 = std::min(lo1, d1);
    hi1 = std::max(hi1, d1);
    lo2 = std::min(lo2, d2);
    hi2 = std::max(hi2, d2);
  }
  const double m1 = 0.5 * (lo1 + hi1), m2 = 0.5 * (lo2 + hi2);
  OrientedBox b;
  b.x = c * m1 - s * m2;
  b.y = s * m1 + c * m2;
  b.angle = angle;
  b.half_a = 0.5 * (hi1 - lo1);
  b.half_b = 0.5 * (hi2 - lo2);
  return b;
}

}  // namespace

double wrapHalfPi(double a) {
  a = std::remainder(a, M_PI);
  return a <= -M_PI / 2 ? a + M_PI : a;
}

Points2 convexHull(const Points2& pts) {
  Points2 p = pts;
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  Points2 h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);  // the last point is the first
  return h;
}

bool minAreaBox(const Points2& pts, OrientedBox& out) {
  if (pts.empty()) return false;
  const Points2 h = convexHull(pts);
  if (h.size() == 1) {
    out = OrientedBox{h[0].x(), h[0].y(), 0, 0, 0};
    return true;
  }
  double best_area = std::numeric_limits<double>::infinity();
  const std::size_t edges = h.size() == 2 ? 1 : h.size();
  for (std::size_t i = 0; i < edges; ++i) {
    const Eigen::Vector2d e = h[(i + 1) % h.size()] - h[i];
    const OrientedBox b = extentsBox(h, wrapHalfPi(std::atan2(e.y(), e.x())));
    const double area = b.half_a * b.half_b;
    if (area < best_area) {
      best_area = area;
      out = b;
    }
  }
  return true;
}

bool lShapeBox(const Points2& pts, OrientedBox& out, double step, double min_distance) {
  if (pts.empty()) return false;
  if (!(step > 0)) step = M_PI / 180;
  const double inf = std::numeric_limits<double>::infinity();
  double best_score = -inf, best_angle = 0;
  for (int k = 0;; ++k) {
    const double th = k * step;
    if (!(th < M_PI / 2)) break;
    const double c = std::cos(th), s = std::sin(th);
    // Extents and the mean of each coordinate, to pick the closer edge of each direction.
    double lo1 = inf, hi1 = -inf, lo2 = inf, hi2 = -inf, s1 = 0, s2 = 0;
    for (const auto& p : pts) {
      const double d1 = c * p.x() + s * p.y(), d2 = -s * p.x() + c * p.y();
      lo1 = std::min(lo1, d1);
      hi1 = std::max(hi1, d1);
      lo2 = std::min(lo2, d2);
      hi2 = std::max(hi2, d2);
      s1 += d1;
      s2 += d2;
    }
    // Zhang et al.'s D₁ = argmin(‖c_max − C‖, ‖C − c_min‖): ‖c_max − C‖² − ‖C − c_min‖² =
    // 2n(c_max − c_min)(mid − mean), so the closer edge is the one on the mean's side.
    const double n = double(pts.size());
    const bool use_hi1 = s1 / n > 0.5 * (lo1 + hi1), use_hi2 = s2 / n > 0.5 * (lo2 + hi2);
    double score = 0;
    for (const auto& p : pts) {
      const double d1 = c * p.x() + s * p.y(), d2 = -s * p.x() + c * p.y();
      const double e1 = use_hi1 ? hi1 - d1 : d1 - lo1, e2 = use_hi2 ? hi2 - d2 : d2 - lo2;
      score += 1 / std::max(std::min(e1, e2), min_distance);
    }
    if (score > best_score) {
      best_score = score;
      best_angle = th;
    }
  }
  out = extentsBox(pts, wrapHalfPi(best_angle));
  return true;
}

Eigen::Vector2d centroid(const Points2& pts) {
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (const auto& p : pts) m += p;
  return pts.empty() ? m : Eigen::Vector2d(m / double(pts.size()));
}

Eigen::Vector2d centroidBehindSurface(const Points2& pts, const Eigen::Vector2d& origin,
                                      double offset) {
  const Eigen::Vector2d c = centroid(pts);
  const Eigen::Vector2d sight = c - origin;
  const double d = sight.norm();
  return d > 0 ? Eigen::Vector2d(c + sight * (offset / d)) : c;
}

}  // namespace pedtrack::fit
