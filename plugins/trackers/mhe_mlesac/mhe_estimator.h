#pragma once
// The torso estimator of mhe_mlesac (P0 §V): a KF on P0's model (eq. 2) observed by the RANSAC
// ellipse of every frame runs alongside; it is the estimate until the track has H frames, and
// its prior gives the arrival cost. From then on each frame's estimate is the last state of the
// MHE-MLESAC window (mhe_mlesac.h), with the KF's estimate as the fallback when Ipopt fails.
// P0's θ is the major axis (α along θ); the output converts to pedtrack's torso convention: the
// facing direction is θ ± π/2 (the side the person walks to; kept while standing), α the
// semi-axis across the shoulders.
#include <memory>

#include "mhe_mlesac/mlesac_select.h"
#include "pedtrack/track/shape_observation.h"
#include "pedtrack/track/torso_estimator.h"

namespace pedtrack::track {

struct MheEstimatorParams {
  mhe::MheParams mhe;
  mhe::MlesacOptions mlesac;
  mhe::SolverOptions solver;
  /// The KF's per-frame ellipse (its RANSAC, N_e, N_b and R_e; R_p when only the centre is seen).
  ShapeObservationParams observation;
  double flip_speed = 0.2;        ///< faster than this, the facing side follows the velocity (m/s)
  double init_speed_sigma = 1.0;  ///< a new track's velocity uncertainty (m/s)
  double init_size_sigma = 0.05;  ///< a new track's semi-axis uncertainty (m)
  /// P0's "RANSAC only" comparison: report the KF alongside (P0's model observed by the RANSAC
  /// ellipse of each frame) and never run the MHE.
  bool kf_only = false;
};

/// What the estimators of one tracker did, for run.json.
struct MheCounters {
  long windows = 0;     ///< MHE-MLESAC runs
  long candidates = 0;  ///< distinct candidates generated
  long solves = 0;      ///< Ipopt solves
  long failed = 0;      ///< Ipopt solves that failed (infeasible, iteration limit, error)
  long fallbacks = 0;   ///< windows whose estimate fell back to the KF
};

/// `counters` (may be null) accumulates over every track.
TorsoEstimatorFactory mheTorsoEstimators(const MheEstimatorParams& params,
                                         std::shared_ptr<MheCounters> counters);

}  // namespace pedtrack::track
