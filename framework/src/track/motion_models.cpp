#include "pedtrack/track/motion_models.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace pedtrack::track {

MotionModel::~MotionModel() = default;

Eigen::Vector2d MotionModel::velocity(const Eigen::VectorXd& x) const {
  return {x(2), x(3)};
}

// ---- constant velocity --------------------------------------------------------------------

Eigen::VectorXd ConstantVelocity::predict(const Eigen::VectorXd& x, double dt) const {
  return jacobian(x, dt) * x;
}

Eigen::MatrixXd ConstantVelocity::jacobian(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(4, 4);
  F(0, 2) = F(1, 3) = dt;
  return F;
}

Eigen::MatrixXd ConstantVelocity::noise(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(4, 4);
  for (int i = 0; i < 2; ++i) {
    Q(i, i) = q_ * dt * dt * dt / 3;
    Q(i, i + 2) = Q(i + 2, i) = q_ * dt * dt / 2;
    Q(i + 2, i + 2) = q_ * dt;
  }
  return Q;
}

// ---- constant acceleration ----------------------------------------------------------------

Eigen::VectorXd ConstantAcceleration::predict(const Eigen::VectorXd& x, double dt) const {
  return jacobian(x, dt) * x;
}

Eigen::MatrixXd ConstantAcceleration::jacobian(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(6, 6);
  for (int i = 0; i < 2; ++i) {
    F(i, i + 2) = dt;
    F(i, i + 4) = dt * dt / 2;
    F(i + 2, i + 4) = dt;
  }
  return F;
}

Eigen::MatrixXd ConstantAcceleration::noise(const Eigen::VectorXd&, double dt) const {
  const double t2 = dt * dt, t3 = t2 * dt, t4 = t3 * dt, t5 = t4 * dt;
  const double q[3][3] = {
      {t5 / 20, t4 / 8, t3 / 6}, {t4 / 8, t3 / 3, t2 / 2}, {t3 / 6, t2 / 2, dt}};
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(6, 6);
  for (int axis = 0; axis < 2; ++axis)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) Q(axis + 2 * a, axis + 2 * b) = q_ * q[a][b];
  return Q;
}

// ---- coordinated turn ---------------------------------------------------------------------

std::string CoordinatedTurn::name() const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "CT%+.2g", omega_);
  return buf;
}

Eigen::VectorXd CoordinatedTurn::predict(const Eigen::VectorXd& x, double dt) const {
  return jacobian(x, dt) * x;
}

Eigen::MatrixXd CoordinatedTurn::jacobian(const Eigen::VectorXd& x, double dt) const {
  const double wt = omega_ * dt;
  if (std::abs(wt) < 1e-9) return cv_.jacobian(x, dt);
  const double s = std::sin(wt), c = std::cos(wt);
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(4, 4);
  F(0, 2) = s / omega_;
  F(0, 3) = -(1 - c) / omega_;
  F(1, 2) = (1 - c) / omega_;
  F(1, 3) = s / omega_;
  F(2, 2) = c;
  F(2, 3) = -s;
  F(3, 2) = s;
  F(3, 3) = c;
  return F;
}

Eigen::MatrixXd CoordinatedTurn::noise(const Eigen::VectorXd& x, double dt) const {
  return cv_.noise(x, dt);
}

// ---- P2 unicycle --------------------------------------------------------------------------

Eigen::VectorXd Unicycle::predict(const Eigen::VectorXd& x, double dt) const {
  Eigen::VectorXd y = x;
  y(0) += x(3) * std::cos(x(2)) * dt;
  y(1) += x(3) * std::sin(x(2)) * dt;
  return y;
}

Eigen::MatrixXd Unicycle::jacobian(const Eigen::VectorXd& x, double dt) const {
  const double s = std::sin(x(2)), c = std::cos(x(2)), v = x(3);
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);  // P2 eq. 15
  A(0, 2) = -v * s * dt;
  A(0, 3) = c * dt;
  A(1, 2) = v * c * dt;
  A(1, 3) = s * dt;
  return A;
}

Eigen::MatrixXd Unicycle::noise(const Eigen::VectorXd& x, double dt) const {
  const double s = std::sin(x(2)), c = std::cos(x(2)), v = x(3);
  Eigen::MatrixXd W(4, 2);  // P2 eq. 15
  W << -v * s * dt, c * dt, v * c * dt, s * dt, 1, 0, 0, 1;
  Eigen::Matrix2d Q = Eigen::Vector2d(q_theta_ * dt, q_v_ * dt).asDiagonal();
  return W * Q * W.transpose();
}

Eigen::Vector2d Unicycle::velocity(const Eigen::VectorXd& x) const {
  return {x(3) * std::cos(x(2)), x(3) * std::sin(x(2))};
}

ShapeUnicycle::ShapeUnicycle(Eigen::VectorXd rates) : rates_(std::move(rates)) {
  if (rates_.size() != 6 || !(rates_.array() >= 0).all())
    throw std::invalid_argument("the shape unicycle needs 6 non-negative noise rates");
}

Eigen::VectorXd ShapeUnicycle::predict(const Eigen::VectorXd& x, double dt) const {
  Eigen::VectorXd y = x;
  y(0) += x(3) * std::cos(x(2)) * dt;
  y(1) += x(3) * std::sin(x(2)) * dt;
  return y;
}

Eigen::MatrixXd ShapeUnicycle::jacobian(const Eigen::VectorXd& x, double dt) const {
  const double s = std::sin(x(2)), c = std::cos(x(2)), v = x(3);
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(6, 6);
  A(0, 2) = -v * s * dt;
  A(0, 3) = c * dt;
  A(1, 2) = v * c * dt;
  A(1, 3) = s * dt;
  return A;
}

Eigen::MatrixXd ShapeUnicycle::noise(const Eigen::VectorXd&, double dt) const {
  return (rates_ * dt).asDiagonal();
}

Eigen::Vector2d ShapeUnicycle::velocity(const Eigen::VectorXd& x) const {
  return {x(3) * std::cos(x(2)), x(3) * std::sin(x(2))};
}

EllipseRandomWalk::EllipseRandomWalk(Eigen::VectorXd q) : q_(std::move(q)) {
  if (q_.size() != 5 || !(q_.array() > 0).all())
    throw std::invalid_argument("the ellipse random walk needs 5 positive noise variances");
}

Eigen::VectorXd EllipseRandomWalk::predict(const Eigen::VectorXd& x, double dt) const {
  Eigen::VectorXd y = x;
  y.head<3>() += dt * x.segment<3>(3);
  return y;
}

Eigen::MatrixXd EllipseRandomWalk::jacobian(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(8, 8);
  A.block<3, 3>(0, 3).diagonal().setConstant(dt);
  return A;
}

Eigen::MatrixXd EllipseRandomWalk::noise(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(8, 8);
  Q.block<5, 5>(3, 3) = (q_ * dt * dt).asDiagonal();
  return Q;
}

// ---- P3's pose constant acceleration ---------------------------------------------------------

PoseConstantAcceleration::PoseConstantAcceleration(double ax, double ay, double at)
    : var_{ax, ay, at} {
  if (!(ax > 0 && ay > 0 && at > 0))
    throw std::invalid_argument("pose-CA: acceleration variances must be positive");
}

Eigen::VectorXd PoseConstantAcceleration::predict(const Eigen::VectorXd& x, double dt) const {
  return jacobian(x, dt) * x;
}

Eigen::MatrixXd PoseConstantAcceleration::jacobian(const Eigen::VectorXd&, double dt) const {
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(9, 9);
  for (int i = 0; i < 3; ++i) {
    F(i, i + 3) = dt;
    F(i, i + 6) = dt * dt / 2;
    F(i + 3, i + 6) = dt;
  }
  return F;
}

Eigen::MatrixXd PoseConstantAcceleration::noise(const Eigen::VectorXd&, double dt) const {
  const double g[3] = {dt * dt / 2, dt, 1};
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(9, 9);
  for (int axis = 0; axis < 3; ++axis)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) Q(axis + 3 * a, axis + 3 * b) = var_[axis] * g[a] * g[b];
  return Q;
}

}  // namespace pedtrack::track
