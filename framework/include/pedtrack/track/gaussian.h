#pragma once
// The state of one filter: a mean and its covariance, and the linear measurement that observes
// it. Dynamic-size Eigen types, so one set of filter parts serves the 4-state CV/CT/unicycle
// models and the 6-state CA model alike.
#include <Eigen/Core>
#include <vector>

namespace pedtrack::track {

struct Gaussian {
  Eigen::VectorXd x;
  Eigen::MatrixXd P;
};

/// z = H x + v, v ~ N(0, R). Rows listed in `angle_rows` are angles: their residuals are wrapped
/// to (-π, π] (the unicycle's heading measurement).
struct LinearMeasurement {
  Eigen::MatrixXd H;
  Eigen::MatrixXd R;
  std::vector<int> angle_rows;
  int dim() const { return int(H.rows()); }
  /// z − H x, with angle rows wrapped.
  Eigen::VectorXd residual(const Eigen::VectorXd& z, const Eigen::VectorXd& x) const;
};

/// Observes the position (states 0 and 1) of an n-state model with isotropic noise σ² I₂.
LinearMeasurement positionMeasurement(int state_dim, double sigma);

/// Wraps an angle to (-π, π].
double wrapAngle(double a);

/// θ + kπ nearest `reference`: an axis (an ellipse's, a box's) is defined modulo π.
double nearestModPi(double theta, double reference);

}  // namespace pedtrack::track
