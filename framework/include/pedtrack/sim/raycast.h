#pragma once
// Casts every ray of one scan against the ground and the scene's primitives, keeping the first
// surface hit per ray, so occlusion between people and objects falls out of the geometry.
#include <mrpt/poses/CPose3D.h>

#include <vector>

#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {

/// `sensor` is the sensor pose in the world. Rays beyond `max_range` see nothing.
void castScan(const RayTable& rays, const mrpt::poses::CPose3D& sensor,
              const std::vector<Primitive>& scene, const Ground& ground, double max_range,
              RangeImage& out);

}  // namespace pedtrack::sim
