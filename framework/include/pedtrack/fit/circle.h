#pragma once
// Least-squares circle fits on planar points.
#include <Eigen/Core>
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

}  // namespace pedtrack::fit
