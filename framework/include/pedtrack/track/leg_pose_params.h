#pragma once
// The parameters of P3's leg-pair pose estimator, declared once for every plugin that runs it
// (leg_pose, leg_people).
#include <vector>

#include "pedtrack/params.h"
#include "pedtrack/track/leg_pose_estimator.h"

namespace pedtrack::track {

/// Declarations with P3's values as defaults (P3 §2.3–2.5).
std::vector<ParamSpec> legPoseParamSpecs();

/// The estimator's parameters from a validated section (gait_solver left null: the caller
/// plugs in Ipopt when the `gait_solver` key asks for it).
LegPoseParams readLegPoseParams(const ParamSet& s);

}  // namespace pedtrack::track
