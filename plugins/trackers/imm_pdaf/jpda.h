#pragma once
// Association probabilities of several tracks at once. Each track t has, for each measurement i
// in its gate, the evidence e_ti = P_D p_ti / λ (likelihood against clutter) and a miss term
// b_t = 1 − P_D P_G. Independent PDA normalises every track on its own, so two tracks may both
// take one measurement; JPDA (Fortmann, Bar-Shalom & Scheffe 1983) weighs the joint events in
// which a measurement is at most one track's, enumerated over each cluster of tracks whose gates
// share measurements.
#include <Eigen/Core>
#include <cstddef>

namespace pedtrack::track {

struct AssociationProbabilities {
  Eigen::MatrixXd beta;   ///< tracks × measurements: P(measurement i is track t's)
  Eigen::VectorXd beta0;  ///< P(none of the measurements is track t's)
  /// The single-track evidence that reproduces beta under the PDA formula: e*_ti = β_ti / β_t0 ·
  /// b_t. IPDA's δ_t = P_D P_G − Σ_i e*_ti then holds for JPDA as for PDA (JIPDA's marginal).
  Eigen::MatrixXd effective_evidence;
  std::size_t clusters_enumerated = 0;    ///< JPDA clusters solved exactly
  std::size_t clusters_approximated = 0;  ///< too large: independent PDA used instead
};

/// Independent PDA per track.
AssociationProbabilities independentPda(const Eigen::MatrixXd& evidence,
                                        const Eigen::VectorXd& miss);

/// JPDA. A cluster whose joint events would exceed `max_events` falls back to independent PDA.
AssociationProbabilities jpda(const Eigen::MatrixXd& evidence, const Eigen::VectorXd& miss,
                              std::size_t max_events = 20000);

}  // namespace pedtrack::track
