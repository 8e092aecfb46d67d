#include "pedtrack/classify/forest.h"

#include <cmath>

#include "pedtrack/errors.h"

namespace pedtrack::classify {

ForestClassifier ForestClassifier::train(const SampleSet& s, const ForestTraining& o) {
  if (s.count(Label::Person) == 0 || s.count(Label::NonPerson) == 0)
    throw DataError("forest: training needs samples of both classes");
  cv::Mat x(int(s.size()), int(s.dims()), CV_32F), y(int(s.size()), 1, CV_32S);
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = 0; j < s.dims(); ++j) x.at<float>(int(i), int(j)) = float(s.row(i)[j]);
    y.at<int>(int(i)) = int(s.y[i]);
  }
  cv::theRNG().state = o.seed;
  auto f = cv::ml::RTrees::create();
  f->setMaxDepth(o.max_depth);
  f->setMinSampleCount(o.min_samples);
  f->setCalculateVarImportance(true);
  f->setActiveVarCount(0);  // sqrt(features) per split
  // Many more non-persons than persons: each class weighted by the inverse of its share.
  const double np = double(s.count(Label::Person)), nn = double(s.count(Label::NonPerson));
  cv::Mat priors =
      (cv::Mat_<float>(1, 2) << float(0.5 * (np + nn) / nn), float(0.5 * (np + nn) / np));
  f->setPriors(priors);
  f->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, o.trees, 0));
  f->train(cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, y));
  return ForestClassifier(f, s.features);
}

ForestClassifier::ForestClassifier(cv::Ptr<cv::ml::RTrees> forest,
                                   std::vector<std::string> features)
    : forest_(std::move(forest)), features_(std::move(features)) {
  if (!forest_ || !forest_->isTrained() || forest_->getVarCount() != int(features_.size()))
    throw DataError("forest: not trained on " + std::to_string(features_.size()) + " features");
}

void ForestClassifier::probability(const double* x, std::size_t n, std::vector<double>& out) const {
  out.assign(n, 0.0);
  if (n == 0) return;
  const int d = int(dims());
  row_.create(int(n), d, CV_32F);
  for (std::size_t i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) row_.at<float>(int(i), j) = float(x[i * d + j]);
  // One call for every row: a header row of the class labels, then per sample its votes.
  forest_->getVotes(row_, votes_, 0);
  for (std::size_t i = 0; i < n; ++i) {
    double person = 0, total = 0;
    for (int c = 0; c < votes_.cols; ++c) {
      const int v = votes_.at<int>(int(i) + 1, c);
      total += v;
      if (votes_.at<int>(0, c) == int(Label::Person)) person += v;
    }
    out[i] = total > 0 ? person / total : 0;
  }
}

}  // namespace pedtrack::classify
