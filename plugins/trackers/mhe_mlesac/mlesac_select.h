#pragma once
// P0 §IV–V, Algorithm 1: MHE-MLESAC. Each of j_max candidates samples |Ψ| points from the whole
// horizon, is fitted by MHE-Ellipse (eq. 5 subject to (6)–(10)) from the a priori window, and is
// scored by the negative log-likelihood of eq. 5 on its inliers |s| < d_th; the lowest wins.
//
// Real time: a fast approximate minimiser (mhe_screen.h) ranks every candidate; Ipopt solves the
// `finalists` best-ranked exactly, warm-started from their screened states, and the winner is
// chosen among those by the same likelihood. `finalists = 0` solves every candidate with Ipopt
// (P0's offline procedure, the reference the screened answer is checked against).
#include <random>
#include <vector>

#include "mhe_mlesac/mhe_ellipse.h"
#include "mhe_mlesac/mhe_solver.h"

namespace pedtrack::track::mhe {

struct MlesacOptions {
  Selection selection = Selection::InlierMean;
  bool sampling = true;       ///< false: one candidate with every point (MHE without MLESAC)
  int finalists = 1;          ///< candidates Ipopt solves (0: all of them)
  int screen_iterations = 2;  ///< LM steps of the screen per candidate
  /// Pruning: after half the screen's steps (at least one) only this many best-ranked candidates
  /// go on; the rest cannot win.
  int survivors = 10;
  /// MLESAC's last step (Torr & Zisserman 2000, P0 ref. 20): the winner solved again with its
  /// inliers Υ as the sample, so the estimate uses every point that agrees with it.
  bool refit = true;
  int refit_points = 400;  ///< the refit's sample: at most this many of the inliers, at random
};

/// One horizon and what the estimator knows before it.
struct MlesacInput {
  const std::vector<HorizonFrame>* frames = nullptr;
  std::vector<State> prior;  ///< a priori window x⁻_{T−H+1:T} (start and θ⁻ of eq. 9)
  State arrival_mean = State::Zero();
  Eigen::Matrix<double, 8, 8> arrival_info = Eigen::Matrix<double, 8, 8>::Identity();
};

struct MlesacResult {
  bool ok = false;        ///< some candidate was solved by Ipopt (else: use the KF)
  std::vector<State> xs;  ///< the winner's window
  Selected score;         ///< its selection cost and inliers
  int candidates = 0;     ///< candidates generated (distinct samples)
  int solved = 0;         ///< Ipopt solves (the refit included)
  int failed = 0;         ///< of which failed (infeasible, iteration limit, error)
};

MlesacResult mheMlesac(const MlesacInput& in, const MheParams& params, const MlesacOptions& options,
                       MheSolver& solver, std::mt19937& rng);

}  // namespace pedtrack::track::mhe
