#include "pedtrack/track/shape_imm_estimator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pedtrack/track/imm.h"
#include "pedtrack/track/kalman.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::track {
namespace {

Imm makeImm(const ShapeTrackerParams& p, const std::shared_ptr<const ShapeUnicycle>& motion) {
  if (p.models.empty()) throw std::invalid_argument("a shape tracker needs an observation model");
  const std::size_t n = p.models.size();
  Eigen::MatrixXd pi = p.transition;
  if (pi.size() == 0 && n == 1) pi = Eigen::MatrixXd::Identity(1, 1);
  if (std::size_t(pi.rows()) != n || std::size_t(pi.cols()) != n)
    throw std::invalid_argument(std::to_string(n) + " observation models need a " +
                                std::to_string(n) + " x " + std::to_string(n) +
                                " transition matrix");
  return Imm(std::vector<std::shared_ptr<const MotionModel>>(n, motion), pi);
}

// θ → θ + π, v → −v: the same motion. The covariance transforms with J = diag(1, 1, 1, −1, 1, 1).
void flipHeading(Gaussian& g) {
  g.x(2) = wrapAngle(g.x(2) + M_PI);
  g.x(3) = -g.x(3);
  g.P.row(3) *= -1;
  g.P.col(3) *= -1;
}

// What every track of one tracker shares.
struct ImmContext {
  ShapeTrackerParams p;
  std::shared_ptr<const ShapeUnicycle> motion;
  Imm imm;
  explicit ImmContext(const ShapeTrackerParams& params)
      : p(params), motion(std::make_shared<ShapeUnicycle>(p.q_rates)), imm(makeImm(p, motion)) {}
};

class ImmTorsoEstimator : public TorsoEstimator {
 public:
  ImmTorsoEstimator(std::shared_ptr<const ImmContext> ctx, const ShapeCloud& cloud,
                    const Eigen::Vector2d& position, std::mt19937& rng);
  void predict(double dt) override {
    align();
    ctx_->imm.predict(s_, dt);
  }
  Eigen::Vector2d position() const override { return Imm::combine(s_).x.head<2>(); }
  void update(const ShapeCloud& cloud, std::mt19937& rng) override;
  Track row() override;

 private:
  void align();
  std::shared_ptr<const ImmContext> ctx_;
  ImmState s_;
};

ImmTorsoEstimator::ImmTorsoEstimator(std::shared_ptr<const ImmContext> ctx, const ShapeCloud& cloud,
                                     const Eigen::Vector2d& position, std::mt19937& rng)
    : ctx_(std::move(ctx)) {
  const ShapeTrackerParams& p = ctx_->p;
  ShapeFits fits(cloud, {}, p.observation, rng);
  Gaussian g;
  g.x = Eigen::VectorXd::Zero(6);
  const Eigen::Vector2d to_sensor = cloud.origin - position;
  g.x << position.x(), position.y(), std::atan2(to_sensor.y(), to_sensor.x()), 0, p.cog_alpha,
      p.observation.cog_beta;
  // The first model (in the tracker's order) that measures the full shape sets it; else the
  // first that measures a position sets that.
  bool have_position = false;
  for (ShapeModel model : p.models) {
    const auto m = fits.measure(model);
    if (!m) continue;
    const Eigen::MatrixXd& H = m->model.H;
    const Eigen::VectorXd x = H.transpose() * m->z;  // the observed states (H selects them)
    if (m->z.size() == 5) {
      for (int k : {0, 1, 2, 4, 5}) g.x(k) = x(k);
      break;
    }
    if (!have_position) g.x.head<2>() = x.head<2>();
    if (model == ShapeModel::Circle) g.x(4) = g.x(5) = m->z(2);
    have_position = true;
  }
  // Facing direction unknown: a walker seen from behind ends up with v < 0 and is turned round
  // by align(); the shape fixes θ modulo π well.
  const Eigen::VectorXd r = p.observation.r_ellipse;
  g.P = Eigen::MatrixXd::Zero(6, 6);
  g.P(0, 0) = g.P(1, 1) = p.observation.r_cog(0);
  g.P(2, 2) = r(2);
  g.P(3, 3) = p.init_speed_sigma * p.init_speed_sigma;
  g.P(4, 4) = g.P(5, 5) = 0.05 * 0.05;
  s_ = ctx_->imm.init(g);
}

// Every mode's heading on the same branch as the most probable mode's, so mixing and combining
// average nearby angles: a mode facing the other way is the same motion with θ + π and −v.
void ImmTorsoEstimator::align() {
  Eigen::Index best = 0;
  s_.mu.maxCoeff(&best);
  const double ref = wrapAngle(s_.modes[best].x(2));
  for (Gaussian& g : s_.modes) {
    double d = wrapAngle(g.x(2) - ref);
    if (std::abs(d) > M_PI / 2) {
      flipHeading(g);
      d = wrapAngle(g.x(2) - ref);
    }
    g.x(2) = ref + d;
  }
}

void ImmTorsoEstimator::update(const ShapeCloud& cloud, std::mt19937& rng) {
  const ShapeTrackerParams& p = ctx_->p;
  ShapeFits fits(cloud, Imm::combine(s_).x, p.observation, rng);
  Eigen::VectorXd ll(p.models.size());
  for (std::size_t j = 0; j < p.models.size(); ++j) {
    ll(j) = -std::numeric_limits<double>::infinity();
    Gaussian& g = s_.modes[j];
    if (auto m = fits.measure(p.models[j])) ll(j) = kalmanUpdate(g, m->model, m->z).log_likelihood;
    if (p.models[j] == ShapeModel::Cog) {
      // P1 §II-D: the COG model does not estimate the size; it keeps P1's fixed semi-axes.
      g.x(4) = p.cog_alpha;
      g.x(5) = p.observation.cog_beta;
    }
    g.x(4) = std::max(g.x(4), 0.01);
    g.x(5) = std::max(g.x(5), 0.01);
  }
  Imm::updateProbabilities(s_, ll);
  align();
  // The shapes fix θ modulo π only; the motion says which way the person faces. Once the person
  // walks backwards faster than flip_speed, every mode turns round (θ + π, −v: the same motion).
  if (Imm::combine(s_).x(3) < -p.flip_speed)
    for (Gaussian& g : s_.modes) flipHeading(g);
}

Track ImmTorsoEstimator::row() {
  align();
  const Gaussian g = Imm::combine(s_);
  Track r = trackRow(0, g, *ctx_->motion);
  r.yaw = wrapAngle(g.x(2));  // the facing direction, also when standing still
  r.alpha = g.x(4);
  r.beta = g.x(5);
  r.has_shape = true;
  r.model_probs.assign(s_.mu.data(), s_.mu.data() + s_.mu.size());
  return r;
}

}  // namespace

TorsoEstimatorFactory immTorsoEstimators(const ShapeTrackerParams& params) {
  auto ctx = std::make_shared<const ImmContext>(params);
  return [ctx](const ShapeCloud& cloud, const Eigen::Vector2d& position, std::mt19937& rng) {
    return std::make_unique<ImmTorsoEstimator>(ctx, cloud, position, rng);
  };
}

}  // namespace pedtrack::track
