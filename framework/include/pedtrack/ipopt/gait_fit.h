#pragma once
// P3 eq. 3 solved as the paper states it — a bounded nonlinear least-squares problem in
// (L₀, f, φ, b) — by Ipopt (P3 used NLopt's COBYLA, a local derivative-free method; Ipopt is the
// constrained optimiser this project uses). Local: it starts from `start` (the previous fit, or
// the middle of the bounds). The reference for gait::fitVarPro, and selectable in leg_pose.
#include <vector>

#include "pedtrack/track/gait_model.h"
#include "pedtrack/track/leg_pose_estimator.h"

namespace pedtrack::track::gait {

/// Eq. 3 by Ipopt from `start` (its t_ref is ignored). Invalid with fewer than 5 samples or when
/// Ipopt fails.
Params fitIpopt(const std::vector<Sample>& newest_first, const Bounds& bounds, const Params& start);

/// Points p.gait_solver at fitIpopt when p.solver asks for Ipopt (else leaves it).
void useChosenGaitSolver(LegPoseParams& p);

}  // namespace pedtrack::track::gait
