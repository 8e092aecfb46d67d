#pragma once
// The MHE-Ellipse problem of mhe_ellipse.h solved by Ipopt (interior point, exact first and
// second derivatives, the problem's block-tridiagonal sparsity). One solver is reused for every
// problem of a tracker: Ipopt's options and its application object are built once.
#include <memory>
#include <string>
#include <vector>

#include "mhe_mlesac/mhe_ellipse.h"

namespace pedtrack::track::mhe {

struct SolverOptions {
  int max_iterations = 30;  ///< Ipopt's max_iter
  double tolerance = 1e-6;  ///< Ipopt's tol (relative)
  int print_level = 0;      ///< Ipopt's log on stdout (0: silent; 5: per iteration)
};

struct SolveResult {
  enum Status { Solved, Acceptable, IterationLimit, Infeasible, Failed };
  Status status = Failed;
  int iterations = 0;
  double objective = 0;
  std::vector<State> xs;  ///< the window's states (the last iterate when not solved)
  bool usable() const { return status == Solved || status == Acceptable; }
};
const char* toString(SolveResult::Status s);

class MheSolver {
 public:
  explicit MheSolver(const MheParams& params, const SolverOptions& options = {});
  ~MheSolver();
  MheSolver(const MheSolver&) = delete;
  MheSolver& operator=(const MheSolver&) = delete;
  /// Minimises eq. 5 subject to (6)–(10) and the kinematic rows of eq. 2, from `start` (one
  /// state per frame). Never throws for a numerical failure: the status says what happened.
  SolveResult solve(const MheProblem& problem, const std::vector<State>& start);
  /// Several problems over the same horizon (MLESAC's candidates), all from `start`, in one
  /// Ipopt call: the answers are each problem's own (the costs are separable); the status and
  /// the iteration count are the batch's.
  std::vector<SolveResult> solveBatch(const std::vector<const MheProblem*>& problems,
                                      const std::vector<State>& start);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pedtrack::track::mhe
