#include "pedtrack/sim/raycast.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::sim {

double RayCaster::intoFoliage(const Primitive& p, double t, const Eigen::Vector3d& o,
                              const Eigen::Vector3d& d) {
  // How deep the ray gets before a leaf returns it: exponential with the mean free path. Deeper
  // than the volume along the ray (a sphere's chord; a box's or a cylinder's smaller width), the
  // ray has passed through.
  const double depth = std::exponential_distribution<double>(1.0 / p.foliage)(foliage_rng_);
  double chord = 2 * std::min(p.ru, p.rv);
  if (p.shape == Shape::Sphere) {
    const Eigen::Vector3d oc = p.a - o;
    const double along = oc.dot(d), miss2 = oc.squaredNorm() - along * along;
    chord = 2 * std::sqrt(std::max(0.0, p.ru * p.ru - miss2));
  }
  return depth > chord ? kNoHit : t + depth;
}

void RayCaster::cast(const mrpt::poses::CPose3D& sensor,
                     std::initializer_list<const std::vector<Primitive>*> scene,
                     const Ground& ground, double max_range, RangeImage& out) {
  const RayTable& rays = rays_;
  out.reset(rays.rings(), rays.cols());
  const Eigen::Matrix3d R = sensor.getRotationMatrix().asEigen();
  const Eigen::Vector3d o(sensor.x(), sensor.y(), sensor.z());

  // World directions of every ray, and the ground first: it is behind everything else.
  std::vector<Eigen::Vector3d>& dirs = dirs_;
  dirs.resize(static_cast<std::size_t>(rays.rings()) * rays.cols());
  for (int r = 0; r < rays.rings(); ++r)
    for (int c = 0; c < rays.cols(); ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * rays.cols() + c;
      dirs[i] = R * rays.dir(r, c);
      const double t = ground.intersect(o, dirs[i]);
      if (t <= max_range) {
        out.range[i] = t;
        out.owner[i] = kOwnerGround;
      }
    }

  // Each primitive tests only the rays that can reach its bounding sphere: the columns within
  // its azimuth half-width and the rings within its elevation half-width (sensor frame).
  for (const std::vector<Primitive>* list : scene)
    for (const Primitive& p : *list) {
      Eigen::Vector3d bc;
      double br = 0;
      p.bound(bc, br);
      const Eigen::Vector3d ps = R.transpose() * (bc - o);
      const double rho = std::hypot(ps.x(), ps.y()), dist = ps.norm();
      if (dist - br > max_range) continue;
      const double az = std::atan2(ps.y(), ps.x());
      const double half_az = rho > br ? std::asin(br / rho) : M_PI;
      const double el = std::atan2(ps.z(), rho);
      const double half_el = dist > br ? std::asin(br / dist) : M_PI;
      int ranges[4];
      const int nr = rays.columnRanges(az, half_az, ranges);
      for (int r = 0; r < rays.rings(); ++r) {
        // 2D scanners have one ring at elevation 0 whatever the bound says: test it always.
        if (rays.rings() > 1 && std::abs(rays.ringElevation(r) - el) > half_el + 0.01) continue;
        for (int k = 0; k < nr; ++k)
          for (int c = ranges[2 * k]; c <= ranges[2 * k + 1]; ++c) {
            const std::size_t i = static_cast<std::size_t>(r) * rays.cols() + c;
            double t = intersect(p, o, dirs[i]);
            if (p.foliage > 0 && t < kNoHit) t = intoFoliage(p, t, o, dirs[i]);
            if (t < out.range[i] && t <= max_range) {
              out.range[i] = t;
              out.owner[i] = p.owner;
            }
          }
      }
    }
}

}  // namespace pedtrack::sim
