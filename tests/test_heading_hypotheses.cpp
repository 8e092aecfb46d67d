// The heading hypotheses (framework/.../heading_hypotheses.h) against hand-derived values: the
// readings a leg vector allows, the hidden-leg bound, the capped rate variance; and against P3's
// single zoning reading on synthetic walkers: a stepping turn in place (where the zoning's
// smaller turn stalls), a side step and a backward walk (where the motion must not turn the
// estimate round).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "pedtrack/track/heading_hypotheses.h"
#include "pedtrack/track/leg_pose_estimator.h"

using namespace pedtrack::track;
using Catch::Detail::Approx;

namespace {

double angleDiff(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * M_PI));
}

Eigen::Vector2d rotated(double yaw, double u, double v) {
  return {std::cos(yaw) * u - std::sin(yaw) * v, std::sin(yaw) * u + std::cos(yaw) * v};
}

bool hasReading(const std::vector<HeadingReading>& rs, double yaw, bool sideways) {
  for (const HeadingReading& r : rs)
    if (r.sideways == sideways && angleDiff(r.yaw, yaw) < 1e-9) return true;
  return false;
}

// A body at `c` facing `yaw` with its legs at (±L/2, ±W/2) in its frame (u forward, v left):
// the sagittal spread L swings with the gait, the frontal one is the step width.
std::pair<Eigen::Vector2d, Eigen::Vector2d> bodyLegs(const Eigen::Vector2d& c, double yaw, double L,
                                                     double W) {
  const Eigen::Vector2d half = 0.5 * rotated(yaw, L, W);
  return {c + half, c - half};
}

// Feeds the estimator `frames` scans at 10 Hz of legs(t) = (left, right), unlabelled (associate
// decides), and returns the mean heading error against yaw(t) over the scans after `skip`.
template <class Legs, class Yaw>
double meanHeadingError(LegPoseEstimator& est, Legs legs, Yaw yaw, int frames, int skip) {
  const auto [l0, r0] = legs(0.0);
  est.start(0, l0, r0, yaw(0.0));
  double sum = 0;
  int n = 0;
  for (int k = 1; k <= frames; ++k) {
    const double t = 0.1 * k;
    est.predict(t);
    const auto [l, r] = legs(t);
    const std::vector<Eigen::Vector2d> cand{r, l};
    const auto [li, ri] = est.associate(cand);
    est.update({li >= 0, li >= 0 ? cand[std::size_t(li)] : Eigen::Vector2d::Zero()},
               {ri >= 0, ri >= 0 ? cand[std::size_t(ri)] : Eigen::Vector2d::Zero()}, {4, 0});
    if (k > skip) sum += angleDiff(est.yaw(), yaw(t)), ++n;
  }
  return sum / n;
}

LegPoseParams withHypotheses(int count) {
  LegPoseParams p;
  p.heading.count = count;
  return p;
}

}  // namespace

TEST_CASE("a leg vector allows two gait branches, a side step, and their mirror images",
          "[heading]") {
  // d = R(θ)·(L, W): ρ = √(L² + W²), β = θ + atan2(W, L). The branches θ = β − asin(W/ρ) (left
  // leg ahead: θ itself) and β − π + asin(W/ρ) = θ − 2·atan(L/W); the side step d's
  // perpendicular, β − π/2 = θ − atan(L/W); each also + π.
  const double theta = 30 * M_PI / 180, L = 0.25, W = 0.18, sigma_leg = 0.02;
  const std::vector<HeadingReading> rs =
      legHeadingReadings(rotated(theta, L, W), W, sigma_leg, 0.0);
  REQUIRE(rs.size() == 6);
  const double other = theta - 2 * std::atan(L / W), side = theta - std::atan(L / W);
  for (const HeadingReading& r : rs)  // −d's readings (left and right exchanged): mirrored
    CHECK(r.mirrored ==
          (angleDiff(r.yaw, theta + M_PI) < 1e-9 || angleDiff(r.yaw, other + M_PI) < 1e-9 ||
           angleDiff(r.yaw, side + M_PI) < 1e-9));
  for (double flip : {0.0, M_PI}) {
    CHECK(hasReading(rs, std::remainder(theta + flip, 2 * M_PI), false));
    CHECK(hasReading(rs, std::remainder(other + flip, 2 * M_PI), false));
    CHECK(hasReading(rs, std::remainder(side + flip, 2 * M_PI), true));
  }
  // A branch's spread: d's direction, σ_d / ρ, and asin's slope, W σ_d / (ρ L), σ_d = √2 σ_leg.
  const double rho = std::hypot(L, W), sd = std::sqrt(2.0) * sigma_leg;
  CHECK(rs[0].sigma == Approx(std::hypot(sd / rho, W * sd / (rho * L))));
  // One leg partly hidden (occluded_sigma_leg, 0.07 m): σ_d = √(σ_leg² + 0.07²) instead.
  const double sd_occluded = std::hypot(sigma_leg, 0.07);
  CHECK(legHeadingReadings(rotated(theta, L, W), W, sigma_leg, 0.0, 0.07)[0].sigma ==
        Approx(std::hypot(sd_occluded / rho, W * sd_occluded / (rho * L))));
  CHECK(legHeadingReadings(rotated(theta, L, W), W, sigma_leg, 0.0, sigma_leg)[0].sigma ==
        Approx(rs[0].sigma));
  // No reading is sharper than the floor.
  CHECK(legHeadingReadings(rotated(theta, L, W), W, sigma_leg, 0.2)[0].sigma == Approx(0.2));
  // Legs passing each other (L within 2 σ_d): one reading, the perpendicular, and its mirror.
  const std::vector<HeadingReading> passing =
      legHeadingReadings(rotated(theta, 0.02, W), W, sigma_leg, 0.0);
  REQUIRE(passing.size() == 2);
  CHECK(angleDiff(passing[0].yaw, theta + std::atan2(W, 0.02) - M_PI / 2) < 1e-9);
  // Legs closer than half a step width give nothing.
  CHECK(legHeadingReadings(rotated(theta, 0.0, 0.08), W, sigma_leg, 0.0).empty());
}

TEST_CASE("a hidden leg bounds the heading to the ray's perpendicular, either way", "[heading]") {
  const std::vector<HeadingReading> b = hiddenLegHeadingBound({0.0, 0.18}, 1.0, 0.1);
  REQUIRE(b.size() == 2);
  CHECK(angleDiff(b[0].yaw, 0.0) < 1e-9);  // d along +y: perpendicular ± x
  CHECK_FALSE(b[0].mirrored);
  CHECK(angleDiff(b[1].yaw, M_PI) < 1e-9);  // the same with left and right exchanged
  CHECK(b[1].mirrored);
  CHECK(b[0].spread == 1.0);
  // A hypothesis outside the bound loses weight against one inside it; neither moves. Both
  // start at weight 0: 0.2 rad (inside ±0.5 of 0) and 1.2 rad (0.7 outside). Inside, the bound
  // child (log 0.95, times 1 − label_swap for the names kept) absorbs the all-clutter one (log
  // 0.05/2π); outside, the bound child falls by ½(0.7 / 0.1)² = 24.5 nats and the all-clutter
  // explanation is what is left.
  HeadingHypothesesParams p;
  p.stop_turn_prior = p.start_turn_prior = 0;
  const Eigen::Matrix3d P = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
  HeadingHypotheses h(p);
  h.start({{Eigen::Vector3d(0.2, 0, 0), P}, {Eigen::Vector3d(1.2, 0, 0), P}});
  h.update(hiddenLegHeadingBound({0.0, 0.18}, 0.5, 0.1), {0, 0}, 0.1, 0.1, 0);
  REQUIRE(h.all().size() == 2);
  CHECK(h.all()[0].x(0) == Approx(0.2));
  CHECK(h.all()[1].x(0) == Approx(1.2));
  const double clutter = 0.05 / (2 * M_PI), bound = 0.95 * (1 - p.label_swap);
  CHECK(h.all()[1].log_w == Approx(std::log(clutter) - std::log(bound + clutter)).margin(1e-3));
}

TEST_CASE("on a hidden leg's bound the turn rate relaxes with hidden_turn_tau", "[heading]") {
  // A hypothesis turning at 1 rad/s, then one scan (0.1 s) whose reading is a bound: the predict
  // step decays the rate by e^(-0.1/turn_tau), the bound by e^(-0.1/hidden_turn_tau) more (the
  // acceleration likewise). The legs showed no turn ending, so the turn must not run on unseen.
  for (const double tau : {0.0, 0.2}) {
    HeadingHypothesesParams p;
    p.hidden_turn_tau = tau;
    HeadingHypotheses h(p);
    h.start(Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal());
    h.predict(0.1, 0.0, 0.0, false);
    h.update(hiddenLegHeadingBound({0.0, 0.18}, 1.0, 0.1), {0, 0}, 0.1, 0.1, 0);
    const double after_predict = std::exp(-0.1 / p.turn_tau);
    const double bound = tau > 0 ? std::exp(-0.1 / tau) : 1.0;
    INFO("hidden_turn_tau " << tau);
    CHECK(h.best().x(0) == Approx(0.1));  // the heading took the rate over the step, unbounded
    CHECK(h.best().x(1) == Approx(after_predict * bound));
  }
}

TEST_CASE("unseen, the turn rate's variance stays within rate_sigma_max", "[heading]") {
  HeadingHypothesesParams p;
  p.turn_tau = 0;  // P3's constant acceleration, whose variances grow fastest
  p.accel_sigma_max = 5;
  HeadingHypotheses h(p);
  h.start({0, 0, 0}, Eigen::Matrix3d::Identity() * 1e-4);
  for (int k = 0; k < 50; ++k) h.predict(0.1, M_PI * M_PI, 0, false);
  CHECK(h.best().P(1, 1) <= p.rate_sigma_max * p.rate_sigma_max * (1 + 1e-9));
  CHECK(h.best().P(2, 2) <= p.accel_sigma_max * p.accel_sigma_max * (1 + 1e-9));
  CHECK(h.best().P(0, 0) > 1);  // the heading itself is free to become unknown
}

TEST_CASE("a stepping turn in place is followed where the zoning's smaller turn stalls",
          "[heading]") {
  // P3 scenario 2's turn: 180° in 2 s on the spot, the feet stepping (L = 0.22 sin(2π 0.3 t)),
  // after 1 s standing; then 1 s standing facing the new way.
  auto yaw = [](double t) { return M_PI + M_PI / 2 * std::clamp(t - 1.0, 0.0, 2.0); };
  auto legs = [&](double t) {
    const double L = (t > 1 && t < 3) ? 0.22 * std::sin(2 * M_PI * 0.3 * (t - 1)) : 0.0;
    return bodyLegs({2, 0}, yaw(t), L, 0.18);
  };
  LegPoseEstimator zoning(withHypotheses(0)), hypotheses(withHypotheses(8));
  const double e_zoning = meanHeadingError(zoning, legs, yaw, 40, 10);
  const double e_hyp = meanHeadingError(hypotheses, legs, yaw, 40, 10);
  INFO("heading MAE over the turn and after: zoning " << e_zoning * 180 / M_PI
                                                      << " deg, hypotheses " << e_hyp * 180 / M_PI);
  CHECK(e_hyp < 10 * M_PI / 180);
  CHECK(e_hyp < 0.5 * e_zoning);
  CHECK(angleDiff(hypotheses.yaw(), yaw(4.0)) < 10 * M_PI / 180);
}

TEST_CASE("a side step keeps the heading: legs open side by side while moving sideways",
          "[heading]") {
  // Facing +x, stepping left along +y at 0.5 m/s: the legs side by side, opened 0.1 m past
  // the step width. Read as a walk, they would say the person turned ±51°.
  auto yaw = [](double) { return 0.0; };
  auto legs = [](double t) {
    const double open = t > 0.5 ? 0.1 * std::abs(std::sin(M_PI * t)) : 0.0;
    return bodyLegs({2, 0.5 * std::max(0.0, t - 0.5)}, 0.0, 0.0, 0.18 + open);
  };
  LegPoseEstimator est(withHypotheses(8));
  const double e = meanHeadingError(est, legs, yaw, 30, 5);
  INFO("heading MAE " << e * 180 / M_PI << " deg");
  CHECK(e < 8 * M_PI / 180);
}

TEST_CASE("a backward walk does not turn the estimate round", "[heading]") {
  // Facing +x, walking backward (−x) at 0.6 m/s for 2 m, the legs scissoring: walking backward
  // is a mode the person is in (one switch), not evidence per scan for the mirror image.
  auto yaw = [](double) { return 0.0; };
  auto legs = [](double t) {
    const double L = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    return bodyLegs({3 - 0.6 * t, 0}, 0.0, L, 0.18);
  };
  LegPoseEstimator est(withHypotheses(8));
  const double e = meanHeadingError(est, legs, yaw, 33, 3);
  INFO("heading MAE " << e * 180 / M_PI << " deg");
  CHECK(e < 8 * M_PI / 180);
  CHECK(angleDiff(est.yaw(), 0) < 15 * M_PI / 180);
  // The test can tell: a facing check set to give up after 0.5 m turns the estimate round.
  LegPoseParams p = withHypotheses(8);
  p.backward_walk_max = 0.5;
  LegPoseEstimator impatient(p);
  meanHeadingError(impatient, legs, yaw, 33, 3);
  CHECK(angleDiff(impatient.yaw(), M_PI) < 15 * M_PI / 180);
}

TEST_CASE("the motion tells a side step from a turn when the legs cannot", "[heading]") {
  // Legs side by side 0.3 m apart with W₀ 0.18: a side step (heading ⟂ d, here +x), or a
  // walker turned ±53° with a leg ahead. The heading is known to about 30°.
  const double W = 0.18;
  const Eigen::Vector2d d(0, 0.3);  // left − right
  HeadingHypothesesParams p;
  p.stop_turn_prior = p.start_turn_prior = 0;
  auto best_after = [&](const Eigen::Vector2d& velocity) {
    HeadingHypotheses h(p);
    h.start({0, 0, 0}, Eigen::Vector3d(0.27, 1e-4, 1e-4).asDiagonal());
    h.update(legHeadingReadings(d, W, 0.02, 0.05), velocity, 0.05, 0.1, 0);
    return h.best().x(0);
  };
  // Moving sideways (+y) at 0.5 m/s: the side step; the heading stays.
  CHECK(angleDiff(best_after({0, 0.5}), 0) < 5 * M_PI / 180);
  // Standing still a side step is unlikely (still_sideways_prior): one of the turned walkers,
  // drawn towards the prediction (a Kalman update, not the reading itself).
  const double standing = best_after({0, 0});
  CHECK(angleDiff(standing, 0) > 20 * M_PI / 180);
  CHECK(angleDiff(standing, 0) < std::acos(W / 0.3));
}

TEST_CASE("hypotheses switched on mid-track start from the pose filter's heading", "[heading]") {
  // leg_people retunes a person's estimator on confirmation; turning the hypotheses on then
  // must start them from the heading so far, not from nothing.
  auto yaw = [](double) { return M_PI / 2; };
  auto legs = [](double t) {
    return bodyLegs({0, 0.8 * t}, M_PI / 2, 0.25 * std::sin(2 * M_PI * 0.9 * t), 0.18);
  };
  LegPoseEstimator est(withHypotheses(0));
  meanHeadingError(est, legs, yaw, 20, 0);
  const double before = est.yaw();
  est.retune(withHypotheses(8));
  est.predict(2.1);
  CHECK(angleDiff(est.yaw(), before) < 5 * M_PI / 180);
  const auto [l, r] = legs(2.1);
  est.update({true, l}, {true, r}, {4, 0});
  CHECK(angleDiff(est.yaw(), M_PI / 2) < 10 * M_PI / 180);
}

TEST_CASE("reading the legs' names the other way round costs label_swap", "[heading]") {
  // One hypothesis at 0 (names as they are), two readings 0.3 rad either side with the same
  // spread, the one at −0.3 read from −d: both children move halfway (P = σ²), and the
  // renaming one is log((1 − label_swap) / label_swap) behind; it is the swapped one.
  HeadingHypothesesParams p;
  p.stop_turn_prior = p.start_turn_prior = 0;
  HeadingHypotheses h(p);
  h.start({0, 0, 0}, Eigen::Vector3d(0.01, 1e-4, 1e-4).asDiagonal());
  HeadingReading same{0.3, 0.1, false}, renamed{-0.3, 0.1, false};
  renamed.mirrored = true;
  h.update({same, renamed}, {0, 0}, 0.1, 0.1, 0);
  REQUIRE(h.all().size() >= 2);
  CHECK(h.all()[0].x(0) == Approx(0.15));
  CHECK_FALSE(h.all()[0].swapped);
  CHECK(h.all()[1].x(0) == Approx(-0.15));
  CHECK(h.all()[1].swapped);
  CHECK(h.all()[1].log_w == Approx(std::log(p.label_swap / (1 - p.label_swap))));
  // A leg hidden or just seen again: label_swap_hidden instead.
  HeadingHypotheses u(p);
  u.start({0, 0, 0}, Eigen::Vector3d(0.01, 1e-4, 1e-4).asDiagonal());
  u.update({same, renamed}, {0, 0}, 0.1, 0.1, 0, true);
  CHECK(u.all()[1].log_w == Approx(std::log(p.label_swap_hidden / (1 - p.label_swap_hidden))));
}
