#pragma once
// Least-squares circle fits on planar points.
#include <Eigen/Core>
#include <random>
#include <vector>

namespace pedtrack::fit {

using Points2 = std::vector<Eigen::Vector2d>;

struct Circle {
  double x = 0, y = 0;  ///< centre
  double r = 0;         ///< radius
};

/// The algebraic (Kåsa) fit: minimises f(x, y, r) = Σ ((xᵢ − x)² + (yᵢ − y)² − r²)², the cost of
/// P3 eq. 1 without its radius bounds. False for fewer than 3 points or collinear points.
bool fitCircleAlgebraic(const Points2& pts, Circle& out);

/// P3 eq. 1: the same cost subject to r_min ≤ r ≤ r_max, solved to its global minimum. Where
/// the algebraic fit's radius is inside the bounds it is the answer; otherwise the minimum lies
/// on the violated bound and is found from a monotone scalar (secular) equation of the Lagrange
/// multiplier (see circle.cpp). Collinear points get the r_max circle. False for fewer than 3
/// points or when all points coincide.
bool fitCircleBounded(const Points2& pts, double r_min, double r_max, Circle& out);

/// Root mean square of the geometric distances | |pᵢ − c| − r | (m).
double circleResidual(const Points2& pts, const Circle& c);

struct CircleRansacParams {
  double r_min = 0.10, r_max = 0.30;  ///< radius bounds (m): a torso's
  double inlier_threshold = 0.03;     ///< a point within this of the circle is an inlier (m)
  int max_iterations = 100;           ///< samples of 3 points at most
  double confidence = 0.95;           ///< adaptive stop, as fitEllipseRansac
};

/// RANSAC circle (P0's KF-circle observations, P0 ref. 15): circles through 3 random points
/// with a radius inside the bounds, scored by their inlier count (ties: smaller residual), then
/// refitted on the winner's inliers with fitCircleBounded. `inliers` receives the count (the
/// points within `inlier_threshold` of the returned, refitted circle). False for fewer than 3
/// points or when no sample gave a circle within the bounds.
bool fitCircleRansac(const Points2& pts, const CircleRansacParams& params, std::mt19937& rng,
                     Circle& out, int* inliers = nullptr);

}  // namespace pedtrack::fit
