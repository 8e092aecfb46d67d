#include "imm_pdaf/pda.h"

#include <algorithm>

#include "pedtrack/track/kalman.h"

namespace pedtrack::track {

double clutterDensity(const PdaParams& p, std::size_t m, double gate_volume, double existence) {
  if (p.clutter_density > 0) return p.clutter_density;
  if (!(gate_volume > 0) || m == 0) return 1;
  // m̂ = m − P_D P_G P_T measurements expected to be false (P4 §2.3's V = V_G / m̂); positive
  // for m ≥ 1 since P_D P_G P_T < 1.
  const double expected = std::max(double(m) - p.p_detect * p.p_gate * existence, 1e-6);
  return expected / gate_volume;
}

PdaWeights pdaWeights(const PdaParams& p, const std::vector<double>& likelihoods,
                      double clutter_density) {
  PdaWeights w;
  double sum = 0;
  w.beta.resize(likelihoods.size());
  for (std::size_t i = 0; i < likelihoods.size(); ++i) {
    w.beta[i] = p.p_detect * likelihoods[i] / clutter_density;
    sum += w.beta[i];
  }
  const double miss = 1 - p.p_detect * p.p_gate;
  w.delta = p.p_detect * p.p_gate - sum;
  w.likelihood_ratio = miss + sum;  // = 1 − δ
  const double total = miss + sum;
  w.beta0 = miss / total;
  for (double& b : w.beta) b /= total;
  return w;
}

void pdaUpdate(Gaussian& g, const LinearMeasurement& m, const std::vector<Eigen::VectorXd>& z,
               const PdaWeights& w) {
  if (z.empty()) return;
  const Eigen::MatrixXd S = innovationCovariance(g, m);
  const Eigen::MatrixXd K = kalmanGain(g, m, S);
  Eigen::VectorXd nu = Eigen::VectorXd::Zero(m.dim());
  Eigen::MatrixXd spread = Eigen::MatrixXd::Zero(m.dim(), m.dim());
  for (std::size_t i = 0; i < z.size(); ++i) {
    const Eigen::VectorXd nui = m.residual(z[i], g.x);
    nu += w.beta[i] * nui;
    spread += w.beta[i] * nui * nui.transpose();
  }
  spread -= nu * nu.transpose();
  const Eigen::MatrixXd Pc = g.P - K * S * K.transpose();
  g.x += K * nu;
  g.P = w.beta0 * g.P + (1 - w.beta0) * Pc + K * spread * K.transpose();
  g.P = 0.5 * (g.P + g.P.transpose());
}

double existencePredict(double p_exist, double p_survive, double p_birth) {
  return p_survive * p_exist + p_birth * (1 - p_exist);
}

double existenceUpdate(double p_exist_predicted, double delta) {
  const double den = 1 - delta * p_exist_predicted;
  if (!(den > 0)) return p_exist_predicted;
  return std::clamp((1 - delta) * p_exist_predicted / den, 0.0, 1.0);
}

}  // namespace pedtrack::track
