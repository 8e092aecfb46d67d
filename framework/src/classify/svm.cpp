#include "pedtrack/classify/svm.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pedtrack/errors.h"

namespace pedtrack::classify {

double PlattSigmoid::operator()(double f) const {
  const double e = a * f + b;
  // The two algebraically equal forms, each where it cannot overflow.
  return e >= 0 ? std::exp(-e) / (1 + std::exp(-e)) : 1 / (1 + std::exp(e));
}

PlattSigmoid PlattSigmoid::fit(const std::vector<double>& f, const std::vector<Label>& y) {
  // Lin, Lin & Weng (2007), Algorithm 1: Newton's method with backtracking on the regularised
  // targets t₊ = (N₊+1)/(N₊+2), t₋ = 1/(N₋+2).
  const std::size_t n = f.size();
  double prior1 = 0, prior0 = 0;
  for (Label l : y) (l == Label::Person ? prior1 : prior0) += 1;
  const double hi = (prior1 + 1) / (prior1 + 2), lo = 1 / (prior0 + 2);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = y[i] == Label::Person ? hi : lo;
  double A = 0, B = std::log((prior0 + 1) / (prior1 + 1));
  auto objective = [&](double a, double b) {
    double fval = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = f[i] * a + b;
      fval +=
          e >= 0 ? t[i] * e + std::log1p(std::exp(-e)) : (t[i] - 1) * e + std::log1p(std::exp(e));
    }
    return fval;
  };
  double fval = objective(A, B);
  const double sigma = 1e-12, eps = 1e-5;
  for (int it = 0; it < 100; ++it) {
    double h11 = sigma, h22 = sigma, h21 = 0, g1 = 0, g2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = f[i] * A + B;
      double p, q;
      if (e >= 0) {
        p = std::exp(-e) / (1 + std::exp(-e));
        q = 1 / (1 + std::exp(-e));
      } else {
        p = 1 / (1 + std::exp(e));
        q = std::exp(e) / (1 + std::exp(e));
      }
      const double d2 = p * q;
      h11 += f[i] * f[i] * d2;
      h22 += d2;
      h21 += f[i] * d2;
      const double d1 = t[i] - p;
      g1 += f[i] * d1;
      g2 += d1;
    }
    if (std::abs(g1) < eps && std::abs(g2) < eps) break;
    const double det = h11 * h22 - h21 * h21;
    const double dA = -(h22 * g1 - h21 * g2) / det, dB = -(-h21 * g1 + h11 * g2) / det;
    const double gd = g1 * dA + g2 * dB;
    double step = 1;
    bool moved = false;
    while (step >= 1e-10) {
      const double nf = objective(A + step * dA, B + step * dB);
      if (nf < fval + 1e-4 * step * gd) {
        A += step * dA, B += step * dB, fval = nf, moved = true;
        break;
      }
      step /= 2;
    }
    if (!moved) break;
  }
  return {A, B};
}

namespace {

cv::Mat standardised(const SampleSet& s, const Standardizer& z) {
  cv::Mat m(int(s.size()), int(s.dims()), CV_32F);
  std::vector<double> row(s.dims());
  for (std::size_t i = 0; i < s.size(); ++i) {
    z.apply(s.row(i), row.data());
    for (std::size_t j = 0; j < s.dims(); ++j) m.at<float>(int(i), int(j)) = float(row[j]);
  }
  return m;
}

cv::Mat labels(const SampleSet& s, const std::vector<std::size_t>& idx) {
  cv::Mat l(int(idx.size()), 1, CV_32S);
  for (std::size_t i = 0; i < idx.size(); ++i) l.at<int>(int(i)) = int(s.y[idx[i]]);
  return l;
}

cv::Ptr<cv::ml::SVM> makeSvm(double c, double gamma, const cv::Mat& weights) {
  auto svm = cv::ml::SVM::create();
  svm->setType(cv::ml::SVM::C_SVC);
  svm->setKernel(cv::ml::SVM::RBF);
  svm->setC(c);
  svm->setGamma(gamma);
  if (!weights.empty()) svm->setClassWeights(weights);
  svm->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, 100000, 1e-4));
  return svm;
}

}  // namespace

SvmClassifier SvmClassifier::train(const SampleSet& s, const SvmTraining& o) {
  const std::size_t np = s.count(Label::Person), nn = s.count(Label::NonPerson);
  if (np < 2 || nn < 2)
    throw ConfigError("svm: training needs at least 2 samples of each class (have " +
                      std::to_string(np) + " persons, " + std::to_string(nn) + " non-persons)");
  const Standardizer z = Standardizer::fit(s);
  const cv::Mat X = standardised(s, z);
  std::vector<std::size_t> all(s.size());
  std::iota(all.begin(), all.end(), 0);
  const cv::Mat Y = labels(s, all);
  cv::Mat weights;
  if (o.balanced) {
    // Class 0 = non-person, 1 = person: each class carries half of the total weight.
    weights =
        (cv::Mat_<double>(2, 1) << double(s.size()) / (2.0 * nn), double(s.size()) / (2.0 * np));
  }
  // Grid search: OpenCV's own k-fold trainAuto over (C, γ), seeded.
  cv::theRNG().state = o.seed * 2654435761ULL + 1;
  auto svm = makeSvm(1, 1, weights);
  auto data = cv::ml::TrainData::create(X, cv::ml::ROW_SAMPLE, Y);
  const cv::ml::ParamGrid cgrid(o.c_min, o.c_max, o.c_step);
  const cv::ml::ParamGrid ggrid(o.gamma_min, o.gamma_max, o.gamma_step);
  const cv::ml::ParamGrid off(0, 0, 0);
  svm->trainAuto(data, o.folds, cgrid, ggrid, off, off, off, off, true);
  const double C = svm->getC(), gamma = svm->getGamma();

  // Calibration: decision values of each sample from a model that did not see it. The folds are
  // contiguous blocks, not a shuffle: samples come in input and time order, and a frame's
  // neighbours are nearly the same samples, so shuffled folds would calibrate on data the fold's
  // model has in effect seen, and make the sigmoid overconfident.
  std::vector<double> held(s.size());
  for (int k = 0; k < o.folds; ++k) {
    std::vector<std::size_t> train_idx, test_idx;
    const std::size_t lo = s.size() * std::size_t(k) / std::size_t(o.folds),
                      hi = s.size() * std::size_t(k + 1) / std::size_t(o.folds);
    for (std::size_t i = 0; i < s.size(); ++i)
      (i >= lo && i < hi ? test_idx : train_idx).push_back(i);
    cv::Mat Xt(int(train_idx.size()), X.cols, CV_32F), Xv(int(test_idx.size()), X.cols, CV_32F);
    for (std::size_t i = 0; i < train_idx.size(); ++i)
      X.row(int(train_idx[i])).copyTo(Xt.row(int(i)));
    for (std::size_t i = 0; i < test_idx.size(); ++i)
      X.row(int(test_idx[i])).copyTo(Xv.row(int(i)));
    const cv::Mat Yt = labels(s, train_idx);
    if (cv::countNonZero(Yt) == 0 || cv::countNonZero(Yt) == Yt.rows) continue;
    auto fold = makeSvm(C, gamma, weights);
    fold->train(Xt, cv::ml::ROW_SAMPLE, Yt);
    cv::Mat out;
    fold->predict(Xv, out, cv::ml::StatModel::RAW_OUTPUT);
    for (std::size_t i = 0; i < test_idx.size(); ++i) held[test_idx[i]] = out.at<float>(int(i));
  }
  const PlattSigmoid platt = PlattSigmoid::fit(held, s.y);
  return SvmClassifier(svm, z, platt, s.features);
}

SvmClassifier::SvmClassifier(cv::Ptr<cv::ml::SVM> svm, Standardizer z, PlattSigmoid platt,
                             std::vector<std::string> features)
    : svm_(std::move(svm)), z_(std::move(z)), platt_(platt), features_(std::move(features)) {
  // A model file is input: its parts must agree before anything indexes one by another
  // (fuzz_model found a file whose support-vector indices ran past the vectors).
  if (z_.mean.size() != dims() || z_.scale.size() != dims())
    throw DataError("SVM model: the standardisation has " + std::to_string(z_.mean.size()) +
                    " means and " + std::to_string(z_.scale.size()) + " scales for " +
                    std::to_string(dims()) + " features");
  if (svm_.empty() || !svm_->isTrained() || svm_->getKernelType() != cv::ml::SVM::RBF ||
      svm_->getType() != cv::ml::SVM::C_SVC)
    return;
  const cv::Mat sv = svm_->getSupportVectors();
  cv::Mat alpha, index;
  const double rho = svm_->getDecisionFunction(0, alpha, index);
  if (sv.type() != CV_32F || sv.cols != int(dims()) || alpha.total() != index.total()) return;
  if (index.type() != CV_32S) throw DataError("SVM model: support vector indices are not integers");
  for (int k = 0; k < int(index.total()); ++k)
    if (index.at<int>(k) < 0 || index.at<int>(k) >= sv.rows)
      throw DataError("SVM model: support vector index " + std::to_string(index.at<int>(k)) +
                      " of " + std::to_string(sv.rows) + " vectors");
  RbfDecision r;
  const int m = int(alpha.total());
  r.sv.resize(m, sv.cols);
  r.alpha.resize(m);
  alpha.convertTo(alpha, CV_64F);
  for (int k = 0; k < m; ++k) {
    const float* row = sv.ptr<float>(index.at<int>(k));
    for (int j = 0; j < sv.cols; ++j) r.sv(k, j) = row[j];
    r.alpha(k) = float(alpha.at<double>(k));
  }
  r.sv_norm2 = r.sv.rowwise().squaredNorm();
  r.gamma = float(svm_->getGamma());
  r.rho = float(rho);
  rbf_ = std::move(r);
}

void SvmClassifier::decision(const double* x, std::size_t n, std::vector<double>& out) const {
  out.resize(n);
  if (n == 0) return;
  const std::size_t d = dims();
  buf_.create(int(n), int(d), CV_32F);
  for (std::size_t i = 0; i < n; ++i) {
    float* r = buf_.ptr<float>(int(i));
    for (std::size_t j = 0; j < d; ++j) r[j] = float((x[i * d + j] - z_.mean[j]) / z_.scale[j]);
  }
  if (!rbf_) {
    svm_->predict(buf_, out_, cv::ml::StatModel::RAW_OUTPUT);
    for (std::size_t i = 0; i < n; ++i) out[i] = out_.at<float>(int(i));
    return;
  }
  // Σ_k α_k exp(−γ |x − sv_k|²) − ρ (OpenCV's sign: tests/test_classify.cpp compares it with
  // predict()), all pairs at once: |x − sv|² = |x|² + |sv|² − 2 x·sv as one matrix product. In
  // float, as OpenCV's own kernel values: the two differ by a few 1e-3 at most.
  const RbfDecision& r = *rbf_;
  const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> xs(
      buf_.ptr<float>(), Eigen::Index(n), Eigen::Index(d));
  kbuf_.noalias() = xs * r.sv.transpose();
  kbuf_ *= -2.0f;
  kbuf_.colwise() += xs.rowwise().squaredNorm();
  kbuf_.rowwise() += r.sv_norm2.transpose();
  kbuf_ = (kbuf_.array() * -r.gamma).exp().matrix();
  fbuf_.noalias() = kbuf_ * r.alpha;
  for (std::size_t i = 0; i < n; ++i) out[i] = double(fbuf_(Eigen::Index(i)) - r.rho);
}

void SvmClassifier::probability(const double* x, std::size_t n, std::vector<double>& out) const {
  decision(x, n, out);
  for (double& v : out) v = platt_(v);
}

}  // namespace pedtrack::classify
