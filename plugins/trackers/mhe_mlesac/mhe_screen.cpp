#include "mhe_mlesac/mhe_screen.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace pedtrack::track::mhe {
namespace {

constexpr double kPenalty = 1e6;  // weight of a squared bound violation (rad², m²)

}  // namespace

MheScreen::MheScreen(const MheProblem& pb, const MheParams& params)
    : p_(params), h_(pb.size()), n_(kStates + 5 * (pb.size() - 1)) {
  // x_0 = z[0:8]; x_k = A_k x_{k−1} + G_k n_k.
  map_.assign(h_, Eigen::MatrixXd::Zero(kStates, n_));
  map_[0].leftCols<kStates>().setIdentity();
  for (int k = 1; k < h_; ++k) {
    const double dt = (*pb.frames)[k].dt;
    Eigen::MatrixXd& m = map_[k];
    m = map_[k - 1];
    m.topRows<3>() += dt * map_[k - 1].middleRows<3>(3);
    m.bottomRows<5>().middleCols<5>(kStates + 5 * (k - 1)) +=
        dt * Eigen::Matrix<double, 5, 5>::Identity();
  }
  for (int k = 0; k < h_; ++k) {
    Eigen::Matrix<double, 5, Eigen::Dynamic> m(5, n_);
    for (int r = 0; r < 5; ++r) m.row(r) = map_[k].row(kShapeStates[r]);
    shape_map_.push_back(std::move(m));
  }
  base_hessian_ = Eigen::MatrixXd::Zero(n_, n_);
  base_hessian_.topLeftCorner<kStates, kStates>() = 2 * pb.arrival_info;
  for (int k = 1; k < h_; ++k)
    for (int j = 0; j < 5; ++j) {
      const int i = kStates + 5 * (k - 1) + j;
      base_hessian_(i, i) = 2 / (params.q(j) * params.horizon);
    }
  z0_ = reduce(pb.prior);
  for (int k = 0; k < h_; ++k) {
    theta_lo_.push_back(pb.prior[k](2) - params.theta_th);
    theta_hi_.push_back(pb.prior[k](2) + params.theta_th);
  }
}

// x_k depends on x_{T−H+1} and n_{T−H+2..k} only: the first kStates + 5k columns of z.
std::vector<State> MheScreen::states(const Eigen::VectorXd& z) const {
  std::vector<State> xs(h_);
  for (int k = 0; k < h_; ++k) {
    const int c = kStates + 5 * k;
    xs[k] = map_[k].leftCols(c) * z.head(c);
  }
  return xs;
}

Eigen::VectorXd MheScreen::reduce(const std::vector<State>& xs) const {
  Eigen::VectorXd z(n_);
  z.head<kStates>() = xs[0];
  for (int k = 1; k < h_; ++k) {
    // dt of frame k from the map: the coefficient of n_k on x_k's vx.
    const double dt = map_[k](3, kStates + 5 * (k - 1));
    z.segment<5>(kStates + 5 * (k - 1)) = systemNoise(xs[k - 1], xs[k], dt);
  }
  return z;
}

// Eq. 5 (motion and arrival exactly as mheCost) plus the bound penalties.
double MheScreen::cost(const MheProblem& pb, const Eigen::VectorXd& z) const {
  const std::vector<State> xs = states(z);
  double J = mheCost(pb, p_, xs).total();
  for (int k = 0; k < h_; ++k) {
    const State& x = xs[k];
    const double v[3] = {std::max({0.0, theta_lo_[k] - x(2), x(2) - theta_hi_[k]}),
                         std::max({0.0, p_.alpha_min - x(6), x(6) - p_.alpha_max}),
                         std::max({0.0, p_.beta_min - x(7), x(7) - p_.beta_max})};
    for (double e : v) J += kPenalty * e * e;
  }
  return J;
}

std::vector<State> MheScreen::minimise(const MheProblem& pb, int iterations,
                                       const std::vector<State>* start) const {
  Eigen::VectorXd z = start ? reduce(*start) : z0_;
  double J = cost(pb, z);
  double lambda = 1e-3;
  Eigen::Matrix<double, 5, 1> g5;
  for (int it = 0; it < iterations; ++it) {
    // Gauss–Newton model of eq. 5 at z: the quadratic terms exactly, the data term and the
    // violated bounds linearised.
    Eigen::MatrixXd H = base_hessian_;
    Eigen::VectorXd grad = base_hessian_ * z;
    grad.head<kStates>() -= 2 * pb.arrival_info * pb.arrival_mean;
    const std::vector<State> xs = states(z);
    for (int k = 0; k < h_; ++k) {
      Eigen::Matrix<double, 5, 5> A = Eigen::Matrix<double, 5, 5>::Zero();
      Eigen::Matrix<double, 5, 1> b = Eigen::Matrix<double, 5, 1>::Zero();
      for (int i : pb.sample[k]) {
        const double s = deviation(xs[k], (*pb.frames)[k].points[i], g5, nullptr);
        A += g5 * g5.transpose();
        b += s * g5;
      }
      A *= 2 * pb.data_weight;
      b *= 2 * pb.data_weight;
      // Bound penalties on θ, α, β (rows 2, 3, 4 of the shape block).
      const double lo[3] = {theta_lo_[k], p_.alpha_min, p_.beta_min};
      const double hi[3] = {theta_hi_[k], p_.alpha_max, p_.beta_max};
      for (int j = 0; j < 3; ++j) {
        const double v = xs[k](kShapeStates[2 + j]);
        const double e = v < lo[j] ? v - lo[j] : v > hi[j] ? v - hi[j] : 0;
        if (e == 0) continue;
        A(2 + j, 2 + j) += 2 * kPenalty;
        b(2 + j) += 2 * kPenalty * e;
      }
      const int c = kStates + 5 * k;  // the columns x_k depends on
      const auto M = shape_map_[k].leftCols(c);
      const Eigen::Matrix<double, 5, Eigen::Dynamic> AM = A * M;
      H.topLeftCorner(c, c).noalias() += M.transpose() * AM;
      grad.head(c).noalias() += M.transpose() * b;
    }
    // Levenberg–Marquardt: damp until the step lowers the cost (a few tries at most).
    bool moved = false;
    for (int tries = 0; tries < 6 && !moved; ++tries) {
      Eigen::MatrixXd D = H;
      D.diagonal() *= 1 + lambda;
      // D is positive definite (eq. 5's quadratic terms, damped): Cholesky without pivoting.
      const Eigen::LLT<Eigen::MatrixXd> llt(D);
      if (llt.info() != Eigen::Success) {
        lambda *= 10;
        continue;
      }
      const Eigen::VectorXd step = llt.solve(-grad);
      const Eigen::VectorXd trial = z + step;
      const double Jt = cost(pb, trial);
      if (std::isfinite(Jt) && Jt < J) {
        z = trial;
        J = Jt;
        lambda = std::max(lambda / 10, 1e-7);
        moved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!moved) break;
  }
  return states(z);
}

}  // namespace pedtrack::track::mhe
