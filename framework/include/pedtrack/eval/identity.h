#pragma once
// Identity metrics (Ristani et al., ECCV 2016 workshops, "Performance Measures and a Data Set for
// Multi-Target, Multi-Camera Tracking"): one global one-to-one assignment of truth ids to track
// ids that maximises IDTP, the number of frames where a matched pair is within the threshold.
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct IdentityCounts {
  double idtp = 0;      ///< truth objects covered by their assigned track within the threshold
  double idfn = 0;      ///< truth objects not covered (all truth objects − IDTP)
  double idfp = 0;      ///< track objects not covering their assigned truth (all tracks − IDTP)
  double idf1() const;  ///< 2·IDTP / (2·IDTP + IDFP + IDFN); NaN when there is nothing
  double idp() const;   ///< IDTP / (IDTP + IDFP)
  double idr() const;   ///< IDTP / (IDTP + IDFN)
  IdentityCounts& operator+=(const IdentityCounts& o);
};

/// IDF1 over `frames` (every truth is scored: remove unscored ones first, see withoutUnscored).
/// A (truth, track) pair counts in a frame when both are present and at most `threshold` apart.
IdentityCounts identity(const std::vector<EvalFrame>& frames, double threshold);

}  // namespace pedtrack::eval
