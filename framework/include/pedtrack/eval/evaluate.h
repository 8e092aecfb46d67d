#pragma once
// Every tracking metric over one or several (Monte Carlo) runs, pooled.
#include <cmath>
#include <optional>
#include <vector>

#include "pedtrack/eval/clear_mot.h"
#include "pedtrack/eval/consistency.h"
#include "pedtrack/eval/error_budget.h"
#include "pedtrack/eval/hota.h"
#include "pedtrack/eval/identity.h"
#include "pedtrack/eval/pair_errors.h"

namespace pedtrack::eval {

struct TrackingOptions {
  double threshold = 0.75;              ///< m, match distance (CLEAR MOT, IDF1, distractor removal)
  std::optional<long> following;        ///< score only this truth id, ignore false positives
  double hota_distance = std::nan("");  ///< τ of HOTA's similarity; NaN: the threshold
  int nis_dof = 2;
};

struct TrackingReport {
  std::size_t runs = 0;
  ClearMotCounts clear;  ///< summed over runs (MOTA, MOTP pooled)
  ErrorBudget budget;    ///< where the misses and false positives are, summed over runs
  PairErrors errors;
  /// Not computed in following mode (the benchmark's following score is CLEAR MOT only).
  std::optional<IdentityCounts> identity;
  std::optional<HotaResult> hota;
  std::optional<ConsistencyReport> nees;  ///< when some matched track has a covariance
  std::optional<ConsistencyReport> nis;   ///< when some matched track has a nis value
};

/// `runs[r]` are the aligned frames of run r (frame index k = the k-th time of that run).
TrackingReport evaluateTracking(const std::vector<std::vector<EvalFrame>>& runs,
                                const TrackingOptions& options);

}  // namespace pedtrack::eval
