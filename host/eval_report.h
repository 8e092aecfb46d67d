#pragma once
// `pedtrack eval` output: a readable table, or one JSON object with every number.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pedtrack/eval/detection_pr.h"
#include "pedtrack/eval/evaluate.h"
#include "pedtrack/eval/leg_coverage.h"
#include "pedtrack/eval/segmentation.h"

namespace pedtrack::cli {

/// What the numbers were computed from, echoed in both formats.
struct EvalSetup {
  double threshold = 0;
  std::string frame = "fixed";  ///< fixed | sensor
  long min_visible = 1;
  std::optional<long> following;
  double hota_distance = 0;
  std::string truth_source = "csv";  ///< csv | bag
  bool legs = false;
};

std::string trackingText(const eval::TrackingReport& r, const EvalSetup& s);
/// `extra`: keys appended to the object with their raw JSON values (e.g. range_bands).
std::string trackingJson(const eval::TrackingReport& r, const EvalSetup& s,
                         const std::vector<std::pair<std::string, std::string>>& extra = {});
std::string detectionText(const eval::DetectionCounts& c, const EvalSetup& s);
std::string detectionJson(const eval::DetectionCounts& c, const EvalSetup& s);
/// Tracks against a labelled bag's legs (`--truth BAG --tracks T`); `bag` names it.
std::string legCoverageText(const eval::LegCoverage& c, const EvalSetup& s, const std::string& bag);
std::string legCoverageJson(const eval::LegCoverage& c, const EvalSetup& s);
std::string segmentationText(const eval::SegmentationReport& r, const eval::SegmentationOptions& o);
std::string segmentationJson(const eval::SegmentationReport& r, const eval::SegmentationOptions& o);

}  // namespace pedtrack::cli
