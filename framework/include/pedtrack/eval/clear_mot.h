#pragma once
// CLEAR MOT (Bernardin & Stiefelhagen 2008) with the frame-walking rules of the leg_tracker
// benchmark's scoring script (Leigh et al., ICRA 2015, clear_mot.py):
//  1. correspondences remembered from earlier frames (track id → truth id) are kept when both ids
//     are present and within the threshold, even if another estimate is closer;
//  2. the remaining truths and estimates get a minimum-distance assignment; pairs farther than the
//     threshold are forbidden (the script lets Munkres pick them and then drops them; forbidding
//     them never yields fewer matches);
//  3. a new match whose track was last matched to another truth, or whose truth was last matched
//     to another track, is one ID switch; unmatched truths are misses, unmatched estimates false
//     positives. MOTA = 1 − (misses + FP + ID switches) / truths; MOTP = mean matched distance.
// Unscored truths (too occluded) may absorb an estimate (not a match, not a false positive) but
// are never misses; such matches do not change the remembered correspondences, so an identity
// change during an occlusion is judged when the person is next scored.
#include <optional>
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct ClearMotOptions {
  double threshold = 0.75;  ///< m, largest distance of a match (inclusive)
  /// Following mode: only this truth id is scored (others become unscored, so they still absorb
  /// their tracks) and false positives are not counted. 0: every truth is the followed person
  /// (a benchmark following recording annotates only them).
  std::optional<long> following;
};

/// A scored truth matched to an estimate in frame `frame` (index into the frames).
struct MatchedPair {
  std::size_t frame = 0;
  Object truth;
  Object estimate;
  double distance = 0;
};

struct ClearMotCounts {
  std::size_t frames = 0;
  std::size_t truths = 0;           ///< scored truth objects over all frames
  std::size_t matches = 0;          ///< scored truths matched (correct + ID switches)
  std::size_t correct = 0;          ///< matches that kept their identity
  std::size_t misses = 0;           ///< scored truths not matched
  std::size_t false_positives = 0;  ///< estimates matched to no truth
  std::size_t id_switches = 0;
  std::size_t fragmentations = 0;  ///< matched → unmatched → matched of a truth (scored frames)
  std::size_t unscored_matches = 0;  ///< estimates absorbed by unscored truths
  double distance_sum = 0;           ///< over matches, m
  double mota() const;               ///< NaN without truths
  double motp() const;               ///< m, NaN without matches
  ClearMotCounts& operator+=(const ClearMotCounts& o);
};

/// One ID switch: where it happened and what came before it.
struct IdSwitch {
  std::size_t frame = 0;  ///< index into the frames
  long truth = 0, track = 0;
  /// The track was last matched to another person (it took someone else's track over); false:
  /// the truth's last track lost them and this one is new to them.
  bool track_from_other = false;
  /// s since the truth was last matched (scored), NaN if never before (a track from another
  /// person took a person over at their first match).
  double gap = 0;
  /// Frames of that gap in which the truth was present, and of those how many it was unscored
  /// (too few returns: out of sight, behind others).
  std::size_t gap_frames = 0, gap_unscored = 0;
};

struct ClearMotResult {
  ClearMotCounts counts;
  std::vector<MatchedPair> pairs;  ///< every scored match, in frame order
  /// Per frame: indices of the estimates absorbed by unscored truths.
  std::vector<std::vector<std::size_t>> absorbed;
  /// Per frame: indices of the scored truths, of those missed, and of the estimates counted as
  /// false positives (none when following).
  std::vector<std::vector<std::size_t>> scored, missed, unmatched;
  std::vector<IdSwitch> switches;  ///< every ID switch, in frame order
};

ClearMotResult clearMot(const std::vector<EvalFrame>& frames, const ClearMotOptions& options);

/// The frames without unscored truths and without the estimates they absorbed (the way
/// TrackEval's MOT Challenge preprocessing removes distractors), for IDF1 and HOTA.
std::vector<EvalFrame> withoutUnscored(const std::vector<EvalFrame>& frames,
                                       const ClearMotResult& clear);

}  // namespace pedtrack::eval
