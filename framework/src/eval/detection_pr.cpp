#include "pedtrack/eval/detection_pr.h"

#include <cmath>

#include "pedtrack/assignment.h"

namespace pedtrack::eval {

double DetectionCounts::precision() const {
  return tp + fp ? double(tp) / double(tp + fp) : std::nan("");
}
double DetectionCounts::recall() const {
  return tp + fn ? double(tp) / double(tp + fn) : std::nan("");
}
double DetectionCounts::f1() const {
  return tp + fp + fn ? 2.0 * double(tp) / double(2 * tp + fp + fn) : std::nan("");
}
double DetectionCounts::meanDistance() const {
  return tp ? distance_sum / double(tp) : std::nan("");
}

DetectionCounts& DetectionCounts::operator+=(const DetectionCounts& o) {
  frames += o.frames;
  truth_points += o.truth_points;
  detections += o.detections;
  tp += o.tp;
  fp += o.fp;
  fn += o.fn;
  unscored_matches += o.unscored_matches;
  distance_sum += o.distance_sum;
  for (const auto& [k, v] : o.by_range) {
    by_range[k].first += v.first;
    by_range[k].second += v.second;
  }
  return *this;
}

DetectionCounts detectionPR(const std::vector<EvalFrame>& frames, double threshold,
                            double range_bin) {
  DetectionCounts c;
  c.range_bin = range_bin;
  for (const EvalFrame& f : frames) {
    ++c.frames;
    c.detections += f.estimates.size();
    const std::size_t nt = f.truths.size(), nd = f.estimates.size();
    std::vector<double> cost(nt * nd);
    for (std::size_t i = 0; i < nt; ++i)
      for (std::size_t j = 0; j < nd; ++j) cost[i * nd + j] = distance(f.truths[i], f.estimates[j]);
    const Assignment as = solveAssignment(cost, int(nt), int(nd), threshold);
    for (std::size_t i = 0; i < nt; ++i) {
      const bool scored = f.truths[i].scored;
      c.truth_points += scored;
      const int j = as.row_to_col[i];
      const double range = f.truths[i].range;
      if (scored && std::isfinite(range) && range_bin > 0) {
        auto& bin = c.by_range[int(std::floor(range / range_bin))];
        (j < 0 ? bin.second : bin.first) += 1;
      }
      if (j < 0) {
        c.fn += scored;
      } else if (!scored) {
        ++c.unscored_matches;
      } else {
        ++c.tp;
        c.distance_sum += cost[i * nd + j];
      }
    }
    c.fp += nd - as.size();
  }
  return c;
}

}  // namespace pedtrack::eval
