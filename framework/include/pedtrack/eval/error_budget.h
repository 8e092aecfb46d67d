#pragma once
// Where MOTA's errors are (ours, #45): the misses by how many returns hit the person, and the
// false positives by how far they lie from the nearest person and whether the track was
// coasting. A miss of a person hit by three returns asks for another fix than a miss of one in
// plain view, and a false positive beside a person (a track that drifted or lags off them, a
// fragment of them) for another fix than one on no person (a bin or a hedge taken for one).
// ID switches go by how long the person had not been matched: a swap while two people pass
// (< 0.5 s) asks for another fix than a person found again after seconds out of sight.
#include <array>
#include <cstddef>
#include <vector>

#include "pedtrack/eval/clear_mot.h"
#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct ErrorBudget {
  /// Scored truths by truth.csv's visible_points: 0–9, 10–29, ≥ 30, unknown (no column).
  static constexpr std::size_t kVisibleBins = 4;
  static constexpr std::array<long, 2> kVisibleEdges{10, 30};
  std::array<std::size_t, kVisibleBins> truths_by_visible{}, misses_by_visible{};
  /// False positives by the distance to the nearest truth of their frame (scored or not):
  /// < 1 m, 1–2 m, ≥ 2 m (or no truth in the frame).
  static constexpr std::size_t kDistanceBins = 3;
  static constexpr std::array<double, 2> kDistanceEdges{1.0, 2.0};
  std::array<std::size_t, kDistanceBins> fp_by_distance{}, coasting_fp_by_distance{};
  /// ID switches by the time since the person was last matched: < 0.5 s, 0.5–2 s, ≥ 2 s, and
  /// never matched before (a track taking a new person over); of those, how many by a track
  /// that was on another person, and how many after a gap the person spent mostly unscored
  /// (out of sight: more than half its frames).
  static constexpr std::size_t kGapBins = 4;
  static constexpr std::array<double, 2> kGapEdges{0.5, 2.0};
  std::array<std::size_t, kGapBins> switches_by_gap{}, switches_from_other_by_gap{},
      switches_unseen_by_gap{};
  ErrorBudget& operator+=(const ErrorBudget& o);
};

/// The budget of one run: `clear` is clearMot(frames, ...) of the same frames.
ErrorBudget errorBudget(const std::vector<EvalFrame>& frames, const ClearMotResult& clear);

}  // namespace pedtrack::eval
