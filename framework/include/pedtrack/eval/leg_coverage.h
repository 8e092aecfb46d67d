#pragma once
// People tracks against hand-labelled legs (leg_tracker's *_extracted.bags label every human leg
// cluster of a scan, not people): how many labelled legs have a track near them, and how many
// track rows are near no labelled leg. A person's track lies between their legs, so one track
// may cover both; there is no one-to-one matching and no identity, only coverage.
#include <map>
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct LegCoverage {
  long legs = 0;         ///< labelled legs in the scored frames
  long covered = 0;      ///< ... with an estimate within the threshold
  long rows = 0;         ///< estimate rows in the scored frames
  long unsupported = 0;  ///< ... with no labelled leg within the threshold
  /// Per estimate id: its rows, and those near a labelled leg.
  std::map<long, std::pair<long, long>> per_track;
  /// Tracks with at most `lone_share` of their rows near a labelled leg: on no person.
  long tracksOnNoPerson(double lone_share = 0.1) const;
  double recall() const { return legs ? double(covered) / double(legs) : 0.0; }
};

/// Truths are the labelled legs, estimates the tracks (same frame, e.g. the laser frame).
LegCoverage legCoverage(const std::vector<EvalFrame>& frames, double threshold);

}  // namespace pedtrack::eval
