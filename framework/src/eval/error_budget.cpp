#include "pedtrack/eval/error_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pedtrack::eval {
namespace {

std::size_t visibleBin(const Object& truth) {
  if (!truth.row || truth.row->visible_points < 0) return ErrorBudget::kVisibleBins - 1;
  const auto& e = ErrorBudget::kVisibleEdges;
  return std::size_t(std::upper_bound(e.begin(), e.end(), truth.row->visible_points) - e.begin());
}

std::size_t distanceBin(double d) {
  const auto& e = ErrorBudget::kDistanceEdges;
  return std::size_t(std::upper_bound(e.begin(), e.end(), d) - e.begin());
}

std::size_t gapBin(double gap) {
  if (std::isnan(gap)) return ErrorBudget::kGapBins - 1;
  const auto& e = ErrorBudget::kGapEdges;
  return std::size_t(std::upper_bound(e.begin(), e.end(), gap) - e.begin());
}

}  // namespace

ErrorBudget& ErrorBudget::operator+=(const ErrorBudget& o) {
  for (std::size_t b = 0; b < kVisibleBins; ++b) {
    truths_by_visible[b] += o.truths_by_visible[b];
    misses_by_visible[b] += o.misses_by_visible[b];
  }
  for (std::size_t b = 0; b < kDistanceBins; ++b) {
    fp_by_distance[b] += o.fp_by_distance[b];
    coasting_fp_by_distance[b] += o.coasting_fp_by_distance[b];
  }
  for (std::size_t b = 0; b < kGapBins; ++b) {
    switches_by_gap[b] += o.switches_by_gap[b];
    switches_from_other_by_gap[b] += o.switches_from_other_by_gap[b];
    switches_unseen_by_gap[b] += o.switches_unseen_by_gap[b];
  }
  return *this;
}

ErrorBudget errorBudget(const std::vector<EvalFrame>& frames, const ClearMotResult& clear) {
  ErrorBudget b;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const EvalFrame& f = frames[k];
    if (k < clear.scored.size())
      for (std::size_t i : clear.scored[k]) ++b.truths_by_visible[visibleBin(f.truths[i])];
    if (k < clear.missed.size())
      for (std::size_t i : clear.missed[k]) ++b.misses_by_visible[visibleBin(f.truths[i])];
    if (k >= clear.unmatched.size()) continue;
    for (std::size_t j : clear.unmatched[k]) {
      const Object& e = f.estimates[j];
      double nearest = std::numeric_limits<double>::infinity();
      for (const Object& t : f.truths) nearest = std::min(nearest, distance(t, e));
      const std::size_t bin = distanceBin(nearest);
      ++b.fp_by_distance[bin];
      if (e.row && e.row->status == "coasting") ++b.coasting_fp_by_distance[bin];
    }
  }
  for (const IdSwitch& s : clear.switches) {
    const std::size_t bin = gapBin(s.gap);
    ++b.switches_by_gap[bin];
    if (s.track_from_other) ++b.switches_from_other_by_gap[bin];
    if (2 * s.gap_unscored > s.gap_frames) ++b.switches_unseen_by_gap[bin];
  }
  return b;
}

}  // namespace pedtrack::eval
