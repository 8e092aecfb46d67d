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

void setCentroidAndExtent(Cluster& c, const mrpt::maps::CSimplePointsMap& cloud) {
  const auto& xs = cloud.getPointsBufferRef_x();
  const auto& ys = cloud.getPointsBufferRef_y();
  const auto& zs = cloud.getPointsBufferRef_z();
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf}, sum[3] = {0, 0, 0};
  for (std::uint32_t i : c.indices) {
    const double p[3] = {xs[i], ys[i], zs[i]};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
      sum[a] += p[a];
    }
  }
  if (c.indices.empty()) return;
  const double n = double(c.indices.size());
  c.cx = sum[0] / n;
  c.cy = sum[1] / n;
  c.cz = sum[2] / n;
  c.size_x = hi[0] - lo[0];
  c.size_y = hi[1] - lo[1];
  c.size_z = hi[2] - lo[2];
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
  // Width–height projection, a binary image of `pixel` cells over the projection's bounding
  // box: occupied cells (distinct cell keys) over all cells.
  const double nw = std::floor(f.w / pixel) + 1, nh = std::floor((h1 - h0) / pixel) + 1;
  std::vector<std::uint64_t> cells;
  cells.reserve(pts.size());
  for (const auto& p : pts) {
    const double across = -by * p.x() + bx * p.y();
    const double i = std::min(nw - 1, std::floor((across - t0) / pixel));
    const double j = std::min(nh - 1, std::floor((p.z() - h0) / pixel));
    cells.push_back(static_cast<std::uint64_t>(j * nw + i));
  }
  std::sort(cells.begin(), cells.end());
  const auto on = std::unique(cells.begin(), cells.end()) - cells.begin();
  f.rho = double(on) / (nw * nh);
  return f;
}

}  // namespace pedtrack::seg
