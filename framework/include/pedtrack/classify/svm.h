#pragma once
// P4 §2.1's classifier: an RBF support vector machine (OpenCV's cv::ml::SVM) on standardised
// segment features, C and γ chosen by cross-validated grid search (SVM::trainAuto), and the
// decision value mapped to a probability by Platt's sigmoid fitted on held-out folds.
#include <Eigen/Core>
#include <opencv2/ml.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"

namespace pedtrack::classify {

/// P(person | f) = 1 / (1 + exp(a·f + b)) for decision value f (Platt 1999).
struct PlattSigmoid {
  double a = -1, b = 0;
  double operator()(double f) const;
  /// Lin, Lin & Weng's (2007) Newton fit with Platt's target smoothing.
  static PlattSigmoid fit(const std::vector<double>& f, const std::vector<Label>& y);
};

struct SvmTraining {
  int folds = 5;           ///< cross-validation folds for the grid search and calibration
  unsigned long seed = 1;  ///< fold assignment and OpenCV's RNG
  double c_min = 0.1, c_max = 1000, c_step = 3.1623;  ///< C grid (log steps)
  double gamma_min = 0.001, gamma_max = 10,
         gamma_step = 3.1623;  ///< γ grid on standardised features
  bool balanced = true;  ///< weight each class by the inverse of its share (many more non-persons)
};

class SvmClassifier {
 public:
  /// Trains on `s`, calibrates and returns the classifier. Deterministic for options.seed.
  static SvmClassifier train(const SampleSet& s, const SvmTraining& options);
  SvmClassifier(cv::Ptr<cv::ml::SVM> svm, Standardizer z, PlattSigmoid platt,
                std::vector<std::string> features);

  /// Raw decision values of n feature vectors (row-major, n × dims()).
  void decision(const double* x, std::size_t n, std::vector<double>& out) const;
  /// Calibrated person probabilities of n feature vectors.
  void probability(const double* x, std::size_t n, std::vector<double>& out) const;

  std::size_t dims() const { return features_.size(); }
  const std::vector<std::string>& features() const { return features_; }
  const cv::Ptr<cv::ml::SVM>& svm() const { return svm_; }
  const Standardizer& standardizer() const { return z_; }
  const PlattSigmoid& platt() const { return platt_; }

 private:
  // An RBF model's decision function, evaluated as one matrix product and Eigen's vectorised
  // exp over all support vectors at once: OpenCV's predict() evaluates the kernel one support
  // vector at a time (~20 ns each, 0.27 ms for 15 leg candidates against the shipped model's 909
  // vectors), which alone kept the leg pipeline under 2,000 scans/s on one core. Empty for other
  // kernels and SVM types (predict() is used).
  struct RbfDecision {
    Eigen::MatrixXf sv;        // m × d support vectors
    Eigen::VectorXf sv_norm2;  // |sv_k|²
    Eigen::VectorXf alpha;     // m weights
    float gamma = 0, rho = 0;
  };
  std::optional<RbfDecision> rbf_;
  cv::Ptr<cv::ml::SVM> svm_;
  Standardizer z_;
  PlattSigmoid platt_;
  std::vector<std::string> features_;
  mutable cv::Mat buf_, out_;
  mutable Eigen::MatrixXf kbuf_;
  mutable Eigen::VectorXf fbuf_;
};

}  // namespace pedtrack::classify
