#pragma once
// P0 §III–IV-B: the moving-horizon estimate of one pedestrian's torso ellipse over the last H
// frames ("MHE-Ellipse"). The state is P0's [x, y, θ, vx, vy, ω, α, β] (eq. 1) with α the
// semi-axis ALONG θ (eq. 3) — pedtrack's torso convention is converted at the tracker's output.
// The cost is eq. 5: the system noise of eq. 2 over the horizon (divided by H), the squared
// ellipse deviations s (eq. 3) of a subset of the horizon's points (weight R⁻¹/|Ψ|), and the
// arrival cost from the KF run alongside. Constraints (6)–(10) are α ≥ β, the bounds of α, β and
// θ, and the centre no nearer to the LiDAR than the sampled points' mean range.
//
// Eq. 2 has no noise on x, y, θ (G's first three rows are zero), so the pseudo-inverse of eq. 5's
// first term leaves those rows unpenalised; the rows x_k = x_{k−1} + vx Δt (and y, θ) are
// therefore equality constraints of the problem, as the model says they hold exactly.
#include <Eigen/Core>
#include <vector>

namespace pedtrack::track::mhe {

constexpr int kStates = 8;  ///< [x, y, θ, vx, vy, ω, α, β]
/// The states eq. 3's ellipse deviation s depends on: x, y, θ, α, β.
constexpr int kShapeStates[5] = {0, 1, 2, 6, 7};
using State = Eigen::Matrix<double, 8, 1>;
using Point = Eigen::Vector2d;

/// P0 §VI-A's values are the defaults.
struct MheParams {
  int horizon = 10;      ///< H (frames)
  int subset = 100;      ///< |Ψ|: points per candidate, drawn from the whole horizon
  int candidates = 100;  ///< j_max
  Eigen::Matrix<double, 5, 1> q = (Eigen::Matrix<double, 5, 1>() << 0.1, 0.1, 0.08, 1e-4, 1e-4)
                                      .finished();  ///< Q: variances of n_x, n_y, n_ω, n_α, n_β
  double r = 1e-4;                                  ///< R (scalar)
  double alpha_min = 0.10, alpha_max = 0.20;        ///< eq. 7 (m)
  double beta_min = 0.05, beta_max = 0.10;          ///< eq. 8 (m)
  double theta_th = 0.174533;                       ///< eq. 9 (rad): P0's π/18 to six digits
  double d_th = 0.8;                                ///< inlier threshold on |s| (§IV-C)
};

/// One frame of the horizon: the time since the previous frame, the LiDAR's position and the
/// person's torso points (fixed frame). A frame without points (the person was not associated)
/// keeps the motion model going.
struct HorizonFrame {
  double dt = 0.1;
  Point origin = Point::Zero();
  std::vector<Point> points;
};

/// One MHE-Ellipse problem (one MLESAC candidate): the horizon, which of its points the data
/// term uses, the a priori window (θ⁻ of eq. 9 and the starting point) and the arrival prior.
struct MheProblem {
  const std::vector<HorizonFrame>* frames = nullptr;  ///< frames[0] is T−H+1
  std::vector<std::vector<int>> sample;               ///< per frame, indices into its points
  std::vector<State> prior;                           ///< x⁻_{T−H+1:T}
  State arrival_mean = State::Zero();                 ///< x̄⁻_{T−H+1}
  Eigen::Matrix<double, 8, 8> arrival_info = Eigen::Matrix<double, 8, 8>::Identity();  ///< P⁻⁻¹
  double data_weight = 1;  ///< R⁻¹ / |Ψ|
  int size() const { return int(frames->size()); }
};

/// Eq. 3: s = (u/α)² + (w/β)² − 1, u and w the point's offset along and across θ.
double deviation(const State& x, const Point& p);
/// Eq. 3 for many points against one state: the trigonometry done once.
class Deviation {
 public:
  explicit Deviation(const State& x);
  double operator()(const Point& p) const;

 private:
  double x_, y_, c_, s_, a_, b_;
};
/// s and its gradient with respect to (x, y, θ, α, β), and with `hess` its Hessian.
double deviation(const State& x, const Point& p, Eigen::Matrix<double, 5, 1>& grad,
                 Eigen::Matrix<double, 5, 5>* hess);

/// The noise n_k = G†(x_k − A x_{k−1}) of eq. 2 between consecutive states (Δt = `dt`).
Eigen::Matrix<double, 5, 1> systemNoise(const State& prev, const State& next, double dt);

/// The three terms of eq. 5 for a window of states.
struct MheCost {
  double motion = 0, data = 0, arrival = 0;
  double total() const { return motion + data + arrival; }
};
/// Eq. 5 with the problem's sample as the data set.
MheCost mheCost(const MheProblem& pb, const MheParams& params, const std::vector<State>& xs);

/// How the candidates are compared (§IV-C).
enum class Selection {
  /// P0: eq. 5 evaluated on the inliers Υ (|s| < d_th of every horizon point), their count in
  /// place of |Ψ| — the mean squared deviation of the inliers.
  InlierMean,
  /// MLESAC's likelihood with uniform outliers (Torr & Zisserman 2000, P0 ref. 20): every
  /// horizon point counts min(s², d_th²), normalised by the points' count.
  Truncated,
};
struct Selected {
  double cost = 0;  ///< J of the candidate
  int inliers = 0;  ///< |Υ|
  int points = 0;   ///< all horizon points
};
Selected selectionCost(const MheProblem& pb, const MheParams& params, Selection selection,
                       const std::vector<State>& xs);

/// The constraints (6)–(10) and x_k = A x_{k−1} on x, y, θ: the largest violation (0 when all
/// hold). Eq. 10 applies to frames with sampled points.
double constraintViolation(const MheProblem& pb, const MheParams& params,
                           const std::vector<State>& xs);

/// Eq. 10's r̄_k: the sampled points' mean distance to the LiDAR (0 without samples).
double meanSampleRange(const MheProblem& pb, int k);

}  // namespace pedtrack::track::mhe
