#pragma once
// Probabilistic data association (Bar-Shalom & Tse 1975; Bar-Shalom et al. 2009, "The PDAF")
// and its integrated form with target existence (IPDA, Mušicki, Evans & Stanković 1994; P4
// eq. 1–2). Inputs are the validated measurements' likelihoods p_i = N(ν_i; 0, S); the clutter
// density λ is given (parametric) or estimated from the gate as m̂ / V (non-parametric, P4).
#include <Eigen/Core>
#include <vector>

#include "pedtrack/track/gaussian.h"

namespace pedtrack::track {

struct PdaParams {
  double p_detect = 0.9;       ///< P_D
  double p_gate = 0.99;        ///< P_G
  double clutter_density = 0;  ///< λ per unit gate volume; 0 = non-parametric (m̂ / V)
};

struct PdaWeights {
  double beta0 = 1;             ///< no measurement is the target's
  std::vector<double> beta;     ///< per validated measurement
  double delta = 0;             ///< IPDA's δ (eq. 2): 1 − likelihood ratio of the scan
  double likelihood_ratio = 1;  ///< 1 − δ = Λ / (clutter-only likelihood)
};

/// The clutter density to use: `p.clutter_density`, or (m − P_D P_G P_T) / V for m ≥ 1
/// validated measurements in a gate of volume V (P4 §2.3's V).
double clutterDensity(const PdaParams& p, std::size_t m, double gate_volume, double existence = 1);

/// β_i ∝ P_D p_i / λ, β_0 ∝ 1 − P_D P_G (normalised), and δ = P_D P_G − P_D Σ p_i / λ.
PdaWeights pdaWeights(const PdaParams& p, const std::vector<double>& likelihoods,
                      double clutter_density);

/// The PDA update of `g` with the validated measurements `z` and their weights: the combined
/// innovation ν = Σ β_i ν_i, x ← x + K ν, and P ← β_0 P⁻ + (1 − β_0) P^c + K (Σ β_i ν_i ν_iᵀ − ν
/// νᵀ) Kᵀ (the spread of the innovations).
void pdaUpdate(Gaussian& g, const LinearMeasurement& m, const std::vector<Eigen::VectorXd>& z,
               const PdaWeights& w);

/// IPDA's existence step. Prediction (eq. 1): P_T ← p_survive P_T + p_birth (1 − P_T).
double existencePredict(double p_exist, double p_survive, double p_birth);
/// Update (eq. 2): P_T ← (1 − δ) P_T / (1 − δ P_T).
double existenceUpdate(double p_exist_predicted, double delta);

}  // namespace pedtrack::track
