#include "mhe_mlesac/mhe_estimator.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>

#include "pedtrack/track/kalman.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {
namespace {

using mhe::State;

constexpr double kAnyMotion = 0.02;  // m/s: slower is no direction at all

struct MheContext {
  MheEstimatorParams p;
  EllipseRandomWalk motion;
  mhe::MheSolver solver;
  std::shared_ptr<MheCounters> counters;
  MheContext(const MheEstimatorParams& params, std::shared_ptr<MheCounters> c)
      : p(params), motion(params.mhe.q), solver(params.mhe, params.solver), counters(std::move(c)) {
    if (!counters) counters = std::make_shared<MheCounters>();
  }
};

class MheEstimator : public TorsoEstimator {
 public:
  MheEstimator(std::shared_ptr<MheContext> ctx, const ShapeCloud& cloud,
               const Eigen::Vector2d& position, std::mt19937& rng);
  void predict(double dt) override;
  Eigen::Vector2d position() const override { return predicted_.head<2>(); }
  void update(const ShapeCloud& cloud, std::mt19937& rng) override;
  void miss() override;
  Track row() override;

 private:
  void push(mhe::HorizonFrame f);
  void kalmanMeasure(const ShapeCloud& cloud, std::mt19937& rng);
  void estimateWindow(std::mt19937& rng);
  std::vector<State> aprioriWindow() const;

  std::shared_ptr<MheContext> ctx_;
  Gaussian kf_;                            // the KF alongside (P0 §III)
  std::vector<mhe::HorizonFrame> frames_;  // the last ≤ H frames
  std::vector<Gaussian> kf_priors_;        // the KF's prior at each of them
  std::vector<State> kf_posts_;            // and its estimate
  std::vector<State> window_;              // the last MHE solution (empty: none yet)
  State estimate_ = State::Zero();         // this frame's estimate
  State predicted_ = State::Zero();        // the estimate moved to the coming frame
  double dt_ = 0.1;
  double facing_ = 0;          // the facing direction last reported
  bool facing_known_ = false;  // the person has walked: facing_ is no longer the initial guess
};

MheEstimator::MheEstimator(std::shared_ptr<MheContext> ctx, const ShapeCloud& cloud,
                           const Eigen::Vector2d& position, std::mt19937& rng)
    : ctx_(std::move(ctx)) {
  const MheEstimatorParams& p = ctx_->p;
  const Eigen::Vector2d to_sensor = cloud.origin - position;
  facing_ = std::atan2(to_sensor.y(), to_sensor.x());  // unknown: assume facing the sensor
  State x = State::Zero();
  x << position.x(), position.y(), facing_ + M_PI / 2, 0, 0, 0,
      0.5 * (p.mhe.alpha_min + p.mhe.alpha_max), 0.5 * (p.mhe.beta_min + p.mhe.beta_max);
  ShapeFits fits(cloud, {}, p.observation, rng);
  if (const auto& e = fits.ellipse(); e && int(cloud.points.size()) >= p.observation.n_e)
    x << e->x, e->y, e->theta + M_PI / 2, 0, 0, 0, e->alpha, e->beta;
  kf_.x = x;
  kf_.P = Eigen::MatrixXd::Zero(8, 8);
  const Eigen::VectorXd& re = p.observation.r_ellipse;
  kf_.P(0, 0) = kf_.P(1, 1) = p.observation.r_cog(0);
  kf_.P(2, 2) = re(2);
  kf_.P(3, 3) = kf_.P(4, 4) = p.init_speed_sigma * p.init_speed_sigma;
  kf_.P(5, 5) = 1;  // turn rate (rad/s)²
  kf_.P(6, 6) = kf_.P(7, 7) = p.init_size_sigma * p.init_size_sigma;
  kf_priors_.push_back(kf_);
  kf_posts_.push_back(x);
  push({dt_, cloud.origin, cloud.points});
  estimate_ = predicted_ = x;
}

void MheEstimator::predict(double dt) {
  dt_ = dt;
  kalmanPredict(kf_, ctx_->motion, dt);
  predicted_ = ctx_->motion.predict(estimate_, dt);
}

void MheEstimator::push(mhe::HorizonFrame f) {
  frames_.push_back(std::move(f));
  if (int(frames_.size()) > ctx_->p.mhe.horizon) {
    frames_.erase(frames_.begin());
    kf_priors_.erase(kf_priors_.begin());
    kf_posts_.erase(kf_posts_.begin());
  }
}

// The KF's measurement: the RANSAC ellipse (P1's constrained fit with P0's bounds) as
// [x, y, θ, α, β] — θ turned to P0's major axis — or its centre, or the cloud's centre of gravity.
void MheEstimator::kalmanMeasure(const ShapeCloud& cloud, std::mt19937& rng) {
  Eigen::VectorXd prior(6);
  prior << kf_.x(0), kf_.x(1), kf_.x(2) - M_PI / 2, 0, kf_.x(6), kf_.x(7);
  ShapeFits fits(cloud, prior, ctx_->p.observation, rng);
  auto m = fits.measure(ShapeModel::Ellipse);
  if (!m) m = fits.measure(ShapeModel::Cog);
  if (!m) return;
  static const int kTo8[6] = {0, 1, 2, -1, 6, 7};  // 6-state index → P0's state
  LinearMeasurement lm;
  lm.H = Eigen::MatrixXd::Zero(m->model.H.rows(), 8);
  for (int c = 0; c < 6; ++c)
    if (kTo8[c] >= 0) lm.H.col(kTo8[c]) = m->model.H.col(c);
  lm.R = m->model.R;
  Eigen::VectorXd z = m->z;
  for (int r = 0; r < lm.H.rows(); ++r)
    if (lm.H(r, 2) != 0) {
      z(r) = nearestModPi(z(r) + M_PI / 2, kf_.x(2));
      lm.angle_rows.push_back(r);
    }
  kalmanUpdate(kf_, lm, z);
}

std::vector<State> MheEstimator::aprioriWindow() const {
  const int h = int(frames_.size());
  std::vector<State> prior;
  if (int(window_.size()) == h) {
    // The last solution moved on by one frame, its last state predicted to the new frame.
    prior.assign(window_.begin() + 1, window_.end());
    prior.push_back(ctx_->motion.predict(window_.back(), frames_.back().dt));
  } else {
    prior = kf_posts_;
  }
  for (int k = 1; k < h; ++k) prior[k](2) = nearestModPi(prior[k](2), prior[k - 1](2));
  return prior;
}

void MheEstimator::estimateWindow(std::mt19937& rng) {
  const MheEstimatorParams& p = ctx_->p;
  mhe::MlesacInput in;
  in.frames = &frames_;
  in.prior = aprioriWindow();
  const Gaussian& arrival = kf_priors_.front();
  in.arrival_mean = arrival.x;
  in.arrival_mean(2) = nearestModPi(in.arrival_mean(2), in.prior[0](2));
  in.arrival_info = arrival.P.inverse();
  const mhe::MlesacResult r = mhe::mheMlesac(in, p.mhe, p.mlesac, ctx_->solver, rng);
  MheCounters& c = *ctx_->counters;
  ++c.windows;
  c.candidates += r.candidates;
  c.solves += r.solved;
  c.failed += r.failed;
  if (!r.ok) {
    ++c.fallbacks;
    window_.clear();
    estimate_ = kf_.x;
    return;
  }
  window_ = r.xs;
  estimate_ = window_.back();
}

void MheEstimator::update(const ShapeCloud& cloud, std::mt19937& rng) {
  kf_priors_.push_back(kf_);
  kalmanMeasure(cloud, rng);
  kf_posts_.push_back(kf_.x);
  push({dt_, cloud.origin, cloud.points});
  if (int(frames_.size()) < ctx_->p.mhe.horizon || ctx_->p.kf_only) {
    estimate_ = kf_.x;  // T < H: the KF (Algorithm 1's preamble)
    return;
  }
  estimateWindow(rng);
}

void MheEstimator::miss() {
  kf_priors_.push_back(kf_);
  kf_posts_.push_back(kf_.x);
  push({dt_, frames_.back().origin, {}});
  estimate_ = predicted_;
  if (int(window_.size()) == ctx_->p.mhe.horizon) {
    window_.erase(window_.begin());
    window_.push_back(estimate_);
  }
}

Track MheEstimator::row() {
  Track r;
  r.x = estimate_(0);
  r.y = estimate_(1);
  r.vx = estimate_(3);
  r.vy = estimate_(4);
  // Facing: the side of the major axis the person walks to; kept while standing. The walking
  // direction is the window's displacement (the last state's velocity follows every frame's few
  // sampled points and would turn a standing person round).
  Eigen::Vector2d walk = estimate_.segment<2>(3);
  if (int(window_.size()) == int(frames_.size()) && frames_.size() > 1) {
    double span = 0;
    for (std::size_t k = 1; k < frames_.size(); ++k) span += frames_[k].dt;
    walk = (window_.back().head<2>() - window_.front().head<2>()) / span;
  }
  // Until the person has walked faster than flip_speed the facing side is a guess (toward the
  // sensor); any motion, however slow, is better evidence than that guess, so it decides.
  const double speed = walk.norm();
  const bool follow = speed > ctx_->p.flip_speed || (!facing_known_ && speed > kAnyMotion);
  facing_known_ = facing_known_ || speed > ctx_->p.flip_speed;
  const double ref = follow ? std::atan2(walk.y(), walk.x()) : facing_;
  facing_ = wrapAngle(nearestModPi(estimate_(2) - M_PI / 2, ref));
  r.yaw = facing_;
  r.alpha = estimate_(6);
  r.beta = estimate_(7);
  r.has_shape = true;
  r.cov_xx = kf_.P(0, 0);
  r.cov_xy = kf_.P(0, 1);
  r.cov_yy = kf_.P(1, 1);
  r.has_cov = true;
  return r;
}

}  // namespace

TorsoEstimatorFactory mheTorsoEstimators(const MheEstimatorParams& params,
                                         std::shared_ptr<MheCounters> counters) {
  auto ctx = std::make_shared<MheContext>(params, std::move(counters));
  return [ctx](const ShapeCloud& cloud, const Eigen::Vector2d& position, std::mt19937& rng) {
    return std::make_unique<MheEstimator>(ctx, cloud, position, rng);
  };
}

}  // namespace pedtrack::track
