// Circle fits for P3 eq. 1, f(x, y, r) = Σ ((xᵢ − x)² + (yᵢ − y)² − r²)², r_min ≤ r ≤ r_max.
//
// Why no NLP solver (P3 uses NLopt's MMA; Ipopt would do): the problem has an exact solution.
// With c = r² − x² − y² the residuals eᵢ = bᵢ − 2xᵢx − 2yᵢy − c (bᵢ = xᵢ² + yᵢ²) are linear in
// z = (x, y, c), so f is a convex quadratic ‖Az − b‖² and the bounds become the shell
// r_min² ≤ g(z) = x² + y² + c ≤ r_max². Its unconstrained minimiser z₀ is the algebraic fit.
//  * r(z₀) inside the bounds: z₀ is the global minimum.
//  * r(z₀) outside: for any feasible z the segment z → z₀ crosses the violated bound's surface
//    at some w with f(w) ≤ max(f(z), f(z₀)) = f(z) (f is convex along the segment), so the
//    minimum lies on that surface: min ‖Az − b‖² s.t. g(z) = R². That is a least-squares problem
//    with one quadratic equality constraint, whose global minimum is the z(μ) solving
//    (AᵀA + μD) z = Aᵀb − μ/2·e₃, D = diag(1, 1, 0), with AᵀA + μD ⪰ 0 and g(z(μ)) = R²
//    (Moré 1993, "Generalizations of the trust region problem").
// With the points centred, AᵀA = diag(4S, n) (S the 2×2 scatter) and, in S's eigenbasis
// (eigenvalues s₁ ≤ s₂, ũ = Vᵀ·2Σ p̃ᵢbᵢ, B = Σbᵢ),
//     φ(μ) = g(z(μ)) − R² = Σₖ ũₖ² / (4sₖ + μ)² + (B − μ/2)/n − R²,   μ > −4s₁,
// which is strictly decreasing (φ' < 0), so its one root is found by bisection plus Newton.
// The "hard case" (ũ₁ = 0, so φ stays below 0 up to the pole) puts μ = −4s₁ and completes the
// centre along s₁'s eigenvector. tests/test_fit.cpp checks the result against Ipopt.
#include "pedtrack/fit/circle.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace pedtrack::fit {
namespace {

// The centred problem's pieces: mean, scatter eigen-decomposition, ũ, B and n.
struct Centred {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Vector2d s;  // eigenvalues of S, ascending
  Eigen::Matrix2d V;  // eigenvectors (columns)
  Eigen::Vector2d u;  // Vᵀ · 2 Σ p̃ b
  double B = 0, n = 0;
};

Centred centre(const Points2& pts) {
  Centred c;
  c.n = double(pts.size());
  for (const auto& p : pts) c.mean += p;
  c.mean /= c.n;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (const auto& p : pts) {
    const Eigen::Vector2d q = p - c.mean;
    const double b = q.squaredNorm();
    S += q * q.transpose();
    u += 2 * b * q;
    c.B += b;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(S);  // closed form for 2 × 2
  c.s = es.eigenvalues();
  c.V = es.eigenvectors();
  c.u = c.V.transpose() * u;
  return c;
}

// z(μ): the centre (centred coordinates) and c = r² − |centre|².
void solve(const Centred& c, double mu, Eigen::Vector2d& centre_out, double& cc) {
  const Eigen::Vector2d w(c.u(0) / (4 * c.s(0) + mu), c.u(1) / (4 * c.s(1) + mu));
  centre_out = c.V * w;
  cc = (c.B - 0.5 * mu) / c.n;
}

double phi(const Centred& c, double mu, double R2) {
  const double a = c.u(0) / (4 * c.s(0) + mu), b = c.u(1) / (4 * c.s(1) + mu);
  return a * a + b * b + (c.B - 0.5 * mu) / c.n - R2;
}

double dphi(const Centred& c, double mu) {
  const double d0 = 4 * c.s(0) + mu, d1 = 4 * c.s(1) + mu;
  return -2 * c.u(0) * c.u(0) / (d0 * d0 * d0) - 2 * c.u(1) * c.u(1) / (d1 * d1 * d1) - 0.5 / c.n;
}

// The minimum of f on the surface r = R.
Circle onRadius(const Centred& c, double R) {
  const double R2 = R * R;
  const double pole = -4 * c.s(0);
  const double scale = 4 * c.s(1) + c.n + c.B + R2;  // a size for brackets and tolerances
  // Bracket the root of the decreasing φ on (pole, ∞).
  double lo = pole, hi;
  if (phi(c, 0, R2) > 0) {
    lo = 0;
    hi = std::max(1.0, scale);
    while (phi(c, hi, R2) > 0) hi *= 2;
  } else {
    hi = 0;
    // Approach the pole; if φ never turns positive this is the hard case.
    double step = std::max(std::abs(pole), 1e-12 * scale);
    bool found = false;
    for (int k = 0; k < 60; ++k) {
      step *= 0.5;
      const double m = pole + step;
      if (m >= hi) continue;
      if (phi(c, m, R2) > 0) {
        lo = m;
        found = true;
        break;
      }
      hi = m;
    }
    if (!found) {
      // Hard case: μ = −4s₁, centre = particular part + τ·v₁ with g = R².
      const double mu = pole;
      const double b = c.u(1) / (4 * c.s(1) + mu);
      const double cc = (c.B - 0.5 * mu) / c.n;
      const double tau2 = std::max(0.0, R2 - cc - b * b);
      const Eigen::Vector2d ctr = c.V * Eigen::Vector2d(std::sqrt(tau2), b);
      return {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), R};
    }
  }
  // Safeguarded Newton inside the bracket.
  double mu = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double f = phi(c, mu, R2);
    if (f > 0)
      lo = mu;
    else
      hi = mu;
    double next = mu - f / dphi(c, mu);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - mu) <= 1e-14 * std::max(1.0, std::abs(mu))) {
      mu = next;
      break;
    }
    mu = next;
  }
  Eigen::Vector2d ctr;
  double cc = 0;
  solve(c, mu, ctr, cc);
  return {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), R};
}

}  // namespace

bool fitCircleAlgebraic(const Points2& pts, Circle& out) {
  if (pts.size() < 3) return false;
  const Centred c = centre(pts);
  if (!(c.s(0) > 1e-12 * std::max(c.s(1), 1e-300))) return false;  // collinear
  Eigen::Vector2d ctr;
  double cc = 0;
  solve(c, 0, ctr, cc);
  const double r2 = ctr.squaredNorm() + cc;
  if (!(r2 > 0)) return false;
  out = {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), std::sqrt(r2)};
  return true;
}

bool fitCircleBounded(const Points2& pts, double r_min, double r_max, Circle& out) {
  if (pts.size() < 3 || !(r_min >= 0) || !(r_max >= r_min)) return false;
  const Centred c = centre(pts);
  if (!(c.s(1) > 0)) return false;  // every point the same
  Circle free;
  const bool ok = c.s(0) > 1e-12 * c.s(1) && fitCircleAlgebraic(pts, free);
  if (ok && free.r >= r_min && free.r <= r_max) {
    out = free;
    return true;
  }
  // Collinear points have no algebraic circle; the cost falls toward larger radii, so the
  // minimum is on the r_max surface (φ(0) > 0 there as the pole sits at 0).
  const double R = ok && free.r < r_min ? r_min : r_max;
  out = onRadius(c, R);
  return std::isfinite(out.x) && std::isfinite(out.y);
}

double circleResidual(const Points2& pts, const Circle& c) {
  if (pts.empty()) return 0;
  double s = 0;
  for (const auto& p : pts) {
    const double dx = p.x() - c.x, dy = p.y() - c.y;
    const double e = std::sqrt(dx * dx + dy * dy) - c.r;
    s += e * e;
  }
  return std::sqrt(s / double(pts.size()));
}

}  // namespace pedtrack::fit
