#pragma once
// A fast approximate minimiser of one MHE-Ellipse problem, used to rank MLESAC's candidates
// before Ipopt solves the ones that can win (mhe_mlesac.h). Ipopt spends ~0.7 ms per iteration
// on this problem size (MUMPS's set-up per factorisation dominates), so solving all j_max = 100
// candidates exactly costs about a second per person and frame; the ranking does not need the
// exact constrained optimum, only its cost to a fraction of the spread between candidates.
//
// The window's states are linear in z = [x_{T−H+1}, n_{T−H+2}, …, n_T] (eq. 2 exactly, so the
// kinematic equality constraints hold by construction); Levenberg–Marquardt on the residuals of
// eq. 5 in z, with the bounds (7)–(9) as stiff penalties. Eq. 6 follows from (7)–(8) with P0's
// bounds (α ≥ α_min ≥ β_max ≥ β) and eq. 10 is left to Ipopt.
#include <Eigen/Core>
#include <vector>

#include "mhe_mlesac/mhe_ellipse.h"

namespace pedtrack::track::mhe {

class MheScreen {
 public:
  /// The parts every candidate of one window shares: the linear map z → states, the motion and
  /// arrival terms (`pb` gives frames, prior and arrival; its sample is not used).
  MheScreen(const MheProblem& pb, const MheParams& params);
  /// `iterations` LM steps on the candidate problem `pb` from `start` (the a priori window when
  /// null).
  std::vector<State> minimise(const MheProblem& pb, int iterations,
                              const std::vector<State>* start = nullptr) const;
  /// The states of z and z of a window (the noises G†(x_k − A x_{k−1}); the kinematic rows of
  /// the window are dropped).
  std::vector<State> states(const Eigen::VectorXd& z) const;
  Eigen::VectorXd reduce(const std::vector<State>& xs) const;

 private:
  double cost(const MheProblem& pb, const Eigen::VectorXd& z) const;
  const MheParams& p_;
  int h_, n_;
  std::vector<Eigen::MatrixXd> map_;  ///< per frame, the 8 × n map z → x_k
  std::vector<Eigen::Matrix<double, 5, Eigen::Dynamic>> shape_map_;  ///< its (x, y, θ, α, β) rows
  Eigen::MatrixXd base_hessian_;  ///< the motion and arrival terms' JᵀJ (constant)
  Eigen::VectorXd z0_;            ///< the a priori window in z
  std::vector<double> theta_lo_, theta_hi_;
};

}  // namespace pedtrack::track::mhe
