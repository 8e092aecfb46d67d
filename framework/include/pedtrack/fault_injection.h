#pragma once
// Fault injection: the `[faults]` section of a pipeline wraps its source, whatever it is, in a
// source that spoils the frames the way broken sensors, drivers and clocks do: non-finite, zero
// and maximum ranges, empty scans and clouds, a 1,000,000-point cloud, timestamps that repeat, go
// back or jump, dropped frames and odometry jumps. Every fault is off by default; what was
// injected is counted under the source in run.json (`faults_*`), what the pipeline noticed under
// `input_warnings` (frame_guard.h). Used by the fault-injection tests and by anyone checking that
// a pipeline survives a bad sensor: `pedtrack run P.ini --set faults.nonfinite_ranges=0.1`.
#include <memory>
#include <vector>

#include "pedtrack/params.h"
#include "pedtrack/plugin.h"

namespace pedtrack {

/// The keys of a `[faults]` section (documented in `pedtrack plugins` style by their docs).
const std::vector<ParamSpec>& faultParams();

/// `source` wrapped by the faults `params` ask for (validated against faultParams()).
std::unique_ptr<Sensor> wrapWithFaults(std::unique_ptr<Sensor> source, const ParamSet& params);

}  // namespace pedtrack
