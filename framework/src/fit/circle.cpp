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
// The "hard case" (ũ₁ = 0, so φ stays below 0 up to the pole; collinear points among others)
// puts μ = −4s₁ and completes the centre along s₁'s eigenvector. tests/test_fit.cpp checks the
// result against Ipopt.
#include "pedtrack/fit/circle.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

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

// Collinear points (s₁ ≈ 0) have no scatter across their line, and ũ₁ is 0 in exact arithmetic:
// it is set to 0 so that the pole at μ = 0 is the hard case instead of 0/0.
bool collinear(const Centred& c) {
  return !(c.s(0) > 1e-12 * c.s(1));
}

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
  if (collinear(c)) {
    c.s(0) = 0;
    c.u(0) = 0;
  }
  return c;
}

// ũₖ / (4sₖ + μ), 0 for a component without data (ũₖ = 0), also at its pole.
double part(const Centred& c, int k, double mu) {
  return c.u(k) == 0 ? 0 : c.u(k) / (4 * c.s(k) + mu);
}

// z(μ): the centre (centred coordinates) and c = r² − |centre|².
void solve(const Centred& c, double mu, Eigen::Vector2d& centre_out, double& cc) {
  centre_out = c.V * Eigen::Vector2d(part(c, 0, mu), part(c, 1, mu));
  cc = (c.B - 0.5 * mu) / c.n;
}

double phi(const Centred& c, double mu, double R2) {
  const double a = part(c, 0, mu), b = part(c, 1, mu);
  return a * a + b * b + (c.B - 0.5 * mu) / c.n - R2;
}

double dphi(const Centred& c, double mu) {
  double d = -0.5 / c.n;
  for (int k = 0; k < 2; ++k) {
    const double p = part(c, k, mu);
    d -= 2 * p * p / (4 * c.s(k) + mu);
  }
  return d;
}

// The algebraic fit: z(0), when the points are not collinear.
bool algebraic(const Centred& c, Circle& out) {
  if (collinear(c)) return false;
  Eigen::Vector2d ctr;
  double cc = 0;
  solve(c, 0, ctr, cc);
  const double r2 = ctr.squaredNorm() + cc;
  if (!(r2 > 0)) return false;
  out = {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), std::sqrt(r2)};
  return true;
}

// The minimum of f on the surface r = R: the root of the decreasing φ on (pole, ∞), or the hard
// case at the pole when φ stays below zero there.
Circle onRadius(const Centred& c, double R) {
  const double R2 = R * R;
  const double pole = -4 * c.s(0);
  const double scale = 4 * c.s(1) + c.n + c.B + R2;  // a size for brackets and tolerances
  // φ just right of the pole: +∞ when ũ₁ ≠ 0, else its finite limit.
  const double at_pole = c.u(0) == 0 ? phi(c, pole, R2) : INFINITY;
  if (!(at_pole > 0)) {
    // Hard case: μ = −4s₁, centre = the second component's part + τ·v₁ with g = R².
    const double b = part(c, 1, pole);
    const double cc = (c.B - 0.5 * pole) / c.n;
    const double tau = std::sqrt(std::max(0.0, R2 - cc - b * b));
    const Eigen::Vector2d ctr = c.V * Eigen::Vector2d(tau, b);
    return {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), R};
  }
  // Bracket the root: from 0 upward when φ(0) > 0, else between the pole and 0.
  double lo, hi;
  if (pole < 0 && !(phi(c, 0, R2) > 0)) {
    hi = 0;
    lo = pole;
    for (double step = -pole; step > 1e-300; step *= 0.5) {  // toward the pole
      if (phi(c, pole + step, R2) > 0) {
        lo = pole + step;
        break;
      }
      hi = pole + step;
    }
  } else {
    lo = std::max(pole, 0.0);
    hi = std::max(1.0, scale);
    while (phi(c, hi, R2) > 0) hi *= 2;
  }
  // Safeguarded Newton inside the bracket.
  double mu = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double f = phi(c, mu, R2);
    (f > 0 ? lo : hi) = mu;
    double next = mu - f / dphi(c, mu);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - mu) <= 1e-14 * std::max(1.0, std::abs(mu));
    mu = next;
    if (done) break;
  }
  Eigen::Vector2d ctr;
  double cc = 0;
  solve(c, mu, ctr, cc);
  return {c.mean.x() + ctr.x(), c.mean.y() + ctr.y(), R};
}

}  // namespace

bool fitCircleAlgebraic(const Points2& pts, Circle& out) {
  return pts.size() >= 3 && algebraic(centre(pts), out);
}

bool fitCircleBounded(const Points2& pts, double r_min, double r_max, Circle& out) {
  if (pts.size() < 3 || !(r_min >= 0) || !(r_max >= r_min)) return false;
  const Centred c = centre(pts);
  if (!(c.s(1) > 0)) return false;  // every point the same
  Circle free;
  const bool ok = algebraic(c, free);
  if (ok && free.r >= r_min && free.r <= r_max) {
    out = free;
    return true;
  }
  // Collinear points have no algebraic circle; the cost falls toward larger radii, so their
  // minimum is on the r_max surface.
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

namespace {

// The circle through three points (false when they are collinear or coincide), computed relative
// to the first point.
bool circleThrough(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   Circle& out) {
  const Eigen::Vector2d p = b - a, q = c - a;
  const double d = 2 * (p.x() * q.y() - p.y() * q.x());
  const double scale = p.squaredNorm() * q.squaredNorm();
  if (!(d * d > 1e-24 * scale) || !(scale > 0)) return false;
  const double pp = p.squaredNorm(), qq = q.squaredNorm();
  const double ux = (q.y() * pp - p.y() * qq) / d, uy = (p.x() * qq - q.x() * pp) / d;
  out = {a.x() + ux, a.y() + uy, std::hypot(ux, uy)};
  return std::isfinite(out.r);
}

// Inlier count and Σ squared geometric distances of the inliers.
int circleInliers(const Points2& pts, const Circle& c, double th, double& sq) {
  int n = 0;
  sq = 0;
  for (const auto& p : pts) {
    const double e = std::abs(std::hypot(p.x() - c.x, p.y() - c.y) - c.r);
    if (e <= th) {
      ++n;
      sq += e * e;
    }
  }
  return n;
}

}  // namespace

bool fitCircleRansac(const Points2& pts, const CircleRansacParams& params, std::mt19937& rng,
                     Circle& out, int* inliers) {
  const int M = int(pts.size());
  if (M < 3 || !(params.r_min >= 0) || !(params.r_max >= params.r_min)) return false;
  const int m = std::max(1, params.max_iterations);
  const double C = params.confidence;
  int N = m;
  std::vector<int> idx(M);
  std::iota(idx.begin(), idx.end(), 0);
  Circle best;
  int best_n = -1;
  double best_sq = 0;
  for (int k = 0; k < N; ++k) {
    for (int i = 0; i < 3; ++i) {  // partial Fisher–Yates: 3 distinct points
      std::uniform_int_distribution<int> pick(i, M - 1);
      std::swap(idx[i], idx[pick(rng)]);
    }
    Circle c;
    if (!circleThrough(pts[idx[0]], pts[idx[1]], pts[idx[2]], c) || c.r < params.r_min ||
        c.r > params.r_max)
      continue;
    double sq = 0;
    const int n = circleInliers(pts, c, params.inlier_threshold, sq);
    if (n > best_n || (n == best_n && sq < best_sq)) {
      best = c;
      best_n = n;
      best_sq = sq;
      // Adaptive count log(1 − C)/log(1 − w³) from the best inlier fraction w.
      const double w3 = std::pow(double(n) / M, 3);
      if (!(C > 0) || !(w3 < 1)) {
        N = std::min(N, k + 1);
      } else if (C < 1 && w3 > 0) {
        const double need = std::ceil(std::log(1 - C) / std::log1p(-w3));
        if (need < N) N = std::max(1, int(need));
      }
    }
  }
  if (best_n < 0) return false;
  Points2 in;
  in.reserve(best_n);
  for (const auto& p : pts)
    if (std::abs(std::hypot(p.x() - best.x, p.y() - best.y) - best.r) <= params.inlier_threshold)
      in.push_back(p);
  Circle refit;
  if (fitCircleBounded(in, params.r_min, params.r_max, refit)) best = refit;
  out = best;
  if (inliers) {
    double sq = 0;
    *inliers = circleInliers(pts, best, params.inlier_threshold, sq);
  }
  return true;
}

}  // namespace pedtrack::fit
