#include "pedtrack/classify/knn.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <nanoflann.hpp>

#include "pedtrack/errors.h"

namespace pedtrack::classify {

KnnMetric parseKnnMetric(const std::string& s) {
  if (s == "mahalanobis") return KnnMetric::Mahalanobis;
  if (s == "minkowski") return KnnMetric::Minkowski;
  throw ConfigError("unknown k-NN metric '" + s + "' (mahalanobis, minkowski)");
}
KnnWeighting parseKnnWeighting(const std::string& s) {
  if (s == "squared_distance") return KnnWeighting::SquaredDistance;
  if (s == "inverse_distance") return KnnWeighting::InverseDistance;
  if (s == "unit") return KnnWeighting::Unit;
  throw ConfigError("unknown k-NN weighting '" + s +
                    "' (squared_distance, inverse_distance, unit)");
}
const char* toString(KnnMetric m) {
  return m == KnnMetric::Mahalanobis ? "mahalanobis" : "minkowski";
}
const char* toString(KnnWeighting w) {
  return w == KnnWeighting::SquaredDistance   ? "squared_distance"
         : w == KnnWeighting::InverseDistance ? "inverse_distance"
                                              : "unit";
}

namespace {

Eigen::MatrixXd classCovariance(const SampleSet& s, Label l) {
  const auto d = static_cast<Eigen::Index>(s.dims());
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.y[i] == l) mean += Eigen::Map<const Eigen::VectorXd>(s.row(i), d), ++n;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(d, d);
  if (n < 2) return c;
  mean /= double(n);
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.y[i] == l) {
      const Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(s.row(i), d) - mean;
      c.noalias() += e * e.transpose();
    }
  return c / double(n - 1);
}

}  // namespace

KnnMetricStats KnnMetricStats::fit(const SampleSet& p) {
  KnnMetricStats st;
  st.sigma = 0.5 * (classCovariance(p, Label::Person) + classCovariance(p, Label::NonPerson));
  const Standardizer z = Standardizer::fit(p);
  st.stddev = Eigen::Map<const Eigen::VectorXd>(z.scale.data(), Eigen::Index(z.scale.size()));
  return st;
}

// The mapped prototypes as nanoflann sees them.
struct KnnClassifier::Index {
  std::vector<double> pts;  // n × d, mapped
  std::size_t n = 0, d = 0;
  std::size_t kdtree_get_point_count() const { return n; }
  double kdtree_get_pt(std::size_t i, std::size_t j) const { return pts[i * d + j]; }
  template <class B>
  bool kdtree_get_bbox(B&) const {
    return false;
  }
  using L2Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Index>,
                                                     Index, -1, std::size_t>;
  using L1Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L1_Adaptor<double, Index>, Index,
                                                     -1, std::size_t>;
  std::unique_ptr<L2Tree> l2;
  std::unique_ptr<L1Tree> l1;
};

KnnClassifier::KnnClassifier(SampleSet prototypes, KnnMetricStats stats, KnnOptions options)
    : prototypes_(std::move(prototypes)), stats_(std::move(stats)), opt_(options) {
  const auto d = static_cast<Eigen::Index>(dims());
  if (prototypes_.size() == 0) throw ConfigError("k-NN: no prototypes");
  if (opt_.k < 1) throw ConfigError("k-NN: k must be at least 1");
  if (opt_.minkowski_p != 1 && opt_.minkowski_p != 2)
    throw ConfigError("k-NN: minkowski_p must be 1 or 2");
  if (stats_.sigma.rows() != d || stats_.sigma.cols() != d || stats_.stddev.size() != d)
    throw ConfigError("k-NN: metric statistics do not match the " + std::to_string(d) +
                      " features");
  if (opt_.metric == KnnMetric::Mahalanobis) {
    // Σ = VΛVᵀ, T = Λ^{-1/2}Vᵀ. Eigenvalues are floored relative to the largest so that a
    // feature that never varies (or two that always vary together) cannot make Σ singular.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(stats_.sigma);
    Eigen::VectorXd lambda = es.eigenvalues();
    const double floor = std::max(1e-12, 1e-9 * lambda.maxCoeff());
    for (Eigen::Index j = 0; j < d; ++j) lambda[j] = 1.0 / std::sqrt(std::max(lambda[j], floor));
    T_ = lambda.asDiagonal() * es.eigenvectors().transpose();
  } else {
    T_ = stats_.stddev.cwiseMax(1e-12).cwiseInverse().asDiagonal();
  }
  index_ = std::make_unique<Index>();
  index_->n = prototypes_.size();
  index_->d = dims();
  index_->pts.resize(index_->n * index_->d);
  for (std::size_t i = 0; i < index_->n; ++i) {
    Eigen::Map<Eigen::VectorXd>(&index_->pts[i * index_->d], d) =
        T_ * Eigen::Map<const Eigen::VectorXd>(prototypes_.row(i), d);
  }
  if (index_->n >= opt_.linear_below) {
    // Leaf size 24: measured fastest of 8/24/64 on 2,000 prototypes (6 and 15 features).
    const nanoflann::KDTreeSingleIndexAdaptorParams params(24);
    if (opt_.metric == KnnMetric::Minkowski && opt_.minkowski_p == 1) {
      index_->l1 = std::make_unique<Index::L1Tree>(index_->d, *index_, params);
      index_->l1->buildIndex();
    } else {
      index_->l2 = std::make_unique<Index::L2Tree>(index_->d, *index_, params);
      index_->l2->buildIndex();
    }
  }
}

KnnClassifier::~KnnClassifier() = default;
KnnClassifier::KnnClassifier(KnnClassifier&&) noexcept = default;
KnnClassifier& KnnClassifier::operator=(KnnClassifier&&) noexcept = default;

double KnnClassifier::distanceSquared(const double* a, const double* b) const {
  const auto d = static_cast<Eigen::Index>(dims());
  const Eigen::VectorXd e =
      T_ * (Eigen::Map<const Eigen::VectorXd>(a, d) - Eigen::Map<const Eigen::VectorXd>(b, d));
  if (opt_.metric == KnnMetric::Minkowski && opt_.minkowski_p == 1) {
    const double l1 = e.cwiseAbs().sum();
    return l1 * l1;
  }
  return e.squaredNorm();
}

double KnnClassifier::quality(const double* x) const {
  const std::size_t d = dims();
  const auto k = std::min<std::size_t>(std::size_t(opt_.k), prototypes_.size());
  // The query, mapped. A fixed buffer: feature vectors are short (P2: 6, scan segments: 17).
  double q[64];
  Eigen::VectorXd qv;
  double* qp = q;
  if (d <= 64) {
    Eigen::Map<Eigen::VectorXd>(q, Eigen::Index(d)) =
        T_ * Eigen::Map<const Eigen::VectorXd>(x, Eigen::Index(d));
  } else {
    qv = T_ * Eigen::Map<const Eigen::VectorXd>(x, Eigen::Index(d));
    qp = qv.data();
  }
  std::size_t idx[64];
  double dist[64];  // L2: squared distance; L1: distance
  std::vector<std::size_t> idx_big;
  std::vector<double> dist_big;
  std::size_t* ip = idx;
  double* dp = dist;
  if (k > 64) {
    idx_big.resize(k), dist_big.resize(k);
    ip = idx_big.data(), dp = dist_big.data();
  }
  const bool l1 = opt_.metric == KnnMetric::Minkowski && opt_.minkowski_p == 1;
  std::size_t found = 0;
  if (index_->l2) {
    found = index_->l2->knnSearch(qp, k, ip, dp);
  } else if (index_->l1) {
    found = index_->l1->knnSearch(qp, k, ip, dp);
  } else {
    // Linear scan with a sorted insertion list of the k best.
    for (std::size_t i = 0; i < index_->n; ++i) {
      const double* p = &index_->pts[i * d];
      double s = 0;
      for (std::size_t j = 0; j < d; ++j)
        s += l1 ? std::abs(p[j] - qp[j]) : (p[j] - qp[j]) * (p[j] - qp[j]);
      if (found == k && s >= dp[k - 1]) continue;
      std::size_t pos = found < k ? found++ : k - 1;
      while (pos > 0 && dp[pos - 1] > s) dp[pos] = dp[pos - 1], ip[pos] = ip[pos - 1], --pos;
      dp[pos] = s, ip[pos] = i;
    }
  }
  double w_person = 0, w_other = 0;
  for (std::size_t n = 0; n < found; ++n) {
    const double d2 = l1 ? dp[n] * dp[n] : dp[n];
    double w = 1;
    if (opt_.weighting == KnnWeighting::SquaredDistance) w = d2;
    if (opt_.weighting == KnnWeighting::InverseDistance) w = 1.0 / (std::sqrt(d2) + 1e-9);
    (prototypes_.y[ip[n]] == Label::Person ? w_person : w_other) += w;
  }
  if (w_person + w_other <= 0) {
    // Every neighbour at distance 0 under the literal rule: fall back to one vote each.
    for (std::size_t n = 0; n < found; ++n)
      (prototypes_.y[ip[n]] == Label::Person ? w_person : w_other) += 1;
  }
  return w_person / (w_person + w_other);
}

}  // namespace pedtrack::classify
