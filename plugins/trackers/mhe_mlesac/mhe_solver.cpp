#include "mhe_mlesac/mhe_solver.h"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>
#include <mutex>

#include "pedtrack/ipopt/ipopt_lock.h"

namespace pedtrack::track::mhe {
namespace {

using Ipopt::Index;
using Ipopt::Number;

constexpr double kInf = 1e19;                        // Ipopt's "no bound" (nlp_upper_bound_inf)
constexpr int kBlock = kStates * (kStates + 1) / 2;  // one state's lower-triangular Hessian

// One Ipopt problem holds a batch of B independent MHE-Ellipse problems over the same horizon
// (the MLESAC candidates of one frame): their costs add, their variables and constraints do not
// meet, so the solution is each problem's own, while Ipopt's fixed cost per call and per
// iteration (MUMPS's set-up dominates at this size) is paid once for the batch.
//
// Per problem — variables: the H states, 8 each; constraints, in order: the kinematic rows of
// eq. 2 (3 per step, = 0), eq. 6 (α − β ≥ 0, one per frame), eq. 10 ((x − oₓ)² + (y − o_y)² ≥ r̄²,
// one per frame; without samples the bound is −∞, so every problem has the same structure).
// Eq. 7–9 are variable bounds. The Lagrangian's Hessian is block tridiagonal: a dense 8 × 8
// block per state and, from the motion term, the diagonal coupling of consecutive velocities
// and semi-axes.
class MheTnlp : public Ipopt::TNLP {
 public:
  MheTnlp(const MheParams& params, int frames, int batch) : p_(params), h_(frames), b_(batch) {}

  int frames() const { return h_; }
  int batch() const { return b_; }
  std::vector<SolveResult> results;

  /// The problems to solve next (same horizon and batch size: Ipopt keeps the structure).
  void set(const std::vector<const MheProblem*>& problems, const std::vector<State>& start) {
    pbs_ = &problems;
    start_ = &start;
    range2_.assign(std::size_t(b_ * h_), -kInf);
    for (int c = 0; c < b_; ++c)
      for (int k = 0; k < h_; ++k)
        if (!problems[c]->sample[k].empty())
          range2_[c * h_ + k] = std::pow(meanSampleRange(*problems[c], k), 2);
    results.assign(std::size_t(b_), SolveResult{});
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = nVars() * b_;
    m = nCons() * b_;
    nnz_jac = (9 * (h_ - 1) + 4 * h_) * b_;
    nnz_h = nHess() * b_;
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index, Number* xl, Number* xu, Index, Number* gl, Number* gu) override {
    for (int c = 0; c < b_; ++c) {
      const MheProblem& pb = *(*pbs_)[c];
      for (int k = 0; k < h_; ++k) {
        Number* l = xl + nVars() * c + kStates * k;
        Number* u = xu + nVars() * c + kStates * k;
        std::fill(l, l + kStates, -kInf);
        std::fill(u, u + kStates, kInf);
        l[2] = pb.prior[k](2) - p_.theta_th;  // (9)
        u[2] = pb.prior[k](2) + p_.theta_th;
        l[6] = p_.alpha_min, u[6] = p_.alpha_max;  // (7)
        l[7] = p_.beta_min, u[7] = p_.beta_max;    // (8)
      }
      Number* lo = gl + nCons() * c;
      Number* hi = gu + nCons() * c;
      int row = 0;
      for (; row < 3 * (h_ - 1); ++row) lo[row] = hi[row] = 0;
      for (int k = 0; k < h_; ++k, ++row) lo[row] = 0, hi[row] = kInf;                    // (6)
      for (int k = 0; k < h_; ++k, ++row) lo[row] = range2_[c * h_ + k], hi[row] = kInf;  // (10)
    }
    return true;
  }

  bool get_starting_point(Index, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    for (int c = 0; c < b_; ++c)
      for (int k = 0; k < h_; ++k) Eigen::Map<State>(x + nVars() * c + kStates * k) = (*start_)[k];
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& f) override {
    f = 0;
    for (int c = 0; c < b_; ++c) f += mheCost(*(*pbs_)[c], p_, states(x, c)).total();
    return std::isfinite(f);
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    std::fill(grad, grad + n, 0.0);
    for (int c = 0; c < b_; ++c) gradient(*(*pbs_)[c], states(x, c), grad + nVars() * c);
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index, Number* g) override {
    for (int c = 0; c < b_; ++c) {
      const MheProblem& pb = *(*pbs_)[c];
      const std::vector<State> xs = states(x, c);
      Number* out = g + nCons() * c;
      int row = 0;
      for (int k = 1; k < h_; ++k) {
        const double dt = (*pb.frames)[k].dt;
        for (int i = 0; i < 3; ++i) out[row++] = xs[k](i) - xs[k - 1](i) - dt * xs[k - 1](3 + i);
      }
      for (int k = 0; k < h_; ++k) out[row++] = xs[k](6) - xs[k](7);
      for (int k = 0; k < h_; ++k)
        out[row++] = (xs[k].head<2>() - (*pb.frames)[k].origin).squaredNorm();
    }
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* iRow, Index* jCol,
                  Number* v) override {
    int e = 0;
    for (int c = 0; c < b_; ++c) {
      const int r0 = nCons() * c, v0 = nVars() * c;
      if (!v) {
        int row = r0;
        auto put = [&](int var) { iRow[e] = row, jCol[e++] = v0 + var; };
        for (int k = 1; k < h_; ++k)
          for (int i = 0; i < 3; ++i, ++row) {
            put(kStates * k + i);
            put(kStates * (k - 1) + i);
            put(kStates * (k - 1) + 3 + i);
          }
        for (int k = 0; k < h_; ++k, ++row) put(kStates * k + 6), put(kStates * k + 7);
        for (int k = 0; k < h_; ++k, ++row) put(kStates * k), put(kStates * k + 1);
        continue;
      }
      const MheProblem& pb = *(*pbs_)[c];
      for (int k = 1; k < h_; ++k)
        for (int i = 0; i < 3; ++i) v[e++] = 1, v[e++] = -1, v[e++] = -(*pb.frames)[k].dt;
      for (int k = 0; k < h_; ++k) v[e++] = 1, v[e++] = -1;
      for (int k = 0; k < h_; ++k) {
        const Point& o = (*pb.frames)[k].origin;
        v[e++] = 2 * (x[v0 + kStates * k] - o.x());
        v[e++] = 2 * (x[v0 + kStates * k + 1] - o.y());
      }
    }
    return true;
  }

  bool eval_h(Index, const Number* x, bool, Number sigma, Index, const Number* lambda, bool,
              Index nele, Index* iRow, Index* jCol, Number* v) override {
    if (!v) {
      int e = 0;
      for (int c = 0; c < b_; ++c) {
        const int v0 = nVars() * c;
        for (int k = 0; k < h_; ++k)
          for (int r = 0; r < kStates; ++r)
            for (int j = 0; j <= r; ++j)
              iRow[e] = v0 + kStates * k + r, jCol[e++] = v0 + kStates * k + j;
        for (int k = 1; k < h_; ++k)
          for (int j = 3; j < kStates; ++j)
            iRow[e] = v0 + kStates * k + j, jCol[e++] = v0 + kStates * (k - 1) + j;
      }
      return true;
    }
    std::fill(v, v + nele, 0.0);
    for (int c = 0; c < b_; ++c)
      hessian(*(*pbs_)[c], states(x, c), sigma, lambda + nCons() * c + 4 * h_ - 3, v + nHess() * c);
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    SolveResult::Status st = SolveResult::Failed;
    switch (status) {
      case Ipopt::SUCCESS:
        st = SolveResult::Solved;
        break;
      case Ipopt::STOP_AT_ACCEPTABLE_POINT:
        st = SolveResult::Acceptable;
        break;
      case Ipopt::MAXITER_EXCEEDED:
      case Ipopt::CPUTIME_EXCEEDED:
        st = SolveResult::IterationLimit;
        break;
      case Ipopt::LOCAL_INFEASIBILITY:
        st = SolveResult::Infeasible;
        break;
      default:
        break;
    }
    for (int c = 0; c < b_; ++c) {
      SolveResult& r = results[c];
      r.status = st;
      r.xs = states(x, c);
      r.objective = mheCost(*(*pbs_)[c], p_, r.xs).total();
    }
  }

 private:
  int nVars() const { return kStates * h_; }
  int nCons() const { return 3 * (h_ - 1) + 2 * h_; }
  int nHess() const { return kBlock * h_ + 5 * (h_ - 1); }

  std::vector<State> states(const Number* x, int c) const {
    std::vector<State> xs(h_);
    for (int k = 0; k < h_; ++k) xs[k] = Eigen::Map<const State>(x + nVars() * c + kStates * k);
    return xs;
  }

  void gradient(const MheProblem& pb, const std::vector<State>& xs, Number* grad) const {
    for (int k = 1; k < h_; ++k) {
      const double dt = (*pb.frames)[k].dt;
      const auto noise = systemNoise(xs[k - 1], xs[k], dt);
      for (int j = 0; j < 5; ++j) {
        const double d = 2 * noise(j) / (p_.q(j) * p_.horizon * dt);
        grad[kStates * k + 3 + j] += d;
        grad[kStates * (k - 1) + 3 + j] -= d;
      }
    }
    Eigen::Map<State>(grad) += 2 * pb.arrival_info * (xs[0] - pb.arrival_mean);
    Eigen::Matrix<double, 5, 1> g;
    for (int k = 0; k < h_; ++k)
      for (int i : pb.sample[k]) {
        const double s = deviation(xs[k], (*pb.frames)[k].points[i], g, nullptr);
        for (int j = 0; j < 5; ++j)
          grad[kStates * k + kShapeStates[j]] += 2 * pb.data_weight * s * g(j);
      }
  }

  // The problem's Hessian entries (σ∇²f + Σ λ∇²g) in eval_h's order; `range_lambda` are the
  // multipliers of its eq. 10 rows.
  void hessian(const MheProblem& pb, const std::vector<State>& xs, double sigma,
               const Number* range_lambda, Number* v) const {
    auto at = [&](int k, int r, int c) -> Number& {  // block k, r ≥ c
      return v[kBlock * k + r * (r + 1) / 2 + c];
    };
    // Motion term: n_j = Δ/dt, cost n_j² / (q_j H).
    for (int k = 1; k < h_; ++k) {
      const double dt = (*pb.frames)[k].dt;
      for (int j = 0; j < 5; ++j) {
        const double w = sigma * 2 / (p_.q(j) * p_.horizon * dt * dt);
        at(k, 3 + j, 3 + j) += w;
        at(k - 1, 3 + j, 3 + j) += w;
        v[kBlock * h_ + 5 * (k - 1) + j] -= w;
      }
    }
    for (int r = 0; r < kStates; ++r)
      for (int c = 0; c <= r; ++c) at(0, r, c) += sigma * 2 * pb.arrival_info(r, c);
    Eigen::Matrix<double, 5, 1> g;
    Eigen::Matrix<double, 5, 5> H;
    for (int k = 0; k < h_; ++k) {
      Eigen::Matrix<double, 5, 5> sum = Eigen::Matrix<double, 5, 5>::Zero();
      for (int i : pb.sample[k]) {
        const double s = deviation(xs[k], (*pb.frames)[k].points[i], g, &H);
        sum += g * g.transpose() + s * H;
      }
      sum *= sigma * 2 * pb.data_weight;
      for (int r = 0; r < 5; ++r)
        for (int c = 0; c <= r; ++c) at(k, kShapeStates[r], kShapeStates[c]) += sum(r, c);
      // Eq. 10: ∇² of (x − oₓ)² + (y − o_y)² is 2 I on (x, y).
      at(k, 0, 0) += 2 * range_lambda[k];
      at(k, 1, 1) += 2 * range_lambda[k];
    }
  }

  const MheParams& p_;
  int h_, b_;
  const std::vector<const MheProblem*>* pbs_ = nullptr;
  const std::vector<State>* start_ = nullptr;
  std::vector<double> range2_;  // r̄² of eq. 10 per problem and frame (−∞: no constraint)
};

}  // namespace

const char* toString(SolveResult::Status s) {
  switch (s) {
    case SolveResult::Solved:
      return "solved";
    case SolveResult::Acceptable:
      return "acceptable";
    case SolveResult::IterationLimit:
      return "iteration limit";
    case SolveResult::Infeasible:
      return "infeasible";
    case SolveResult::Failed:
      break;
  }
  return "failed";
}

struct MheSolver::Impl {
  MheParams params;
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
  Ipopt::SmartPtr<MheTnlp> nlp;  // reused while the horizon length stays the same
};

MheSolver::MheSolver(const MheParams& params, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->params = params;
  const std::lock_guard<std::mutex> lock(ipoptLock());
  // Quiet: no banner, no iteration log (an application without a console journal).
  impl_->app = new Ipopt::IpoptApplication(options.print_level > 0);
  Ipopt::OptionsList& o = *impl_->app->Options();
  o.SetIntegerValue("print_level", options.print_level);
  o.SetStringValue("sb", "yes");
  o.SetIntegerValue("max_iter", options.max_iterations);
  o.SetNumericValue("tol", options.tolerance);
  o.SetStringValue("hessian_approximation", "exact");
  // Warm start: every candidate starts from the a priori window, already near the answer, so
  // the barrier starts small and the start is barely pushed off the bounds.
  o.SetNumericValue("mu_init", 1e-3);
  o.SetNumericValue("bound_push", 1e-6);
  o.SetNumericValue("bound_frac", 1e-6);
  o.SetStringValue("mu_strategy", "adaptive");
  impl_->app->Initialize();
}

MheSolver::~MheSolver() {
  const std::lock_guard<std::mutex> lock(ipoptLock());  // MUMPS's clean-up touches it too
  impl_.reset();
}

SolveResult MheSolver::solve(const MheProblem& problem, const std::vector<State>& start) {
  return solveBatch({&problem}, start).front();
}

std::vector<SolveResult> MheSolver::solveBatch(const std::vector<const MheProblem*>& problems,
                                               const std::vector<State>& start) {
  const int h = problems.front()->size(), b = int(problems.size());
  Ipopt::SmartPtr<MheTnlp>& nlp = impl_->nlp;
  const bool again = IsValid(nlp) && nlp->frames() == h && nlp->batch() == b;
  if (!again) nlp = new MheTnlp(impl_->params, h, b);
  nlp->set(problems, start);
  const std::lock_guard<std::mutex> lock(ipoptLock());
  try {
    const Ipopt::SmartPtr<Ipopt::TNLP> tnlp(GetRawPtr(nlp));
    again ? impl_->app->ReOptimizeTNLP(tnlp) : impl_->app->OptimizeTNLP(tnlp);
  } catch (...) {
    // An exception inside Ipopt (a failed allocation, a NaN it could not recover from): the
    // results stay Failed with the start as their states.
  }
  int iterations = 0;
  if (auto stats = impl_->app->Statistics(); IsValid(stats)) iterations = stats->IterationCount();
  std::vector<SolveResult> out = nlp->results;
  for (SolveResult& r : out) {
    if (r.xs.empty()) r.xs = start, r.status = SolveResult::Failed;  // no finalize_solution
    r.iterations = iterations;
  }
  return out;
}

}  // namespace pedtrack::track::mhe
