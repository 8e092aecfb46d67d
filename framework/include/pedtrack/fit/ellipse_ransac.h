#pragma once
// P1 §III-B (after P0 ref. 12): a torso ellipse fitted by RANSAC under shape constraints, so the
// arms and body sway are outliers. Each iteration fits a constrained ellipse to a random sample
// of the points (eq. 12: minimise J of eq. 6 subject to eq. 8–11) and scores it on every point
// (eq. 13); the best-scoring candidate is the answer.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "pedtrack/fit/circle.h"

namespace pedtrack::fit {

/// A torso ellipse in P1's convention (README "Torso convention"): centre (x, y); `theta` the
/// direction the person faces, defined modulo π by the shape alone; `alpha` the semi-axis across
/// the shoulders (perpendicular to theta), `beta` front to back (along theta).
struct TorsoEllipse {
  double x = 0, y = 0;
  double theta = 0;
  double alpha = 0, beta = 0;
};

/// P1 eq. 7: s = ((−x̃ sin θ + ỹ cos θ)/α)² + ((−x̃ cos θ − ỹ sin θ)/β)² − 1 with x̃ = pₓ − x,
/// ỹ = p_y − y: 0 on the ellipse, negative inside, positive outside (dimensionless).
double ellipseDeviation(const TorsoEllipse& e, const Eigen::Vector2d& p);

/// Defaults are P1 §V-A's.
struct EllipseRansacParams {
  int sample_size = 9;       ///< n(N): points per random sample
  int max_iterations = 100;  ///< m: iterations at most
  /// C: stop once a sample free of outliers was drawn with this probability
  double confidence = 0.95;
  double alpha_min = 0.10, alpha_max = 0.20;  ///< eq. 9 (m)
  double beta_min = 0.05, beta_max = 0.10;    ///< eq. 10 (m)
  double theta_window = 0.261799;             ///< θ_th of eq. 11 (rad): P1's π/12, six digits
  double inlier_threshold = 0.5;              ///< d_th: |s| above it is an outlier (eq. 13)
  bool center_correction = true;              ///< the exp term of eq. 6
  int solver_iterations = 20;  ///< LM iterations (trial steps) of eq. 12 per sample, at most
};

/// The minimiser of eq. 12 on `pts`: J = Σ sᵢ² + Σ exp(|pᵢ − o| − |c − o|) (the second sum only
/// with `center_correction`; o = `origin`, the sensor) over (x, y, θ, α, β), subject to α ≥ β
/// (eq. 8), the bounds of eq. 9–10 and, when `prior_theta` is finite, |θ − θ'| ≤ θ_th modulo π
/// (eq. 11). Solved by projected Levenberg–Marquardt from `start` (projected onto the
/// constraints first; the step uses the exact Hessian where its damped form is positive definite,
/// else JᵀJ; an iterate with β > α is turned by π/2 with α and β swapped, the same ellipse, when
/// eq. 11 allows). The result always satisfies every constraint, θ in (−π, π]. False for fewer
/// than 3 points, bounds with no feasible point (β_min ≤ 0, a min above its max, β_min > α_max,
/// θ_th < 0) or a non-finite result.
bool fitEllipseConstrained(const Points2& pts, const Eigen::Vector2d& origin, double prior_theta,
                           const EllipseRansacParams& params, TorsoEllipse start,
                           TorsoEllipse& out);

/// A starting ellipse for the solver: the points' centroid moved back along the line of sight
/// from `origin` by the middle of β's bounds, θ facing the origin (or `prior_theta` when finite),
/// α and β at the middle of their bounds.
TorsoEllipse initialEllipse(const Points2& pts, const Eigen::Vector2d& origin, double prior_theta,
                            const EllipseRansacParams& params);

struct EllipseRansacResult {
  bool ok = false;
  TorsoEllipse ellipse;
  double cost = 0;     ///< W of the winner: Σ min(sᵢ², d_th²) over all points (eq. 13, MSAC)
  int inliers = 0;     ///< points with |s| ≤ d_th
  int iterations = 0;  ///< samples fitted
  std::vector<std::uint8_t> inlier;  ///< per point, 1 for an inlier
};

/// Algorithm 1 of P1. Samples of min(n(N), M) distinct points (at least 3) are drawn with `rng`;
/// the iteration count is m, lowered adaptively to ⌈log(1 − C)/log(1 − wⁿ)⌉ by the best inlier
/// fraction w seen (one iteration when every sample is all M points). Each sample's candidate is
/// fitEllipseConstrained from initialEllipse of the sample; the lowest W wins (first on ties), as
/// fitted: no refit on its inliers. Points beyond d_th count d_th² each in W (the truncated cost
/// that makes them outliers). Needs at least 3 points and feasible bounds (ok = false otherwise).
/// Deterministic for a given rng state.
EllipseRansacResult fitEllipseRansac(const Points2& pts, const Eigen::Vector2d& origin,
                                     double prior_theta, const EllipseRansacParams& params,
                                     std::mt19937& rng);

}  // namespace pedtrack::fit
