#pragma once
// How far each person the scan hit is from everything else it hit: the truth behind scoring a
// segmenter only on people it could have separated (`pedtrack eval --isolation`).
#include <utility>
#include <vector>

#include "pedtrack/point_labels.h"
#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {

/// For every person with a hit in `img`: the smallest 3D distance from one of its hits to a hit
/// of another person or an object (the ground does not count), capped at `cap` (m). Hits are
/// the true surface points (no range noise).
std::vector<PersonClearance> personClearance(const RangeImage& img, const RayTable& rays,
                                             double cap);

}  // namespace pedtrack::sim
