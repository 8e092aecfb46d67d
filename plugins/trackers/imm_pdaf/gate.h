#pragma once
// Validation gates (Bar-Shalom et al. 2001, §5.4.2 / Bar-Shalom & Li 1995, §3.3.2): a
// measurement is inside when its NIS is at most γ, the χ²(n) quantile of the gate probability
// P_G; the gate is an ellipsoid of volume c_n γ^{n/2} √|S|.
#include <Eigen/Core>

namespace pedtrack::track {

/// γ with P(χ²(dof) ≤ γ) = p_gate.
double gateThreshold(double p_gate, int dof);
/// Volume of the unit hypersphere in n dimensions (c_1 = 2, c_2 = π, c_3 = 4π/3).
double unitBallVolume(int n);
/// c_n γ^{n/2} √|S|.
double gateVolume(double gamma, const Eigen::MatrixXd& S);

}  // namespace pedtrack::track
