#pragma once
// Scores of labelled samples summarised: the confusion matrix at a threshold (P2 Table 1), the
// ROC curve and its area.
#include <cstddef>
#include <vector>

#include "pedtrack/classify/samples.h"

namespace pedtrack::classify {

struct Confusion {
  std::size_t tp = 0, fn = 0;  ///< persons decided person / non-person
  std::size_t fp = 0, tn = 0;  ///< non-persons decided person / non-person
  double detectionRate() const { return tp + fn ? double(tp) / double(tp + fn) : 0; }
  double falsePositiveRate() const { return fp + tn ? double(fp) / double(fp + tn) : 0; }
};

/// A sample is decided a person when its score ≥ threshold.
Confusion confusionAt(const std::vector<double>& scores, const std::vector<Label>& y,
                      double threshold);

struct RocPoint {
  double fpr = 0, tpr = 0;
  double threshold = 0;  ///< persons are score ≥ threshold at this point
};

/// The ROC curve from (0, 0) to (1, 1), one point per distinct score.
std::vector<RocPoint> rocCurve(const std::vector<double>& scores, const std::vector<Label>& y);

/// The best detection rate at a false-positive rate ≤ max_fpr (with its threshold), and the lowest
/// false-positive rate at a detection rate ≥ min_tpr: operating points read off the curve.
RocPoint bestAtFpr(const std::vector<RocPoint>& roc, double max_fpr);
RocPoint bestAtTpr(const std::vector<RocPoint>& roc, double min_tpr);

/// Area under the ROC curve: the probability that a random person scores above a random
/// non-person, ties counting one half (Mann–Whitney U / (n₊ n₋)).
double rocAuc(const std::vector<double>& scores, const std::vector<Label>& y);

}  // namespace pedtrack::classify
