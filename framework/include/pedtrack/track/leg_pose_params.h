#pragma once
// The parameters of P3's leg-pair pose estimator, declared once for every plugin that runs it
// (leg_pose, leg_people).
#include <vector>

#include "pedtrack/params.h"
#include "pedtrack/track/leg_pose_estimator.h"

namespace pedtrack::track {

/// Declarations with `defaults`' values (P3's, P3 §2.3–2.5, unless a plugin changes some).
std::vector<ParamSpec> legPoseParamSpecs(const LegPoseParams& defaults = LegPoseParams{});

/// The estimator's parameters from a validated section (gait_solver left null: the caller
/// plugs in Ipopt when the `gait_solver` key asks for it).
LegPoseParams readLegPoseParams(const ParamSet& s);

}  // namespace pedtrack::track
