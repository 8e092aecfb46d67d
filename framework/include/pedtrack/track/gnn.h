#pragma once
// Global nearest neighbour association: tracks × measurements, the cheapest one-to-one
// assignment of pairs whose cost is within a gate, solved by the shared `solveAssignment`.
#include <functional>
#include <vector>

#include "pedtrack/assignment.h"

namespace pedtrack::track {

/// `cost(track, measurement)` (NaN or > gate forbids the pair); returns measurement per track
/// (-1 = none) and track per measurement.
Assignment gnnAssociate(int tracks, int measurements, const std::function<double(int, int)>& cost,
                        double gate);

}  // namespace pedtrack::track
