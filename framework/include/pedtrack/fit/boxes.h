#pragma once
// Bounding boxes of planar point sets (P1's bounding-box model, P0's KF-BB baseline) and the
// point-cloud centre of gravity of P1's PC-COG model.
#include <Eigen/Core>

#include "pedtrack/fit/circle.h"

namespace pedtrack::fit {

/// A rectangle: centre, the direction of its first side (rad, in (−π/2, π/2]) and its half-sides
/// along that direction (`half_a`) and across it (`half_b`).
struct OrientedBox {
  double x = 0, y = 0;
  double angle = 0;
  double half_a = 0, half_b = 0;
};

/// Convex hull, counter-clockwise, no collinear points (Andrew's monotone chain).
Points2 convexHull(const Points2& pts);
/// An axis direction (defined modulo π: a box side, an ellipse's axis) wrapped to (−π/2, π/2].
double wrapHalfPi(double a);

/// The rectangle of least area enclosing the points (rotating calipers: one side lies on a hull
/// edge). False for no points; one point or collinear points give a degenerate box (zero side).
bool minAreaBox(const Points2& pts, OrientedBox& out);

/// L-shape fitting (Zhang et al., "Efficient L-shape fitting for vehicle detection using laser
/// scanners", IV 2017) with the closeness criterion: the orientation in [0, π/2) (searched in
/// steps of `step` rad) whose two edges the points lie closest to, then the rectangle of the
/// points' extents in that orientation. Suited to a partly seen object (one or two sides).
/// `min_distance` (m) is the closeness criterion's d₀. False for no points.
bool lShapeBox(const Points2& pts, OrientedBox& out, double step = M_PI / 180,
               double min_distance = 0.01);

/// Mean of the points. Zero for no points.
Eigen::Vector2d centroid(const Points2& pts);

/// P1 §II-D: the centroid moved `offset` metres further from `origin` along the line of sight,
/// towards the torso centre (the points lie on the near surface). The centroid itself when it
/// coincides with the origin.
Eigen::Vector2d centroidBehindSurface(const Points2& pts, const Eigen::Vector2d& origin,
                                      double offset);

}  // namespace pedtrack::fit
