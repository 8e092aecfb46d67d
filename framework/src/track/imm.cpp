#include "pedtrack/track/imm.h"

#include <cmath>
#include <stdexcept>

#include "pedtrack/track/kalman.h"

namespace pedtrack::track {

Imm::Imm(std::vector<std::shared_ptr<const MotionModel>> models, Eigen::MatrixXd transition)
    : models_(std::move(models)), pi_(std::move(transition)) {
  const auto n = Eigen::Index(models_.size());
  if (n == 0) throw std::invalid_argument("IMM: no models");
  if (pi_.rows() != n || pi_.cols() != n)
    throw std::invalid_argument("IMM: the transition matrix must be " + std::to_string(n) + " x " +
                                std::to_string(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    if (std::abs(pi_.row(i).sum() - 1) > 1e-6 || (pi_.row(i).array() < 0).any())
      throw std::invalid_argument("IMM: transition row " + std::to_string(i + 1) +
                                  " is not a probability distribution (sum 1, no negatives)");
    if (models_[i]->dim() != models_[0]->dim())
      throw std::invalid_argument("IMM: models " + models_[0]->name() + " and " +
                                  models_[i]->name() + " have different states");
  }
}

ImmState Imm::init(const Gaussian& g, Eigen::VectorXd mu) const {
  ImmState s;
  s.modes.assign(models_.size(), g);
  s.mu = mu.size() ? mu : Eigen::VectorXd::Constant(Eigen::Index(size()), 1.0 / double(size()));
  return s;
}

void Imm::predict(ImmState& s, double dt) const {
  const Eigen::Index n = Eigen::Index(size());
  const Eigen::VectorXd c = pi_.transpose() * s.mu;  // c_j = Σ_i Π_ij μ_i
  std::vector<Gaussian> mixed(size());
  for (Eigen::Index j = 0; j < n; ++j) {
    // μ_{i|j} = Π_ij μ_i / c_j; a model nobody can reach keeps its own estimate.
    Gaussian& m = mixed[j];
    if (c(j) <= 0) {
      m = s.modes[j];
      continue;
    }
    m.x = Eigen::VectorXd::Zero(s.modes[0].x.size());
    for (Eigen::Index i = 0; i < n; ++i) m.x += pi_(i, j) * s.mu(i) / c(j) * s.modes[i].x;
    m.P = Eigen::MatrixXd::Zero(m.x.size(), m.x.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::VectorXd d = s.modes[i].x - m.x;
      m.P += pi_(i, j) * s.mu(i) / c(j) * (s.modes[i].P + d * d.transpose());
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    kalmanPredict(mixed[j], *models_[j], dt);
    s.modes[j] = std::move(mixed[j]);
  }
  s.mu = c / c.sum();
}

void Imm::updateProbabilities(ImmState& s, const Eigen::VectorXd& log_likelihoods) {
  const double top = log_likelihoods.maxCoeff();
  if (!std::isfinite(top)) return;
  Eigen::VectorXd w = s.mu.array() * (log_likelihoods.array() - top).exp();
  const double sum = w.sum();
  if (sum > 0 && std::isfinite(sum)) s.mu = w / sum;
}

Gaussian Imm::combine(const ImmState& s) {
  Gaussian g;
  g.x = Eigen::VectorXd::Zero(s.modes[0].x.size());
  for (std::size_t j = 0; j < s.modes.size(); ++j) g.x += s.mu(Eigen::Index(j)) * s.modes[j].x;
  g.P = Eigen::MatrixXd::Zero(g.x.size(), g.x.size());
  for (std::size_t j = 0; j < s.modes.size(); ++j) {
    const Eigen::VectorXd d = s.modes[j].x - g.x;
    g.P += s.mu(Eigen::Index(j)) * (s.modes[j].P + d * d.transpose());
  }
  return g;
}

}  // namespace pedtrack::track
