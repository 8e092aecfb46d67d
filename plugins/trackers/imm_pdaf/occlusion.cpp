#include "imm_pdaf/occlusion.h"

#include <cmath>

namespace pedtrack::track {

OcclusionMap::OcclusionMap(const Frame& f, double margin)
    : sensor_(f.sensor_pose), margin_(margin) {
  const mrpt::poses::CPose3D mount = f.sensorMount();
  shadows_.reserve(f.clusters.size());
  for (const Cluster& c : f.clusters) {
    double sx, sy, sz;
    mount.inverseComposePoint(c.cx, c.cy, c.cz, sx, sy, sz);
    const double range = std::hypot(sx, sy);
    if (range < 1e-3) continue;
    const double half = 0.5 * std::hypot(c.size_x, c.size_y) + margin_;
    shadows_.push_back({std::atan2(sy, sx), std::atan(half / range), range});
  }
}

bool OcclusionMap::hidden(double x, double y, double radius) const {
  double sx, sy, sz;
  sensor_.inverseComposePoint(x, y, sensor_.z(), sx, sy, sz);
  const double range = std::hypot(sx, sy);
  if (range < 1e-3) return false;
  const double bearing = std::atan2(sy, sx), own = std::atan(radius / range);
  for (const Shadow& s : shadows_) {
    if (s.range > range - margin_) continue;
    const double d = std::abs(std::remainder(bearing - s.bearing, 2 * M_PI));
    if (d < s.half_width + own) return true;
  }
  return false;
}

}  // namespace pedtrack::track
