#pragma once
// What a person's point cloud says about the torso state [x, y, θ, v, α, β] of P1 (eq. 3–5,
// 18): each observation model fits its shape to the points and returns a linear measurement of
// the state, whose dimension switches with the number of points.
//   ellipse  RANSAC ellipse (fit/ellipse_ransac.h): [x, y, θ, α, β] with ≥ N_e points, the
//            centre [x, y] with ≥ N_b, nothing below
//   box      bounding box (fit/boxes.h): [x, y, θ, α, β] with ≥ N_b points, nothing below
//   cog      the points' centre of gravity moved back by β along the line of sight: [x, y]
// Below N_b only the COG observes: a box or ellipse of a handful of points mostly measures where
// the scan lines happened to fall (eq. 18 is printed with its inequality reversed and leaves
// the sparse case open; this is our reading, and what makes the COG model take over far away).
//   circle   RANSAC circle (P0's KF-circle): [x, y, r] with r observing (α + β)/2
// A shape fixes θ only modulo π (an ellipse or box looks the same from behind): the measured θ
// is the representative nearest the prior heading.
#include <Eigen/Core>
#include <optional>
#include <random>
#include <string>

#include "pedtrack/fit/boxes.h"
#include "pedtrack/fit/ellipse_ransac.h"
#include "pedtrack/track/gaussian.h"

namespace pedtrack::track {

enum class ShapeModel { Ellipse, Box, Cog, Circle };
const char* toString(ShapeModel m);  ///< "ellipse", "box", "cog", "circle"
/// Parses a name of toString; std::invalid_argument otherwise.
ShapeModel shapeModelFromString(const std::string& name);

struct ShapeObservationParams {
  fit::EllipseRansacParams ellipse;  ///< P1 §V-A
  fit::CircleRansacParams circle;
  int n_e = 40;          ///< N_e of eq. 18: points for the full ellipse observation
  int n_b = 10;          ///< N_b: points for the full box observation (and any ellipse at all)
  bool l_shape = false;  ///< box by L-shape fitting instead of minimum area
  /// Measurement variances (P1 Table I): R_e, R_b over [x, y, θ, α, β], R_p over [x, y], and
  /// the circle's over [x, y, r].
  Eigen::VectorXd r_ellipse, r_box, r_cog, r_circle;
  double cog_beta = 0.08;  ///< the COG offset when no ellipse estimate exists (P1: 0.08 m)
  ShapeObservationParams();
};

/// One frame's points of one person, fixed frame, and where the sensor was.
struct ShapeCloud {
  fit::Points2 points;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
};

/// A measurement of the 6-state: z = H x + v.
struct ShapeMeasurement {
  Eigen::VectorXd z;
  LinearMeasurement model;
};

/// The fits of one cloud, each computed once on first use and shared by every observation model
/// (the IMM's three filters see one RANSAC ellipse, not three).
class ShapeFits {
 public:
  /// `prior` is the predicted state (its θ sets the RANSAC window and resolves θ modulo π, its
  /// β offsets the COG), or empty for a cloud no track predicts yet.
  ShapeFits(const ShapeCloud& cloud, Eigen::VectorXd prior, const ShapeObservationParams& params,
            std::mt19937& rng);
  /// The measurement of `model`, or nothing when the cloud has too few points for it.
  std::optional<ShapeMeasurement> measure(ShapeModel model);
  /// The fitted ellipse (when ≥ N_b points and the fit succeeded).
  const std::optional<fit::TorsoEllipse>& ellipse();
  const ShapeCloud& cloud() const { return cloud_; }

 private:
  std::optional<ShapeMeasurement> ellipseMeasurement();
  std::optional<ShapeMeasurement> boxMeasurement();
  std::optional<ShapeMeasurement> cogMeasurement();
  std::optional<ShapeMeasurement> circleMeasurement();
  double resolveHeading(double theta) const;

  const ShapeCloud& cloud_;
  Eigen::VectorXd prior_;
  const ShapeObservationParams& params_;
  std::mt19937& rng_;
  bool ellipse_done_ = false;
  std::optional<fit::TorsoEllipse> ellipse_;
};

/// The rows of `state` (of 6) that a measurement observes, with variances `r`: H selects them.
ShapeMeasurement selectStates(const Eigen::VectorXd& z, const std::vector<int>& states,
                              const Eigen::VectorXd& r);

}  // namespace pedtrack::track
