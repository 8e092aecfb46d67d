// Shape features of a 3D cluster beyond P2's six: where it stands (range, lowest point), how its
// points spread (principal axes), its profile in height slices (a person's legs, hips, shoulders
// and head; a post's constant width; a bush's ball; a car's long low box), a density that does
// not fall with range, and how much narrower its top is than what is below it (a head on
// shoulders).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "pedtrack/seg/cluster_features.h"

namespace pedtrack::seg {
namespace {

constexpr int kSlices = 5;
constexpr double kSlice = 0.4;  // m: 0-0.4 (feet, shins), ... 1.6-2.0 (heads)

}  // namespace

const std::vector<std::string>& shapeFeatureNames() {
  static const std::vector<std::string> names = {
      "range", "zmin", "s1", "s2", "s3", "linearity", "planarity", "scatter", "vertical",
      "w0",    "w1",   "w2", "w3", "w4", "d0",        "d1",        "d2",      "d3",
      "d4",    "p0",   "p1", "p2", "p3", "p4",        "density",   "head"};
  return names;
}

void appendShapeFeatures(const std::vector<Eigen::Vector3d>& pts, double su, double sv,
                         std::vector<double>& out) {
  const std::size_t first = out.size();
  out.resize(first + shapeFeatureNames().size(), 0.0);
  if (pts.empty()) return;
  double* f = out.data() + first;
  const double n = double(pts.size());
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : pts) c += p;
  c /= n;
  // Bearing frame: across (width) and along (depth) the line from the sensor.
  double bx = c.x() - su, by = c.y() - sv;
  const double range = std::hypot(bx, by);
  if (range > 1e-9)
    bx /= range, by /= range;
  else
    bx = 1, by = 0;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  constexpr double inf = std::numeric_limits<double>::infinity();
  double zmin = inf, zmax = -inf;
  double lo_w[kSlices], hi_w[kSlices], lo_d[kSlices], hi_d[kSlices];
  int count[kSlices] = {0, 0, 0, 0, 0};
  std::fill(lo_w, lo_w + kSlices, inf), std::fill(hi_w, hi_w + kSlices, -inf);
  std::fill(lo_d, lo_d + kSlices, inf), std::fill(hi_d, hi_d + kSlices, -inf);
  double w_lo = inf, w_hi = -inf;
  for (const auto& p : pts) {
    const Eigen::Vector3d q = p - c;
    cov += q * q.transpose();
    zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    const double across = -by * p.x() + bx * p.y(), along = bx * p.x() + by * p.y();
    w_lo = std::min(w_lo, across), w_hi = std::max(w_hi, across);
    const int k = std::clamp(int(std::floor(p.z() / kSlice)), 0, kSlices - 1);
    ++count[k];
    lo_w[k] = std::min(lo_w[k], across), hi_w[k] = std::max(hi_w[k], across);
    lo_d[k] = std::min(lo_d[k], along), hi_d[k] = std::max(hi_d[k], along);
  }
  cov /= n;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d ev = eig.eigenvalues().cwiseMax(0.0);  // ascending
  const double s1 = std::sqrt(ev(2)), s2 = std::sqrt(ev(1)), s3 = std::sqrt(ev(0));
  f[0] = range;
  f[1] = zmin;
  f[2] = s1, f[3] = s2, f[4] = s3;
  const double denom = std::max(s1, 1e-6);
  f[5] = (s1 - s2) / denom;
  f[6] = (s2 - s3) / denom;
  f[7] = s3 / denom;
  f[8] = std::abs(eig.eigenvectors().col(2).z());  // the main axis upright: 1
  for (int k = 0; k < kSlices; ++k) {
    f[9 + k] = count[k] ? hi_w[k] - lo_w[k] : 0;
    f[14 + k] = count[k] ? hi_d[k] - lo_d[k] : 0;
    f[19 + k] = count[k] / n;
  }
  // Points per square metre of the width-height projection, times range²: a solid surface's
  // returns thin as 1/range², so this stays put for one sensor at any range.
  const double area = std::max(0.01, (w_hi - w_lo) * (zmax - zmin));
  f[24] = n * range * range / area / 1000;
  // Width of the top 0.3 m over the width of the 0.3 m below it: a head on shoulders ~0.5, a
  // post 1, a bush's crown near 1.
  double top_lo = inf, top_hi = -inf, mid_lo = inf, mid_hi = -inf;
  for (const auto& p : pts) {
    const double across = -by * p.x() + bx * p.y();
    if (p.z() >= zmax - 0.3)
      top_lo = std::min(top_lo, across), top_hi = std::max(top_hi, across);
    else if (p.z() >= zmax - 0.6)
      mid_lo = std::min(mid_lo, across), mid_hi = std::max(mid_hi, across);
  }
  f[25] = mid_hi > mid_lo ? (top_hi - top_lo) / std::max(0.02, mid_hi - mid_lo) : 1.0;
}

}  // namespace pedtrack::seg
