#pragma once
// Motion models x_{k+1} = f(x_k, Δt) + w, w ~ N(0, Q(x, Δt)), with their Jacobians F = ∂f/∂x
// (the linear ones return their transition matrix, so a Kalman and an extended Kalman step are
// one code path). Every model keeps the position in states 0 and 1.
//   CV  [x, y, vx, vy]          continuous white-noise acceleration (Bar-Shalom et al. 2001, §6.2)
//   CA  [x, y, vx, vy, ax, ay]  continuous Wiener-process acceleration (§6.2.3)
//   CT  [x, y, vx, vy]          coordinated turn with a known rate ω (§11.7.1), CV's noise
//   Unicycle [x, y, θ, v]       P2 eq. 13, Jacobians eq. 15, P = A P Aᵀ + W Q Wᵀ (eq. 14)
//   ShapeUnicycle [x, y, θ, v, α, β]  P1 eq. 1–2: the unicycle with the torso semi-axes, every
//                               state a random walk with additive noise
//   EllipseRandomWalk [x, y, θ, vx, vy, ω, α, β]  P0 eq. 1–2: constant velocity and turn rate,
//                               the velocities and semi-axes random walks driven through G
//   PoseConstantAcceleration [X, Y, θ, Ẋ, Ẏ, θ̇, Ẍ, Ÿ, θ̈]  P3 eq. 4: constant acceleration on
//                               each of X, Y, θ, discrete white-noise acceleration
#include <Eigen/Core>
#include <memory>
#include <string>

namespace pedtrack::track {

class MotionModel {
 public:
  virtual ~MotionModel();
  virtual int dim() const = 0;
  virtual std::string name() const = 0;
  virtual Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const = 0;
  virtual Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const = 0;
  virtual Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const = 0;
  /// The fixed-frame velocity (m/s) a state describes.
  virtual Eigen::Vector2d velocity(const Eigen::VectorXd& x) const;
};

/// Constant velocity; `q` is the acceleration noise's power spectral density (m²/s³).
class ConstantVelocity : public MotionModel {
 public:
  explicit ConstantVelocity(double q) : q_(q) {}
  int dim() const override { return 4; }
  std::string name() const override { return "CV"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;

 private:
  double q_;
};

/// Constant acceleration; `q` is the jerk noise's power spectral density (m²/s⁵).
class ConstantAcceleration : public MotionModel {
 public:
  explicit ConstantAcceleration(double q) : q_(q) {}
  int dim() const override { return 6; }
  std::string name() const override { return "CA"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;

 private:
  double q_;
};

/// Coordinated turn at a known rate ω (rad/s, positive = counter-clockwise); ω = 0 is CV.
class CoordinatedTurn : public MotionModel {
 public:
  CoordinatedTurn(double omega, double q) : omega_(omega), cv_(q) {}
  int dim() const override { return 4; }
  std::string name() const override;
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;
  double omega() const { return omega_; }

 private:
  double omega_;
  ConstantVelocity cv_;
};

/// P2's unicycle: heading θ (rad) and speed v (m/s) random walks with variance rates
/// `q_theta` (rad²/s) and `q_v` (m²/s³): Q = diag(q_θ Δt, q_v Δt), propagated through W.
class Unicycle : public MotionModel {
 public:
  Unicycle(double q_theta, double q_v) : q_theta_(q_theta), q_v_(q_v) {}
  int dim() const override { return 4; }
  std::string name() const override { return "unicycle"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;
  Eigen::Vector2d velocity(const Eigen::VectorXd& x) const override;

 private:
  double q_theta_, q_v_;
};

/// P1 eq. 2: ẋ = v cos θ, ẏ = v sin θ, θ, v, α and β random walks; the noise is additive,
/// Q = diag(rates) Δt with `rates` the six variance rates (units²/s) of [x, y, θ, v, α, β].
class ShapeUnicycle : public MotionModel {
 public:
  /// std::invalid_argument unless `rates` has 6 non-negative entries.
  explicit ShapeUnicycle(Eigen::VectorXd rates);
  int dim() const override { return 6; }
  std::string name() const override { return "shape-unicycle"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;
  Eigen::Vector2d velocity(const Eigen::VectorXd& x) const override;

 private:
  Eigen::VectorXd rates_;
};

/// P0 eq. 2 by Euler: x_k = A x_{k−1} + G n_k with A moving x, y, θ by vx Δt, vy Δt, ω Δt, and
/// G = [0; Δt I₅] putting n = [n_x, n_y, n_ω, n_α, n_β] ~ N(0, diag(q)) (accelerations, and the
/// semi-axes' rates) on vx, vy, ω, α, β: the noise is G diag(q) Gᵀ.
class EllipseRandomWalk : public MotionModel {
 public:
  /// std::invalid_argument unless `q` has 5 positive entries.
  explicit EllipseRandomWalk(Eigen::VectorXd q);
  int dim() const override { return 8; }
  std::string name() const override { return "ellipse-random-walk"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;
  Eigen::Vector2d velocity(const Eigen::VectorXd& x) const override { return x.segment<2>(3); }
  const Eigen::VectorXd& q() const { return q_; }

 private:
  Eigen::VectorXd q_;
};

/// P3 eq. 4: P = [H, Ḣ, Ḧ] with H = [X, Y, θ] and F the constant-acceleration transition per
/// axis. The three axes are independent; each gets a discrete white-noise acceleration of
/// variance σ²_a (P3: 10², 10², π²), Q_axis = σ²_a Γ Γᵀ with Γ = [Δt²/2, Δt, 1]ᵀ (Bar-Shalom et
/// al. 2001, §6.3.3).
class PoseConstantAcceleration : public MotionModel {
 public:
  /// std::invalid_argument unless all three variances are positive.
  PoseConstantAcceleration(double var_ax, double var_ay, double var_atheta);
  int dim() const override { return 9; }
  std::string name() const override { return "pose-CA"; }
  Eigen::VectorXd predict(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& x, double dt) const override;
  Eigen::MatrixXd noise(const Eigen::VectorXd& x, double dt) const override;
  Eigen::Vector2d velocity(const Eigen::VectorXd& x) const override { return x.segment<2>(3); }

 private:
  double var_[3];
};

}  // namespace pedtrack::track
