#include "pedtrack/seg/cluster_features.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pedtrack::seg {

GroundAligned::GroundAligned(const GroundPlane& g) {
  if (!g.valid) return;
  const Eigen::Vector3d n = Eigen::Vector3d(g.nx, g.ny, g.nz).normalized();
  R_ = Eigen::Quaterniond::FromTwoVectors(n, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  offset_ = g.d / Eigen::Vector3d(g.nx, g.ny, g.nz).norm();
}

const std::vector<std::string>& p2FeatureNames() {
  static const std::vector<std::string> names = {"h", "w", "d", "v", "lambda", "rho"};
  return names;
}

P2Features p2Features(const std::vector<Eigen::Vector3d>& pts, double su, double sv, double pixel) {
  P2Features f;
  if (pts.empty()) return f;
  // Bearing from the sensor to the centroid: depth along it, width across it.
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : pts) c += p;
  c /= double(pts.size());
  double bx = c.x() - su, by = c.y() - sv;
  const double bn = std::hypot(bx, by);
  if (bn > 1e-9) {
    bx /= bn;
    by /= bn;
  } else {
    bx = 1;
    by = 0;
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  double a0 = inf, a1 = -inf, t0 = inf, t1 = -inf, h0 = inf, h1 = -inf;
  for (const auto& p : pts) {
    const double along = bx * p.x() + by * p.y(), across = -by * p.x() + bx * p.y();
    a0 = std::min(a0, along);
    a1 = std::max(a1, along);
    t0 = std::min(t0, across);
    t1 = std::max(t1, across);
    h0 = std::min(h0, p.z());
    h1 = std::max(h1, p.z());
  }
  f.h = h1;
  f.w = t1 - t0;
  f.d = a1 - a0;
  f.v = f.w * f.d * (h1 - h0);
  std::size_t top = 0;
  for (const auto& p : pts) top += p.z() > 0.5 * f.h;
  f.lambda = double(top) / double(pts.size());
  // Width–height projection, binary image of `pixel` cells over the projection's bounding box.
  const int nw = static_cast<int>(std::floor(f.w / pixel)) + 1;
  const int nh = static_cast<int>(std::floor((h1 - h0) / pixel)) + 1;
  std::vector<std::uint8_t> img(static_cast<std::size_t>(nw) * nh, 0);
  std::size_t on = 0;
  for (const auto& p : pts) {
    const double across = -by * p.x() + bx * p.y();
    const int i = std::min(nw - 1, static_cast<int>(std::floor((across - t0) / pixel)));
    const int j = std::min(nh - 1, static_cast<int>(std::floor((p.z() - h0) / pixel)));
    auto& cell = img[static_cast<std::size_t>(j) * nw + i];
    on += cell == 0;
    cell = 1;
  }
  f.rho = double(on) / double(img.size());
  return f;
}

}  // namespace pedtrack::seg
