#include "pedtrack/ipopt/gait_fit.h"

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>

#include "pedtrack/ipopt/ipopt_lock.h"

namespace pedtrack::track::gait {
namespace {

using Ipopt::Index;
using Ipopt::Number;

class GaitTnlp : public Ipopt::TNLP {
 public:
  GaitTnlp(const std::vector<Sample>& s, const Bounds& b, const double start[4])
      : s_(s), b_(b), t_ref_(s.front().t) {
    std::copy(start, start + 4, start_);
  }
  double result[4] = {0, 0, 0, 0};
  double cost = 0;

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = 4, m = 0, nnz_jac = 0, nnz_h = 10, style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Index, Number* lo, Number* hi, Index, Number*, Number*) override {
    lo[0] = b_.l0_min, hi[0] = b_.l0_max;
    lo[1] = b_.f_min, hi[1] = b_.f_max;
    lo[2] = 0, hi[2] = 2 * M_PI;
    lo[3] = b_.b_min, hi[3] = b_.b_max;
    return true;
  }
  bool get_starting_point(Index, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    std::copy(start_, start_ + 4, x);
    return true;
  }
  bool eval_f(Index, const Number* x, bool, Number& f) override {
    f = objective(s_, t_ref_, x[0], x[1], x[2], x[3]);
    return true;
  }
  bool eval_grad_f(Index, const Number* x, bool, Number* g) override {
    std::fill(g, g + 4, 0.0);
    for (std::size_t j = 0; j < s_.size(); ++j) {
      const double w = 1.0 / double((j + 1) * (j + 1)), tau = s_[j].t - t_ref_;
      const double a = 2 * M_PI * x[1] * tau + x[2], c = std::cos(a), sn = std::sin(a);
      const double r = x[0] * c + x[3] - s_[j].l;
      g[0] += 2 * w * r * c;
      g[1] += -2 * w * r * x[0] * sn * 2 * M_PI * tau;
      g[2] += -2 * w * r * x[0] * sn;
      g[3] += 2 * w * r;
    }
    return true;
  }
  bool eval_g(Index, const Number*, bool, Index, Number*) override { return true; }
  bool eval_jac_g(Index, const Number*, bool, Index, Index, Index*, Index*, Number*) override {
    return true;
  }
  // Exact Hessian of Σ w r² (lower triangle, row-major): 2 Σ w (∇r ∇rᵀ + r ∇²r).
  bool eval_h(Index, const Number* x, bool, Number sigma, Index, const Number*, bool, Index,
              Index* irow, Index* jcol, Number* v) override {
    if (!v) {
      int k = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j <= i; ++j) irow[k] = i, jcol[k] = j, ++k;
      return true;
    }
    double H[4][4] = {};
    for (std::size_t j = 0; j < s_.size(); ++j) {
      const double w = 1.0 / double((j + 1) * (j + 1)), tau = s_[j].t - t_ref_;
      const double k = 2 * M_PI * tau, a = k * x[1] + x[2], c = std::cos(a), sn = std::sin(a);
      const double r = x[0] * c + x[3] - s_[j].l;
      const double g[4] = {c, -x[0] * sn * k, -x[0] * sn, 1};
      double h[4][4] = {};
      h[1][0] = -sn * k, h[2][0] = -sn;
      h[1][1] = -x[0] * c * k * k, h[2][1] = -x[0] * c * k, h[2][2] = -x[0] * c;
      for (int p = 0; p < 4; ++p)
        for (int q = 0; q <= p; ++q) H[p][q] += 2 * w * (g[p] * g[q] + r * h[p][q]);
    }
    int idx = 0;
    for (int p = 0; p < 4; ++p)
      for (int q = 0; q <= p; ++q) v[idx++] = sigma * H[p][q];
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Index, const Number* x, const Number*, const Number*,
                         Index, const Number*, const Number*, Number obj, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    std::copy(x, x + 4, result);
    cost = obj;
  }

 private:
  const std::vector<Sample>& s_;
  Bounds b_;
  double t_ref_;
  double start_[4];
};

}  // namespace

Params fitIpopt(const std::vector<Sample>& s, const Bounds& bd, const Params& start) {
  Params p;
  if (s.size() < 5) return p;
  double x0[4] = {0.5 * (bd.l0_min + bd.l0_max), 0.5 * (bd.f_min + bd.f_max), M_PI,
                  0.5 * (bd.b_min + bd.b_max)};
  if (start.valid) {
    // The previous fit's phase carried to the newest sample's time.
    const double phi =
        std::fmod(start.phi + 2 * M_PI * start.f * (s.front().t - start.t_ref), 2 * M_PI);
    x0[0] = std::clamp(start.l0, bd.l0_min, bd.l0_max);
    x0[1] = std::clamp(start.f, bd.f_min, bd.f_max);
    x0[2] = phi < 0 ? phi + 2 * M_PI : phi;
    x0[3] = std::clamp(start.b, bd.b_min, bd.b_max);
  }
  Ipopt::SmartPtr<GaitTnlp> nlp = new GaitTnlp(s, bd, x0);
  const std::lock_guard<std::mutex> lock(ipoptLock());
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetIntegerValue("max_iter", 100);
  app->Options()->SetNumericValue("tol", 1e-8);
  if (app->Initialize() != Ipopt::Solve_Succeeded) return p;
  const Ipopt::ApplicationReturnStatus st = app->OptimizeTNLP(nlp);
  if (st != Ipopt::Solve_Succeeded && st != Ipopt::Solved_To_Acceptable_Level) return p;
  p.l0 = nlp->result[0];
  p.f = nlp->result[1];
  p.phi = nlp->result[2];
  p.b = nlp->result[3];
  p.t_ref = s.front().t;
  p.cost = nlp->cost;
  p.valid = true;
  return p;
}

void useChosenGaitSolver(LegPoseParams& p) {
  if (p.solver == LegPoseParams::GaitSolver::Ipopt) p.gait_solver = &fitIpopt;
}

}  // namespace pedtrack::track::gait
