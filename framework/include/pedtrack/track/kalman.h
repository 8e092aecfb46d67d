#pragma once
// The (extended) Kalman filter step: a prediction through a MotionModel (linearised at the
// estimate), and a measurement update in Joseph form (stays symmetric positive definite).
#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {

/// x ← f(x), P ← F P Fᵀ + Q.
void kalmanPredict(Gaussian& g, const MotionModel& model, double dt);

/// The predicted measurement's statistics for measurement z.
struct Innovation {
  Eigen::VectorXd nu;     ///< z − H x (angle rows wrapped)
  Eigen::MatrixXd S;      ///< H P Hᵀ + R
  double nis = 0;         ///< νᵀ S⁻¹ ν
  double log_likelihood;  ///< ln N(ν; 0, S)
};

/// S = H P Hᵀ + R of a prediction.
Eigen::MatrixXd innovationCovariance(const Gaussian& g, const LinearMeasurement& m);
Innovation innovation(const Gaussian& g, const LinearMeasurement& m, const Eigen::VectorXd& z);

/// The Kalman gain K = P Hᵀ S⁻¹.
Eigen::MatrixXd kalmanGain(const Gaussian& g, const LinearMeasurement& m, const Eigen::MatrixXd& S);

/// x ← x + K ν, P ← (I − K H) P (I − K H)ᵀ + K R Kᵀ. Returns the innovation used.
Innovation kalmanUpdate(Gaussian& g, const LinearMeasurement& m, const Eigen::VectorXd& z);

/// ln N(ν; 0, S) for a symmetric positive definite S (−∞ otherwise).
double gaussianLogPdf(const Eigen::VectorXd& nu, const Eigen::MatrixXd& S);

}  // namespace pedtrack::track
