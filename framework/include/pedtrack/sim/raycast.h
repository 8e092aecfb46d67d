#pragma once
// Casts every ray of one scan against the ground and the scene's primitives, keeping the first
// surface hit per ray, so occlusion between people and objects falls out of the geometry.
#include <mrpt/poses/CPose3D.h>

#include <initializer_list>
#include <vector>

#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {

class RayCaster {
 public:
  explicit RayCaster(const RayTable& rays) : rays_(rays) {}
  /// `sensor` is the sensor pose in the world; `scene` the primitive lists to cast against
  /// (static objects, people). Rays beyond `max_range` see nothing.
  void cast(const mrpt::poses::CPose3D& sensor,
            std::initializer_list<const std::vector<Primitive>*> scene, const Ground& ground,
            double max_range, RangeImage& out);

 private:
  const RayTable& rays_;
  std::vector<Eigen::Vector3d> dirs_;  // world directions of the current scan, reused
};

}  // namespace pedtrack::sim
