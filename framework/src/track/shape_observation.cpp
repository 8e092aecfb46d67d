#include "pedtrack/track/shape_observation.h"

#include <cmath>
#include <stdexcept>

namespace pedtrack::track {
namespace {

constexpr double kNoHeading = std::numeric_limits<double>::quiet_NaN();

}  // namespace

const char* toString(ShapeModel m) {
  switch (m) {
    case ShapeModel::Ellipse:
      return "ellipse";
    case ShapeModel::Box:
      return "box";
    case ShapeModel::Cog:
      return "cog";
    case ShapeModel::Circle:
      return "circle";
  }
  return "?";
}

ShapeModel shapeModelFromString(const std::string& name) {
  for (ShapeModel m : {ShapeModel::Ellipse, ShapeModel::Box, ShapeModel::Cog, ShapeModel::Circle})
    if (name == toString(m)) return m;
  throw std::invalid_argument("unknown shape model '" + name + "' (ellipse, box, cog or circle)");
}

ShapeObservationParams::ShapeObservationParams() {
  // P1 Table I.
  const double th = 0.068538919452;  // (π/12)², as the keys have always given it (12 digits)
  r_ellipse = (Eigen::VectorXd(5) << 9e-4, 9e-4, th, 9e-2, 9e-2).finished();
  r_box = (Eigen::VectorXd(5) << 9e-4, 9e-4, th, 16e-2, 16e-2).finished();
  r_cog = (Eigen::VectorXd(2) << 3.6e-3, 3.6e-3).finished();
  r_circle = (Eigen::VectorXd(3) << 9e-4, 9e-4, 9e-2).finished();
}

ShapeMeasurement selectStates(const Eigen::VectorXd& z, const std::vector<int>& states,
                              const Eigen::VectorXd& r) {
  ShapeMeasurement m;
  m.z = z;
  const int n = int(states.size());
  m.model.H = Eigen::MatrixXd::Zero(n, 6);
  for (int i = 0; i < n; ++i) {
    m.model.H(i, states[i]) = 1;
    if (states[i] == 2) m.model.angle_rows.push_back(i);
  }
  m.model.R = r.head(n).asDiagonal();
  return m;
}

ShapeFits::ShapeFits(const ShapeCloud& cloud, Eigen::VectorXd prior,
                     const ShapeObservationParams& params, std::mt19937& rng)
    : cloud_(cloud), prior_(std::move(prior)), params_(params), rng_(rng) {}

std::optional<ShapeMeasurement> ShapeFits::measure(ShapeModel model) {
  switch (model) {
    case ShapeModel::Ellipse:
      return ellipseMeasurement();
    case ShapeModel::Box:
      return boxMeasurement();
    case ShapeModel::Cog:
      return cogMeasurement();
    case ShapeModel::Circle:
      return circleMeasurement();
  }
  return std::nullopt;
}

// The shape's heading modulo π, made the representative nearest the prior heading; without a
// prior, the one facing the sensor.
double ShapeFits::resolveHeading(double theta) const {
  if (prior_.size() >= 3) return nearestModPi(theta, prior_(2));
  return theta;
}

const std::optional<fit::TorsoEllipse>& ShapeFits::ellipse() {
  if (ellipse_done_) return ellipse_;
  ellipse_done_ = true;
  if (int(cloud_.points.size()) < params_.n_b) return ellipse_;
  const double prior_theta = prior_.size() >= 3 ? prior_(2) : kNoHeading;
  const fit::EllipseRansacResult r =
      fit::fitEllipseRansac(cloud_.points, cloud_.origin, prior_theta, params_.ellipse, rng_);
  if (r.ok) ellipse_ = r.ellipse;
  return ellipse_;
}

std::optional<ShapeMeasurement> ShapeFits::ellipseMeasurement() {
  const auto& e = ellipse();
  if (!e) return std::nullopt;
  if (int(cloud_.points.size()) < params_.n_e)
    return selectStates(Eigen::Vector2d(e->x, e->y), {0, 1}, params_.r_ellipse);
  Eigen::VectorXd z(5);
  z << e->x, e->y, resolveHeading(e->theta), e->alpha, e->beta;
  return selectStates(z, {0, 1, 2, 4, 5}, params_.r_ellipse);
}

std::optional<ShapeMeasurement> ShapeFits::boxMeasurement() {
  if (int(cloud_.points.size()) < params_.n_b) return std::nullopt;
  fit::OrientedBox b;
  if (!(params_.l_shape ? fit::lShapeBox(cloud_.points, b) : fit::minAreaBox(cloud_.points, b)))
    return std::nullopt;
  // The heading is one of the box's axes: the one nearer the prior heading, else the shorter
  // side's (β, front to back, is the smaller semi-axis). α is the half-side across it.
  double heading = b.angle, along = b.half_a, across = b.half_b;
  const auto swapAxes = [&] {
    heading = b.angle + M_PI / 2;
    along = b.half_b;
    across = b.half_a;
  };
  if (prior_.size() >= 3) {
    const double d0 = std::abs(wrapAngle(2 * (b.angle - prior_(2))));
    const double d1 = std::abs(wrapAngle(2 * (b.angle + M_PI / 2 - prior_(2))));
    if (d1 < d0) swapAxes();
  } else if (b.half_b < b.half_a) {
    swapAxes();
  }
  if (prior_.size() < 3) {
    // No prior: face the sensor.
    const Eigen::Vector2d to_sensor = cloud_.origin - Eigen::Vector2d(b.x, b.y);
    if (std::cos(heading) * to_sensor.x() + std::sin(heading) * to_sensor.y() < 0) heading += M_PI;
  }
  Eigen::VectorXd z(5);
  z << b.x, b.y, wrapAngle(resolveHeading(heading)), across, along;
  return selectStates(z, {0, 1, 2, 4, 5}, params_.r_box);
}

std::optional<ShapeMeasurement> ShapeFits::cogMeasurement() {
  if (cloud_.points.empty()) return std::nullopt;
  const double beta = prior_.size() >= 6 && prior_(5) > 0 ? prior_(5) : params_.cog_beta;
  const Eigen::Vector2d c = fit::centroidBehindSurface(cloud_.points, cloud_.origin, beta);
  return selectStates(c, {0, 1}, params_.r_cog);
}

std::optional<ShapeMeasurement> ShapeFits::circleMeasurement() {
  fit::Circle c;
  if (!fit::fitCircleRansac(cloud_.points, params_.circle, rng_, c)) return std::nullopt;
  ShapeMeasurement m;
  m.z = Eigen::Vector3d(c.x, c.y, c.r);
  m.model.H = Eigen::MatrixXd::Zero(3, 6);
  m.model.H(0, 0) = 1;
  m.model.H(1, 1) = 1;
  m.model.H(2, 4) = 0.5;  // the circle's radius lies between the semi-axes: their mean
  m.model.H(2, 5) = 0.5;
  m.model.R = params_.r_circle.asDiagonal();
  return m;
}

}  // namespace pedtrack::track
