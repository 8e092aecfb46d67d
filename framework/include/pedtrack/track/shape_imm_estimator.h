#pragma once
// The torso estimator of imm_shape, kf_bb and kf_circle (P1 §III–IV): an IMM whose filters share
// the motion model of P1 eq. 2 and differ in how they observe the points (ellipse, bounding box,
// centre of gravity, circle; shape_observation.h). One filter alone is a plain KF.
#include "pedtrack/track/shape_tracker.h"
#include "pedtrack/track/torso_estimator.h"

namespace pedtrack::track {

/// The estimators of `params.models` with transition matrix `params.transition`;
/// std::invalid_argument for an inconsistent Π.
TorsoEstimatorFactory immTorsoEstimators(const ShapeTrackerParams& params);

}  // namespace pedtrack::track
