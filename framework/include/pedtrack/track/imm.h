#pragma once
// The interacting multiple model cycle (Blom & Bar-Shalom 1988; Bar-Shalom et al. 2001, §11.6):
// mixing by the Markov transition matrix Π, one filter per model, model probabilities updated by
// each model's measurement likelihood, and the moment-matched combination for output. All the
// models share one state layout (P4's CV and CT models do).
#include <memory>
#include <vector>

#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {

struct ImmState {
  std::vector<Gaussian> modes;  ///< one per model, the model-conditioned estimates
  Eigen::VectorXd mu;           ///< model probabilities, sum 1
};

class Imm {
 public:
  /// `transition(i, j)` = P(model j at k+1 | model i at k); rows must sum to 1 and every model
  /// must have the same state dimension (std::invalid_argument otherwise).
  Imm(std::vector<std::shared_ptr<const MotionModel>> models, Eigen::MatrixXd transition);

  std::size_t size() const { return models_.size(); }
  const MotionModel& model(std::size_t i) const { return *models_[i]; }
  const Eigen::MatrixXd& transition() const { return pi_; }

  /// Every mode starts from `g`, with probabilities `mu` (uniform when empty).
  ImmState init(const Gaussian& g, Eigen::VectorXd mu = {}) const;
  /// Mixing (interaction) then each model's prediction over dt; mu becomes the predicted
  /// probabilities c_j = Σ_i Π_ij μ_i.
  void predict(ImmState& s, double dt) const;
  /// μ_j ← c_j Λ_j / Σ c Λ for the models' measurement likelihoods Λ_j, given as logarithms
  /// (they may be far below the double range). Leaves μ unchanged when every Λ_j is 0.
  static void updateProbabilities(ImmState& s, const Eigen::VectorXd& log_likelihoods);
  /// The moment-matched single Gaussian of the mixture (mean and covariance with the spread of
  /// the means).
  static Gaussian combine(const ImmState& s);

 private:
  std::vector<std::shared_ptr<const MotionModel>> models_;
  Eigen::MatrixXd pi_;
};

}  // namespace pedtrack::track
