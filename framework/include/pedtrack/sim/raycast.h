#pragma once
// Casts every ray of one scan against the ground and the scene's primitives, keeping the first
// surface hit per ray, so occlusion between people and objects falls out of the geometry.
#include <mrpt/poses/CPose3D.h>

#include <initializer_list>
#include <random>
#include <vector>

#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {

class RayCaster {
 public:
  /// `seed` seeds the depths rays reach into foliage (a stream of their own).
  explicit RayCaster(const RayTable& rays, unsigned long seed = 1)
      : rays_(rays), foliage_rng_(seed ^ 0x6a09e667f3bcc909ull) {}
  /// `sensor` is the sensor pose in the world; `scene` the primitive lists to cast against
  /// (static objects, people). Rays beyond `max_range` see nothing.
  void cast(const mrpt::poses::CPose3D& sensor,
            std::initializer_list<const std::vector<Primitive>*> scene, const Ground& ground,
            double max_range, RangeImage& out);

 private:
  // Where a ray from o along d that meets foliage `p` at range t returns, or kNoHit (it passes
  // through).
  double intoFoliage(const Primitive& p, double t, const Eigen::Vector3d& o,
                     const Eigen::Vector3d& d);
  const RayTable& rays_;
  std::vector<Eigen::Vector3d> dirs_;  // world directions of the current scan, reused
  std::mt19937_64 foliage_rng_;
};

}  // namespace pedtrack::sim
