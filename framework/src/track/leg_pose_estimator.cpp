#include "pedtrack/track/leg_pose_estimator.h"

#include <algorithm>
#include <cmath>

#include "pedtrack/track/kalman.h"

namespace pedtrack::track {
namespace {

constexpr double kMaxCoastSpeed = 2.0;  // m/s
constexpr double kSeenRecently = 0.5;   // s, a leg's last sighting still counts in associate()

// Eq. 6: the point W₀ behind `visible` on the scanner's ray (`visible` itself at the scanner).
Eigen::Vector2d behindOnRay(const Eigen::Vector2d& sensor, const Eigen::Vector2d& visible,
                            double w0) {
  const Eigen::Vector2d sl = visible - sensor;
  const double n = sl.norm();
  return n < 1e-9 ? visible : Eigen::Vector2d(sensor + (w0 / n + 1) * sl);
}

Eigen::Vector2d rotate(double yaw, const Eigen::Vector2d& v) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

LegPoseEstimator::LegPoseEstimator(const LegPoseParams& p)
    : p_(p), model_(p.var_ax, p.var_ay, p.var_atheta), w0_(p.w0_default), headings_(p.heading) {}

namespace {
constexpr int kHeadingRows[3] = {2, 5, 8};  // θ, θ̇, θ̈ in the pose filter's state
}  // namespace

void LegPoseEstimator::takeBestHeading() {
  const HeadingHypotheses::Hypothesis& b = headings_.best();
  for (int i = 0; i < 3; ++i) {
    g_.x(kHeadingRows[i]) = b.x(i);
    // The heading block is independent of the position blocks in P3's model (eq. 4 is per
    // axis, the measurement noise diagonal): the cross terms stay zero.
    for (int r = 0; r < 9; ++r) g_.P(kHeadingRows[i], r) = g_.P(r, kHeadingRows[i]) = 0;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) g_.P(kHeadingRows[i], kHeadingRows[j]) = b.P(i, j);
}

void LegPoseEstimator::start(double t, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             double yaw) {
  const Eigen::Vector2d left_dir = rotate(yaw, {0, 1});
  const bool a_left = (a - b).dot(left_dir) >= 0;
  left_ = a_left ? a : b;
  right_ = a_left ? b : a;
  g_.x = Eigen::VectorXd::Zero(9);
  g_.x.head<2>() = 0.5 * (a + b);
  g_.x(2) = yaw;
  // Position and heading as measured; velocity and acceleration unknown (a walk, a stride).
  g_.P = Eigen::MatrixXd::Zero(9, 9);
  const double sp = p_.sigma_xy, st = p_.sigma_theta;
  g_.P.diagonal() << sp * sp, sp * sp, st * st, 1, 1, 1, 4, 4, 4;
  t_ = t_start_ = t;
  prev_yaw_ = yaw;
  measured_yaw_ = yaw;
  have_measured_yaw_ = true;
  // The starting facing is the caller's knowledge (leg_pose: P3's frontal following).
  facing_walked_ = p_.backward_walk_max;
  body_d_ = rotate(-yaw, left_ - right_);
  if (multiHeading()) startHeadings();
  started_ = true;
  pred_left_ = seen_left_ = left_;
  pred_right_ = seen_right_ = right_;
}

void LegPoseEstimator::predict(double t) {
  const double dt = std::max(0.0, t - t_);
  prev_yaw_ = g_.x(2);
  const bool coasting = hidden_left_ > 0 && hidden_right_ > 0;
  if (coasting) {
    // Coasting (no leg last scan): P3's constant acceleration, driven by σ_a = 10 m/s², would
    // extrapolate a stride's acceleration quadratically; a person unseen keeps at most their
    // speed, bounded by a brisk walk.
    g_.x.tail<3>().setZero();
    const double v = g_.x.segment<2>(3).norm();
    if (v > kMaxCoastSpeed) g_.x.segment<2>(3) *= kMaxCoastSpeed / v;
    if (p_.coast_tau > 0 && dt > 0) g_.x.segment<2>(3) *= std::exp(-dt / p_.coast_tau);
  }
  if (dt > 0) kalmanPredict(g_, model_, dt);
  g_.x(2) = wrapAngle(g_.x(2));
  clampTurnRate();
  if (multiHeading()) {
    headings_.predict(dt, p_.var_atheta, p_.max_turn_rate, coasting);
    takeBestHeading();
    if (dt > 0) kalmanPredict(walk_, walk_model_, dt);
  }
  hidden_left_ += dt;
  hidden_right_ += dt;
  dt_ = dt;
  t_ = t;
  // Usual motion: the gait model gives the sagittal spread, the step width the frontal one.
  // Unusual motion: legs symmetric about the sagittal plane, as far apart as last seen.
  Eigen::Vector2d d = body_d_;
  if (isUsual(zone_)) {
    d.y() = w0_;
    if (gait_.valid) d.x() = gait_.at(t);
  } else {
    d = {0, std::max(body_d_.y(), w0_)};
  }
  const Eigen::Vector2d c = g_.x.head<2>(), half = 0.5 * rotate(g_.x(2), d);
  pred_left_ = c + half;
  pred_right_ = c - half;
}

std::pair<int, int> LegPoseEstimator::associate(const std::vector<Eigen::Vector2d>& cand) const {
  const double gate2 = p_.leg_gate * p_.leg_gate;
  auto dist2 = [&](const Eigen::Vector2d& c, const Eigen::Vector2d& pred,
                   const Eigen::Vector2d& seen, double hidden) {
    const double dp = (c - pred).squaredNorm();
    return hidden < kSeenRecently ? std::min(dp, (c - seen).squaredNorm()) : dp;
  };
  std::pair<int, int> best{-1, -1};
  double best_cost = INFINITY;
  const int n = int(cand.size());
  for (int i = 0; i < n; ++i) {
    const double dl = dist2(cand[i], pred_left_, seen_left_, hidden_left_);
    if (dl > gate2) continue;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const double dr = dist2(cand[j], pred_right_, seen_right_, hidden_right_);
      if (dr > gate2 || dl + dr >= best_cost) continue;
      best_cost = dl + dr;
      best = {i, j};
    }
  }
  if (best.first >= 0) return best;
  for (int i = 0; i < n; ++i) {
    const double dl = dist2(cand[i], pred_left_, seen_left_, hidden_left_);
    const double dr = dist2(cand[i], pred_right_, seen_right_, hidden_right_);
    const double d = std::min(dl, dr);
    if (d > gate2 || d >= best_cost) continue;
    best_cost = d;
    best = dl <= dr ? std::make_pair(i, -1) : std::make_pair(-1, i);
  }
  return best;
}

Eigen::Vector2d LegPoseEstimator::hiddenLeg(const Eigen::Vector2d& sensor,
                                            const Eigen::Vector2d& visible,
                                            const Eigen::Vector2d& predicted, double w0,
                                            double hidden_for) {
  if ((visible - sensor).norm() < 1e-9) return predicted;
  const Eigen::Vector2d ro = behindOnRay(sensor, visible, w0);  // eq. 6
  const double alpha = std::exp(-hidden_for);                   // α = 1 / e^{T_o}
  return alpha * predicted + (1 - alpha) * ro;                  // eq. 7
}

void LegPoseEstimator::update(const LegSeen& left, const LegSeen& right,
                              const Eigen::Vector2d& sensor) {
  legs_swapped_ = false;
  turned_round_ = false;
  occluded_left_ = left.seen && left.occluded;
  occluded_right_ = right.seen && right.occluded;
  if (!left.seen && !right.seen) return;  // coast on the prediction
  bool inferred = false;
  // A leg hidden this scan after being seen, or seen again after a scan or more hidden: its
  // name rests on eq. 6's point or on a place seen scans ago. (Through an occlusion the visible
  // leg keeps its name scan after scan.)
  auto changed = [&](bool seen, double hidden) { return seen == (hidden > 1.5 * dt_); };
  const bool names_uncertain =
      changed(left.seen, hidden_left_) || changed(right.seen, hidden_right_);
  if (left.seen) {
    left_ = seen_left_ = left.p;
    hidden_left_ = 0;
  }
  if (right.seen) {
    right_ = seen_right_ = right.p;
    hidden_right_ = 0;
  }
  if (!right.seen) {
    right_ = p_.occlusion ? hiddenLeg(sensor, left_, pred_right_, w0_, hidden_right_) : pred_right_;
    inferred = true;
  } else if (!left.seen) {
    left_ = p_.occlusion ? hiddenLeg(sensor, right_, pred_left_, w0_, hidden_left_) : pred_left_;
    inferred = true;
  }
  // The hypotheses' leg vector. With a leg hidden only its direction counts (a bound): the
  // scanner's ray through the visible leg, on which eq. 6's point lies W₀ further out. Eq. 7's
  // blend leans on the predicted leg, which follows the predicted heading: read back as an
  // orientation, it would confirm whatever turn the heading was predicted to make.
  const Eigen::Vector2d legs_d = !right.seen ? Eigen::Vector2d(sensor - left_)
                                             : (!left.seen ? Eigen::Vector2d(right_ - sensor)
                                                           : Eigen::Vector2d(left_ - right_));
  const double k = inferred ? p_.inferred_sigma_scale : 1.0;
  bool observable = false;
  double innovation = 0;
  if (multiHeading()) {
    innovation = updateWithHypotheses(legs_d, inferred, nameLegs(left.seen, right.seen, sensor),
                                      names_uncertain, observable);
  } else {
    innovation = updateWithZoning(k, observable);
  }
  updateFromMotion();
  clampTurnRate();
  checkFacing(innovation);
  body_d_ = rotate(-g_.x(2), left_ - right_);
  if (!inferred && observable) {
    learnStepWidth(body_d_.norm());
    if (isUsual(zone_)) recordGait(t_);
  }
}

double LegPoseEstimator::updateWithZoning(double k, bool& observable) {
  const ZoneResult z = zoneOrientation(left_, right_, prev_yaw_, w0_, p_.zoning);
  if (z.swap) swapNames();
  // z = [midpoint, θ_m] (eq. 5); the midpoint alone when the legs give no orientation.
  observable = z.observable;
  const int rows = z.observable ? 3 : 2;
  Eigen::VectorXd meas(rows);
  meas.head<2>() = 0.5 * (left_ + right_);
  LinearMeasurement m;
  m.H = Eigen::MatrixXd::Zero(rows, 9);
  m.H.leftCols(rows).setIdentity();
  const double sp = k * p_.sigma_xy, st = k * p_.sigma_theta;
  m.R = Eigen::MatrixXd::Zero(rows, rows);
  m.R(0, 0) = m.R(1, 1) = sp * sp;
  if (z.observable) {
    // P3: in go-straight and move-sideways "the human orientation estimation keeps constant":
    // the measurement stays the last one a turning zone gave (not the drifting posterior, whose
    // turn rate would otherwise carry the heading on while the person walks straight).
    const bool unchanged = z.yaw == prev_yaw_;
    if (!unchanged || !have_measured_yaw_) measured_yaw_ = z.yaw;
    have_measured_yaw_ = true;
    meas(2) = measured_yaw_;
    m.R(2, 2) = st * st;
    m.angle_rows = {2};
    zone_ = z.zone;
  }
  // Innovation against the prediction (g_.x(2) is still the predicted heading here).
  const double innovation = z.observable ? wrapAngle(meas(2) - g_.x(2)) : 0.0;
  const double gate = p_.orientation_gate;
  if (z.observable && gate > 0) {
    const double s2 = g_.P(2, 2) + m.R(2, 2), nu2 = innovation * innovation;
    if (nu2 > gate * gate * s2) m.R(2, 2) = nu2 / (gate * gate) - g_.P(2, 2);
  }
  kalmanUpdate(g_, m, meas);
  g_.x(2) = wrapAngle(g_.x(2));
  return innovation;
}

void LegPoseEstimator::swapNames() {
  std::swap(left_, right_);
  std::swap(seen_left_, seen_right_);
  std::swap(hidden_left_, hidden_right_);
  legs_swapped_ = true;
}

bool LegPoseEstimator::nameLegs(bool left_seen, bool right_seen, const Eigen::Vector2d& sensor) {
  bool left_is_a;
  if (left_seen && right_seen) {
    left_is_a = (left_ - leg_a_).squaredNorm() + (right_ - leg_b_).squaredNorm() <=
                (left_ - leg_b_).squaredNorm() + (right_ - leg_a_).squaredNorm();
  } else {
    // The visible leg and eq. 6's point W₀ behind it on the scanner's ray (no heading in it):
    // the pair, not the visible leg alone, which mid-swing may be nearer the other's last place.
    const Eigen::Vector2d& v = left_seen ? left_ : right_;
    const Eigen::Vector2d h = behindOnRay(sensor, v, w0_);
    const bool v_is_a = (v - leg_a_).squaredNorm() + (h - leg_b_).squaredNorm() <=
                        (v - leg_b_).squaredNorm() + (h - leg_a_).squaredNorm();
    left_is_a = left_seen == v_is_a;
  }
  if (left_seen) (left_is_a ? leg_a_ : leg_b_) = left_;
  if (right_seen) (left_is_a ? leg_b_ : leg_a_) = right_;
  return left_is_a;
}

double LegPoseEstimator::updateWithHypotheses(const Eigen::Vector2d& legs_d, bool inferred,
                                              bool left_is_a, bool names_uncertain,
                                              bool& observable) {
  const double k = inferred ? p_.inferred_sigma_scale : 1.0;
  // The position: the legs' midpoint (eq. 5's first two rows).
  LinearMeasurement m;
  m.H = Eigen::MatrixXd::Zero(2, 9);
  m.H.leftCols(2).setIdentity();
  const double sp = k * p_.sigma_xy;
  m.R = Eigen::MatrixXd::Identity(2, 2) * sp * sp;
  kalmanUpdate(g_, m, 0.5 * (left_ + right_));
  LinearMeasurement wm;
  wm.H = Eigen::MatrixXd::Identity(2, 4);
  wm.R = m.R;
  kalmanUpdate(walk_, wm, 0.5 * (left_ + right_));
  // With a leg hidden, half of the midpoint is eq. 7's inference, and the walk filter's velocity
  // then shows the inference moving (the blend sliding from the prediction to the ray's point),
  // not the body: no motion evidence on such a scan. It had swung P3 scenario 1's estimate round
  // while the person backed away behind their own leg (over 170 seeds 10.1° -> 8.4°).
  const Eigen::Vector2d walk_v =
      inferred ? Eigen::Vector2d::Zero() : Eigen::Vector2d(walk_.x.segment<2>(2));
  const double walk_v_sigma = std::sqrt(std::max(walk_.P(2, 2), walk_.P(3, 3)));
  // The heading: every hypothesis against every reading the leg vector allows. A hidden leg
  // bounds it (eq. 6's geometry); without occlusion handling the hidden leg is the predicted
  // one, whose vector would only echo the predicted heading: no reading.
  // The leg vector as A − B, the legs by the names the hypotheses know them by.
  const Eigen::Vector2d d_ab = left_is_a ? legs_d : Eigen::Vector2d(-legs_d);
  std::vector<HeadingReading> readings;
  if (!inferred) {
    // A partly hidden leg's circle is less sure of its place (LegSeen::occluded).
    const double occ =
        p_.heading.occluded_sigma_leg > 0 ? p_.heading.occluded_sigma_leg : p_.heading.sigma_leg;
    readings =
        legHeadingReadings(d_ab, w0_, occluded_left_ ? occ : p_.heading.sigma_leg,
                           p_.heading.sigma_floor, occluded_right_ ? occ : p_.heading.sigma_leg);
  } else if (p_.occlusion)
    readings = hiddenLegHeadingBound(d_ab, p_.heading.hidden_spread, p_.heading.sigma_floor);
  observable = !readings.empty();
  const double predicted = g_.x(2);  // the best's prediction
  const bool was_backward = headings_.best().backward;
  headings_.update(readings, walk_v, walk_v_sigma, dt_, p_.max_turn_rate, names_uncertain);
  takeBestHeading();
  if (observable) {
    // The zone (the gait model's switch) from the legs as the association named them, then
    // left is the leg the best hypothesis names left (on its heading's left). A renaming scan
    // then reads as an unusual one (legs whose names disagree with the heading: a turn), so the
    // gait records no sample across it; zoning the renamed legs instead was worse (P3 s1 heading
    // MAE 17.4° against 13.6° over 70 seeds).
    zone_ = zoneOrientation(left_, right_, g_.x(2), w0_, p_.zoning).zone;
    if (headings_.best().swapped == left_is_a) swapNames();
  }
  // The facing check's innovation: the best's own or, when a hypothesis walking the other way
  // (forward or backward) took the lead, the jump from the previous best's prediction to it, if
  // larger. Such a lead change is the facing in doubt as much as a large innovation is: in P3
  // scenario 4's quick turns the lead passed to a backward-walking hypothesis 127° away whose
  // own innovation was 4°, and the walk counted before the turn then held the estimate facing
  // backward for seconds (over 170 seeds scenario 4 15.5° -> 14.2°, the others unchanged).
  // Every lead change counted so turned P3 scenario 1's walker round as they back away (its
  // gait branches trade the lead up to 100° apart): 7.8° -> 71°.
  const double own = headings_.best().innovation;
  const double jump = wrapAngle(g_.x(2) - predicted);
  if (headings_.best().backward != was_backward && std::abs(jump) > std::abs(own)) return jump;
  return own;
}

void LegPoseEstimator::learnStepWidth(double distance) {
  if (w0_learned_) return;
  if (t_ - t_start_ > p_.w0_time && !w0_samples_.empty()) {
    w0_learned_ = true;
    return;
  }
  if (distance > 2 * p_.leg_gate) return;  // not one person's legs
  // The legs' distance, not its frontal part (which depends on the heading being estimated),
  // and a low quantile, not the mean: over a stride |d| is √(W² + L_p²), smallest (= W) as the
  // legs pass each other; a side step or a turn only ever widens it. A person who starts by
  // stepping sideways (P3 scenario 2) or turning (scenario 3) then still learns their W.
  w0_samples_.push_back(distance);
  std::vector<double> v = w0_samples_;
  auto q = v.begin() + std::ptrdiff_t(0.1 * double(v.size() - 1));
  std::nth_element(v.begin(), q, v.end());
  w0_ = *q;
}

void LegPoseEstimator::recordGait(double t) {
  samples_.insert(samples_.begin(), gait::Sample{t, body_d_.x()});
  if (int(samples_.size()) > p_.gait_frames) samples_.resize(std::size_t(p_.gait_frames));
  const gait::Params fit = p_.gait_solver ? p_.gait_solver(samples_, p_.gait, gait_)
                                          : gait::fitVarPro(samples_, p_.gait);
  if (fit.valid) gait_ = fit;
}

void LegPoseEstimator::updateFromMotion() {
  if (p_.motion_heading_sigma <= 0 || multiHeading()) return;  // the hypotheses weigh motion
  const Eigen::Vector2d v = velocity();
  if (v.norm() < p_.motion_heading_speed) return;
  const double heading = std::atan2(v.y(), v.x());
  if (std::abs(wrapAngle(heading - g_.x(2))) > M_PI / 2) return;
  LinearMeasurement m;
  m.H = Eigen::MatrixXd::Zero(1, 9);
  m.H(0, 2) = 1;
  m.R = Eigen::MatrixXd::Constant(1, 1, p_.motion_heading_sigma * p_.motion_heading_sigma);
  m.angle_rows = {0};
  kalmanUpdate(g_, m, Eigen::VectorXd::Constant(1, heading));
  g_.x(2) = wrapAngle(g_.x(2));
}

void LegPoseEstimator::clampTurnRate() {
  if (p_.max_turn_rate > 0) g_.x(5) = std::clamp(g_.x(5), -p_.max_turn_rate, p_.max_turn_rate);
}

void LegPoseEstimator::checkFacing(double innovation) {
  if (p_.backward_walk_max <= 0) return;
  // The chance that this reading was the mirror image: nil up to 45°, 1/2 from 90° (the two
  // perpendiculars of the leg vector are then equally near the prediction). The certainty of
  // the facing, carried as the evidence, shrinks by 1 − 2·slip.
  const double slip = 0.5 * std::clamp((std::abs(innovation) - M_PI / 4) / (M_PI / 4), 0.0, 1.0);
  facing_walked_ *= 1 - 2 * slip;
  const Eigen::Vector2d v = velocity();
  if (v.norm() >= p_.mirror_min_speed && dt_ > 0) {
    const double along = v.x() * std::cos(yaw()) + v.y() * std::sin(yaw());
    facing_walked_ = std::min(p_.backward_walk_max, facing_walked_ + along * dt_);
  }
  if (facing_walked_ < -p_.mirror_margin) {
    turnAround();
    facing_walked_ = -facing_walked_;
    turned_round_ = true;
    legs_swapped_ = true;
  }
}

void LegPoseEstimator::retune(const LegPoseParams& p) {
  const bool had_hypotheses = multiHeading();
  p_ = p;
  model_ = PoseConstantAcceleration(p.var_ax, p.var_ay, p.var_atheta);
  headings_.setParams(p.heading);
  if (started_ && multiHeading() && !had_hypotheses) startHeadings();
}

void LegPoseEstimator::startHeadings() {
  // One hypothesis, the pose filter's heading block; the walk filter from its position and
  // velocity, the velocity's variance as the pose filter has it.
  Eigen::Vector3d x;
  Eigen::Matrix3d P;
  for (int i = 0; i < 3; ++i) {
    x(i) = g_.x(kHeadingRows[i]);
    for (int j = 0; j < 3; ++j) P(i, j) = g_.P(kHeadingRows[i], kHeadingRows[j]);
  }
  headings_.start(x, P);
  leg_a_ = left_;  // A is the left leg now
  leg_b_ = right_;
  walk_.x = Eigen::Vector4d(g_.x(0), g_.x(1), g_.x(3), g_.x(4));
  walk_.P = Eigen::Vector4d(g_.P(0, 0), g_.P(1, 1), g_.P(3, 3), g_.P(4, 4)).asDiagonal();
}

void LegPoseEstimator::setVelocity(const Eigen::Vector2d& v) {
  g_.x.segment<2>(3) = v;
  g_.x.segment<2>(6).setZero();
}

void LegPoseEstimator::turnAround() {
  g_.x(2) = wrapAngle(g_.x(2) + M_PI);
  g_.x(5) = 0;  // the turn rate belonged to the wrong facing
  g_.x(8) = 0;
  if (multiHeading()) headings_.turnAround();
  swapNames();
  std::swap(pred_left_, pred_right_);
  prev_yaw_ = g_.x(2);
  measured_yaw_ = wrapAngle(measured_yaw_ + M_PI);
  body_d_ = rotate(-g_.x(2), left_ - right_);
  samples_.clear();
  gait_ = gait::Params{};
}

}  // namespace pedtrack::track
