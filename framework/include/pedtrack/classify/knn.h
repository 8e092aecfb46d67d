#pragma once
// P2's appearance classifier (§3.3, §5.2): k nearest prototypes under a Mahalanobis metric with
// Σ = (Σ_P + Σ_P̄)/2 (eq. 5) or a per-feature scaled Minkowski metric (eq. 22), weighted votes
// (eq. 6) and the quality Q = W_P / (W_P + W_P̄).
//
// Both metrics are a fixed linear map T followed by an L2 (or L1) norm: Mahalanobis
// d² = (x−x')ᵀΣ⁻¹(x−x') = |T(x−x')|² with T = Λ^{-1/2}Vᵀ from Σ = VΛVᵀ; Minkowski scales each
// feature by 1/σ. Prototypes are mapped once, so a query costs one map and a KD-tree search
// (nanoflann) in the mapped space.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/classify/samples.h"

namespace pedtrack::classify {

enum class KnnMetric { Mahalanobis, Minkowski };
/// How each of the k neighbours votes. P2 eq. 6 as printed gives each one votes equal to its
/// squared distance (SquaredDistance), which favours the farther neighbours; InverseDistance
/// gives 1/d; Unit is the traditional one vote each.
enum class KnnWeighting { SquaredDistance, InverseDistance, Unit };

KnnMetric parseKnnMetric(const std::string& s);  ///< "mahalanobis" | "minkowski"
KnnWeighting parseKnnWeighting(
    const std::string& s);  ///< "squared_distance" | "inverse_distance" | "unit"
const char* toString(KnnMetric m);
const char* toString(KnnWeighting w);

struct KnnOptions {
  int k = 5;  ///< P2: 5
  KnnMetric metric = KnnMetric::Mahalanobis;
  int minkowski_p = 2;  ///< 1 (Manhattan) or 2 (Euclidean)
  KnnWeighting weighting = KnnWeighting::InverseDistance;
  /// Databases smaller than this are scanned linearly (a tree does not pay below it).
  std::size_t linear_below = 64;
};

/// The metric's statistics, computed from the prototypes at training and stored in the model.
struct KnnMetricStats {
  Eigen::MatrixXd sigma;   ///< (Σ_P + Σ_P̄)/2
  Eigen::VectorXd stddev;  ///< per-feature σ over all prototypes (Minkowski scaling α = 1/σ)
  static KnnMetricStats fit(const SampleSet& prototypes);
};

class KnnClassifier {
 public:
  KnnClassifier(SampleSet prototypes, KnnMetricStats stats, KnnOptions options);
  ~KnnClassifier();
  KnnClassifier(KnnClassifier&&) noexcept;
  KnnClassifier& operator=(KnnClassifier&&) noexcept;

  /// Q ∈ [0, 1] of feature vector x (dims() values).
  double quality(const double* x) const;
  /// The squared metric distance between two feature vectors (eq. 5 or eq. 22 squared).
  double distanceSquared(const double* a, const double* b) const;

  std::size_t dims() const { return prototypes_.dims(); }
  const SampleSet& prototypes() const { return prototypes_; }
  const KnnMetricStats& stats() const { return stats_; }
  const KnnOptions& options() const { return opt_; }

 private:
  struct Index;
  SampleSet prototypes_;
  KnnMetricStats stats_;
  KnnOptions opt_;
  Eigen::MatrixXd T_;  ///< the metric's linear map
  std::unique_ptr<Index> index_;
};

}  // namespace pedtrack::classify
