#include "pedtrack/track/gaussian.h"

#include <cmath>

namespace pedtrack::track {

double wrapAngle(double a) {
  a = std::remainder(a, 2 * M_PI);  // in [-π, π]
  return a <= -M_PI ? a + 2 * M_PI : a;
}

Eigen::VectorXd LinearMeasurement::residual(const Eigen::VectorXd& z,
                                            const Eigen::VectorXd& x) const {
  Eigen::VectorXd r = z - H * x;
  for (int i : angle_rows) r(i) = wrapAngle(r(i));
  return r;
}

LinearMeasurement positionMeasurement(int state_dim, double sigma) {
  LinearMeasurement m;
  m.H = Eigen::MatrixXd::Zero(2, state_dim);
  m.H(0, 0) = m.H(1, 1) = 1;
  m.R = Eigen::MatrixXd::Identity(2, 2) * sigma * sigma;
  return m;
}

double nearestModPi(double theta, double reference) {
  return reference + wrapAngle(2 * (theta - reference)) / 2;
}

}  // namespace pedtrack::track
