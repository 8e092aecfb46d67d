#include "pedtrack/track/kalman.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

namespace pedtrack::track {

void kalmanPredict(Gaussian& g, const MotionModel& model, double dt) {
  const Eigen::MatrixXd F = model.jacobian(g.x, dt);  // at the prior estimate (EKF)
  const Eigen::MatrixXd Q = model.noise(g.x, dt);
  g.x = model.predict(g.x, dt);
  g.P = F * g.P * F.transpose() + Q;
  g.P = 0.5 * (g.P + g.P.transpose());
}

Eigen::MatrixXd innovationCovariance(const Gaussian& g, const LinearMeasurement& m) {
  return m.H * g.P * m.H.transpose() + m.R;
}

double gaussianLogPdf(const Eigen::VectorXd& nu, const Eigen::MatrixXd& S) {
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  const Eigen::VectorXd w = llt.matrixL().solve(nu);
  const double log_det = 2 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
  return -0.5 * (w.squaredNorm() + log_det + double(nu.size()) * std::log(2 * M_PI));
}

Innovation innovation(const Gaussian& g, const LinearMeasurement& m, const Eigen::VectorXd& z) {
  Innovation in;
  in.nu = m.residual(z, g.x);
  in.S = innovationCovariance(g, m);
  const Eigen::LLT<Eigen::MatrixXd> llt(in.S);
  in.nis = llt.info() == Eigen::Success ? in.nu.dot(llt.solve(in.nu))
                                        : std::numeric_limits<double>::infinity();
  in.log_likelihood = gaussianLogPdf(in.nu, in.S);
  return in;
}

Eigen::MatrixXd kalmanGain(const Gaussian& g, const LinearMeasurement& m,
                           const Eigen::MatrixXd& S) {
  // K = P Hᵀ S⁻¹, solved rather than inverted: Kᵀ = S⁻¹ H P (S and P symmetric).
  return S.llt().solve(m.H * g.P).transpose();
}

Innovation kalmanUpdate(Gaussian& g, const LinearMeasurement& m, const Eigen::VectorXd& z) {
  Innovation in = innovation(g, m, z);
  const Eigen::MatrixXd K = kalmanGain(g, m, in.S);
  g.x += K * in.nu;
  const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(g.x.size(), g.x.size()) - K * m.H;
  g.P = IKH * g.P * IKH.transpose() + K * m.R * K.transpose();
  g.P = 0.5 * (g.P + g.P.transpose());
  return in;
}

}  // namespace pedtrack::track
