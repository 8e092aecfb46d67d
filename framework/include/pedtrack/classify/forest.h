#pragma once
// A random forest person classifier (ours, beside P2's k-NN and P4's SVM): OpenCV's
// cv::ml::RTrees on the raw cluster features (trees need no scaling), each class weighted by the
// inverse of its share, the score the share of trees voting "person". Trees split on whichever
// features separate the classes where they do, so a profile of many features (cluster_features.h)
// helps instead of drowning the few that matter, as it can for a distance-based k-NN.
#include <opencv2/ml.hpp>
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"

namespace pedtrack::classify {

struct ForestTraining {
  int trees = 100;         ///< forest size
  int max_depth = 10;      ///< deepest split
  int min_samples = 5;     ///< a node with fewer samples is a leaf
  unsigned long seed = 1;  ///< OpenCV's RNG (bootstrap samples, feature draws)
};

class ForestClassifier {
 public:
  /// Trains on `s`. Deterministic for options.seed.
  static ForestClassifier train(const SampleSet& s, const ForestTraining& options);
  ForestClassifier(cv::Ptr<cv::ml::RTrees> forest, std::vector<std::string> features);

  /// Share of trees voting "person" for n feature vectors (row-major, n × dims()).
  void probability(const double* x, std::size_t n, std::vector<double>& out) const;

  std::size_t dims() const { return features_.size(); }
  const std::vector<std::string>& features() const { return features_; }
  const cv::Ptr<cv::ml::RTrees>& forest() const { return forest_; }

 private:
  cv::Ptr<cv::ml::RTrees> forest_;
  std::vector<std::string> features_;
  mutable cv::Mat row_, votes_;
};

}  // namespace pedtrack::classify
