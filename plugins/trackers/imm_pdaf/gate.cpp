#include "imm_pdaf/gate.h"

#include <Eigen/LU>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace pedtrack::track {

double gateThreshold(double p_gate, int dof) {
  return boost::math::quantile(boost::math::chi_squared(dof), p_gate);
}

double unitBallVolume(int n) {
  return std::pow(M_PI, n / 2.0) / std::tgamma(n / 2.0 + 1);
}

double gateVolume(double gamma, const Eigen::MatrixXd& S) {
  const int n = int(S.rows());
  return unitBallVolume(n) * std::pow(gamma, n / 2.0) * std::sqrt(std::max(0.0, S.determinant()));
}

}  // namespace pedtrack::track
