#pragma once
// The parameters of P3's leg-pair pose estimator, declared once for every plugin that runs it
// (leg_pose, leg_people).
#include "pedtrack/param_table.h"
#include "pedtrack/track/leg_pose_estimator.h"

namespace pedtrack::track {

/// Every key of LegPoseParams, each bound to its member; the defaults are the LegPoseParams a
/// plugin holds (P3's, P3 §2.3–2.5, unless the plugin changes some). A plugin that reads
/// gait_solver = ipopt points gait_solver at gait::fitIpopt (pedtrack/ipopt/gait_fit.h).
const ParamTable<LegPoseParams>& legPoseTable();

}  // namespace pedtrack::track
