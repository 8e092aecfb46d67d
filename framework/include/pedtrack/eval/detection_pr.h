#pragma once
// Detection precision / recall with per-scan matching: in every frame the detections and the
// truth points get a minimum-distance assignment, pairs farther than the threshold forbidden.
// A detection matched to a scored truth point is a TP, an unmatched detection an FP, an unmatched
// scored truth point an FN; a detection matched to an unscored truth point is neither.
#include <map>
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct DetectionCounts {
  std::size_t frames = 0;
  std::size_t truth_points = 0;  ///< scored truth points
  std::size_t detections = 0;
  std::size_t tp = 0, fp = 0, fn = 0;
  std::size_t unscored_matches = 0;
  double distance_sum = 0;  ///< over TPs, m
  /// Scored truth points by distance from the sensor: bin k holds [k·range_bin, (k+1)·range_bin)
  /// m; per bin (TP, FN). Truths of unknown range are left out.
  std::map<int, std::pair<std::size_t, std::size_t>> by_range;
  double range_bin = 1.0;
  double precision() const;  ///< TP / (TP + FP), NaN when 0/0
  double recall() const;     ///< TP / (TP + FN)
  double f1() const;         ///< 2·TP / (2·TP + FP + FN)
  double meanDistance() const;
  DetectionCounts& operator+=(const DetectionCounts& o);
};

/// `frames[k].estimates` are the detections; recall is also binned by range (`range_bin` m).
DetectionCounts detectionPR(const std::vector<EvalFrame>& frames, double threshold,
                            double range_bin = 1.0);

}  // namespace pedtrack::eval
