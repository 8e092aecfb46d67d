#include "pedtrack/track/gait_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace pedtrack::track::gait {

double Params::at(double t) const {
  return l0 * std::cos(2 * M_PI * f * (t - t_ref) + phi) + b;
}

double objective(const std::vector<Sample>& s, double t_ref, double l0, double f, double phi,
                 double b) {
  double sum = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double w = 1.0 / double((j + 1) * (j + 1));
    const double r = l0 * std::cos(2 * M_PI * f * (s[j].t - t_ref) + phi) + b - s[j].l;
    sum += w * r * r;
  }
  return sum;
}

namespace {

struct Linear {
  double A = 0, B = 0, b = 0, cost = INFINITY;
};

// For a fixed f: min Σ w (A cos ωτ + B sin ωτ + b − l)² with L₀ = |(A, B)| and b in bounds.
// A = L₀ cos φ, B = −L₀ sin φ. Bounds by clamping: b first (re-solving A, B), then L₀ (scaling
// (A, B) onto the bound and re-solving b).
Linear solveForFrequency(const std::vector<Sample>& s, double t_ref, double f, const Bounds& bd) {
  const double w0 = 2 * M_PI * f;
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double w = 1.0 / double((j + 1) * (j + 1));
    const double a = w0 * (s[j].t - t_ref);
    const Eigen::Vector3d g(std::cos(a), std::sin(a), 1.0);
    N += w * g * g.transpose();
    r += w * s[j].l * g;
  }
  Linear out;
  Eigen::Vector3d x = N.ldlt().solve(r);
  if (!x.allFinite()) x.setZero();
  if (x(2) < bd.b_min || x(2) > bd.b_max) {
    x(2) = std::clamp(x(2), bd.b_min, bd.b_max);
    const Eigen::Vector2d ab =
        N.topLeftCorner<2, 2>().ldlt().solve(r.head<2>() - N.topRightCorner<2, 1>() * x(2));
    if (ab.allFinite()) x.head<2>() = ab;
  }
  const double l0 = x.head<2>().norm();
  if (l0 < bd.l0_min || l0 > bd.l0_max) {
    const double target = std::clamp(l0, bd.l0_min, bd.l0_max);
    x.head<2>() =
        l0 > 1e-12 ? Eigen::Vector2d(x.head<2>() * (target / l0)) : Eigen::Vector2d(target, 0.0);
    const double bb = (r(2) - N.row(2).head<2>().dot(x.head<2>())) / N(2, 2);
    x(2) = std::clamp(bb, bd.b_min, bd.b_max);
  }
  out.A = x(0);
  out.B = x(1);
  out.b = x(2);
  // Σ w (gᵀx − l)² = xᵀNx − 2 rᵀx + Σ w l².
  double wll = 0;
  for (std::size_t j = 0; j < s.size(); ++j) wll += s[j].l * s[j].l / double((j + 1) * (j + 1));
  out.cost = std::max(0.0, x.dot(N * x) - 2 * r.dot(x) + wll);
  return out;
}

}  // namespace

Params fitVarPro(const std::vector<Sample>& s, const Bounds& bd) {
  Params p;
  if (s.size() < 5) return p;
  const double t_ref = s.front().t;
  auto cost = [&](double f) { return solveForFrequency(s, t_ref, f, bd).cost; };
  // A grid fine enough that the optimum's basin (width ~ 1 / the window's duration) is sampled.
  constexpr int kGrid = 21;
  const double step = (bd.f_max - bd.f_min) / (kGrid - 1);
  double best_f = bd.f_min, best = INFINITY;
  for (int i = 0; i < kGrid; ++i) {
    const double f = bd.f_min + i * step, c = cost(f);
    if (c < best) best = c, best_f = f;
  }
  // Golden section on the bracket around the best grid point, to 1 mHz: over a 2 s window that
  // is a phase error of 0.01 rad, far below what the legs' noise resolves.
  double lo = std::max(bd.f_min, best_f - step), hi = std::min(bd.f_max, best_f + step);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), c1 = cost(x1), c2 = cost(x2);
  for (int it = 0; it < 25 && hi - lo > 1e-3; ++it) {
    if (c1 < c2) {
      hi = x2, x2 = x1, c2 = c1, x1 = hi - g * (hi - lo), c1 = cost(x1);
    } else {
      lo = x1, x1 = x2, c1 = c2, x2 = lo + g * (hi - lo), c2 = cost(x2);
    }
  }
  const double f = c1 < c2 ? x1 : x2;
  const Linear lin = solveForFrequency(s, t_ref, f, bd);
  const Linear at_grid = solveForFrequency(s, t_ref, best_f, bd);
  const Linear& use = lin.cost <= at_grid.cost ? lin : at_grid;
  p.f = lin.cost <= at_grid.cost ? f : best_f;
  p.l0 = std::hypot(use.A, use.B);
  p.phi = std::atan2(-use.B, use.A);
  if (p.phi < 0) p.phi += 2 * M_PI;
  p.b = use.b;
  p.t_ref = t_ref;
  p.cost = use.cost;
  p.valid = true;
  return p;
}

}  // namespace pedtrack::track::gait
