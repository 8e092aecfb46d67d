// leg_people where the robot's motion is unknown (Frame::motion_unknown: scan matching found
// nothing to match): a person walking with the robot stands still in the tracking frame, and
// clutter moves in it as the robot drives. A tentative person is then confirmed by their legs'
// scissoring alone (confirm_stride), never by travel; a rigid pair slid and turned by the robot
// never is; a person standing where one is expected (a following robot's zone) is confirmed
// after follow_confirm_time, through a scan that misses them and clutter beside them; a person's
// velocity is not carried through a scan where the motion is unknown (unknown_motion_tau). And
// where the robot turns fast (max_travel_turn_rate) the way a tentative person goes is no
// evidence for their confirmation.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "leg_people/leg_people_tracker.h"
#include "leg_walker.h"

using namespace pedtrack::track;

namespace {

const Eigen::Vector2d kSensor{0, 0};

// Two legs scored 0.6 at `centre`, `separation` apart along the direction `angle`.
std::vector<LegDetection> pair(const Eigen::Vector2d& centre, double separation, double angle) {
  const Eigen::Vector2d u(std::cos(angle), std::sin(angle));
  return {{centre + 0.5 * separation * u, 0.6, kSensor, 0},
          {centre - 0.5 * separation * u, 0.6, kSensor, 1}};
}

bool anyConfirmed(const LegPeopleTracker& tr) {
  for (const PersonState& s : tr.people())
    if (s.confirmed) return true;
  return false;
}

}  // namespace

TEST_CASE("where the motion is unknown a walker keeping pace is confirmed by gait alone",
          "[legs]") {
  // 1.5 m ahead, keeping pace with the robot: no travel in the frame. The legs scissor, their
  // separation swinging 0.15-0.35 m at 0.9 Hz (thigh height, as in leg_tracker's outdoor
  // following recording).
  LegPeopleTracker tr{LegPeopleParams{}};
  double confirmed_at = NAN;
  for (double t = 0; t < 3 && std::isnan(confirmed_at); t += 0.1) {
    const double sep = 0.25 + 0.1 * std::sin(2 * M_PI * 0.9 * t);
    tr.step(t, pair({1.5, 0}, sep, 0), {}, {}, false);
    if (anyConfirmed(tr)) confirmed_at = t;
  }
  REQUIRE(std::isfinite(confirmed_at));
  CHECK(confirmed_at < 1.5);
  // The same walker with the motion known is not: they moved nowhere.
  LegPeopleTracker known{LegPeopleParams{}};
  for (double t = 0; t < 3; t += 0.1)
    known.step(t, pair({1.5, 0}, 0.25 + 0.1 * std::sin(2 * M_PI * 0.9 * t), 0), {}, {}, true);
  CHECK_FALSE(anyConfirmed(known));
}

TEST_CASE("where the motion is unknown a rigid pair slid and turned by the robot is not confirmed",
          "[legs]") {
  // Two poles 0.3 m apart, sliding past at 1 m/s while the robot turns at 30 deg/s: in the frame
  // they travel 3 m and their leg vector turns 90 deg, but the distance between them stays.
  LegPeopleTracker tr{LegPeopleParams{}};
  for (double t = 0; t < 3; t += 0.1) {
    tr.step(t, pair({2.0 - t, 1.0}, 0.3, M_PI / 6 * t), {}, {}, false);
    CHECK_FALSE(anyConfirmed(tr));
  }
}

TEST_CASE("a person standing where one is expected is confirmed after follow_confirm_time",
          "[legs]") {
  // Standing still 1.2 m in front of a following robot, legs 0.2 m apart.
  auto expected = [](double x, double y) { return x > 0.3 && x < 3 && std::abs(y) < 1; };
  LegPeopleParams p;
  LegPeopleTracker tr(p);
  double confirmed_at = NAN;
  for (double t = 0; t < 2 && std::isnan(confirmed_at); t += 0.1) {
    tr.step(t, pair({1.2, 0.1}, 0.2, M_PI / 2), {}, {}, false, expected);
    if (anyConfirmed(tr)) confirmed_at = t;
  }
  REQUIRE(std::isfinite(confirmed_at));
  CHECK(confirmed_at >= p.follow_confirm_time - 1e-9);
  CHECK(confirmed_at < p.follow_confirm_time + 0.25);
  // Outside the zone, or with follow_confirm_time 0, they stay tentative.
  LegPeopleTracker outside(p);
  for (double t = 0; t < 2; t += 0.1)
    outside.step(t, pair({4.0, 0.1}, 0.2, M_PI / 2), {}, {}, false, expected);
  CHECK_FALSE(anyConfirmed(outside));
  p.follow_confirm_time = 0;
  LegPeopleTracker off(p);
  for (double t = 0; t < 2; t += 0.1)
    off.step(t, pair({1.2, 0.1}, 0.2, M_PI / 2), {}, {}, false, expected);
  CHECK_FALSE(anyConfirmed(off));
}

TEST_CASE("a person waiting to be followed is confirmed through a missed scan and clutter beside",
          "[legs]") {
  // As at the start of the outdoor following recording: standing 1.2 m in front of the robot;
  // the fourth scan (t = 0.3 s) sees nothing of them, the fifth only clutter 0.35 m beside their
  // left leg (within the general gate of 0.45 m), then both legs again. Returns when the person
  // is confirmed and how far their estimate strayed from where they stand.
  auto expected = [](double x, double y) { return x > 0.3 && x < 3 && std::abs(y) < 1; };
  auto run = [&](double standing_gate) {
    LegPeopleParams p;
    p.standing_gate = standing_gate;
    LegPeopleTracker tr(p);
    const Eigen::Vector2d at(1.2, 0.1), left(1.2, 0.2),
        clutter = left + Eigen::Vector2d(0.2, 0.287);
    double confirmed_at = NAN, strayed = 0;
    for (int k = 0; k < 20; ++k) {
      const double t = 0.1 * k;
      std::vector<LegDetection> seen = pair(at, 0.2, M_PI / 2);
      if (k == 3) seen.clear();
      if (k == 4) seen = {{clutter, 0.6, kSensor, 0}};
      tr.step(t, seen, {}, {}, false, expected);
      for (const PersonState& s : tr.people()) strayed = std::max(strayed, (s.p - at).norm());
      if (std::isnan(confirmed_at) && anyConfirmed(tr)) confirmed_at = t;
    }
    return std::make_pair(confirmed_at, strayed);
  };
  const auto [confirmed_at, strayed] = run(LegPeopleParams().standing_gate);
  // Formed at the first scan, expected from the second (t = 0.1): 0.5 s later.
  CHECK(confirmed_at == Catch::Detail::Approx(0.6).margin(0.01));
  CHECK(strayed < 0.05);
  // With the general gate the clutter takes their leg, and the wait starts again.
  const auto [late, dragged] = run(0);
  CHECK(late > 0.8);
  CHECK(dragged > 0.1);
}

TEST_CASE("where the motion is unknown a person's velocity decays before the prediction",
          "[legs]") {
  // walkThenStand's walker along +x at 1 m/s, legs scissoring, confirmed with the motion known
  // while still walking (1.4 m); then one scan (0.1 s) sees neither leg. Returns how far their
  // estimate moved in that scan.
  auto advance = [](double tau, bool motion_known) {
    LegPeopleParams p;
    p.unknown_motion_tau = tau;
    LegPeopleTracker tr(p);
    double t = 0;
    const long id = pedtrack::test::walkThenStand(tr, t, 15);
    REQUIRE(id > 0);
    const Eigen::Vector2d before = tr.people().front().p;
    tr.step(t, {}, {}, {}, motion_known);
    return (tr.people().front().p - before).norm();
  };
  // Known motion: the walk goes on (~0.1 m). Unknown, tau 0.1 s: e^-1 of it.
  CHECK(advance(0.1, true) == Catch::Detail::Approx(0.1).margin(0.03));
  CHECK(advance(0.1, false) == Catch::Detail::Approx(0.1 * std::exp(-1.0)).margin(0.02));
  CHECK(advance(0, false) == Catch::Detail::Approx(advance(0.1, true)).margin(0.005));  // off
}

TEST_CASE("where the motion is unknown a lost person is re-identified only where predicted",
          "[legs]") {
  // A walker confirmed on the way (motion known), then unseen for 1.5 s: a new leg pair 0.9 m
  // beside their prediction is them again when the frame is fixed (they may have stepped
  // aside), but not when the frame moves by an unknown amount (clutter streams past there).
  auto run = [](bool known) {
    LegPeopleTracker tr{LegPeopleParams{}};
    double t = 0;
    for (; t < 3; t += 0.1) {
      const double x = -1.5 + t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      tr.step(t, pair({x, 0}, 0.2 + std::abs(lp), 0), {}, {}, true);
    }
    long id = 0;
    for (const PersonState& s : tr.people())
      if (s.confirmed) id = s.id;
    REQUIRE(id > 0);
    for (; t < 4.5; t += 0.1) tr.step(t, {}, {}, {}, known);
    const Eigen::Vector2d predicted = [&] {
      for (const PersonState& s : tr.people())
        if (s.id == id) return s.p;
      return Eigen::Vector2d(NAN, NAN);
    }();
    REQUIRE(predicted.allFinite());
    for (int k = 0; k < 3; ++k, t += 0.1)
      tr.step(t, pair(predicted + Eigen::Vector2d(0, 0.9), 0.25, 0), {}, {}, known);
    for (const PersonState& s : tr.people())
      if (s.id == id && s.seen) return true;
    return false;
  };
  CHECK(run(true));
  CHECK_FALSE(run(false));
}

TEST_CASE("the way a pair goes while the robot turns fast does not confirm them", "[legs]") {
  // A walker's scissoring legs (score 0.5: confirm_travel applies) going 1 m/s along +x for 2 s,
  // the robot turning at `turn` rad/s the first `turning` s. Returns the walker's x when first
  // confirmed (NaN: never).
  auto confirmedAt = [](double turn, double turning) {
    LegPeopleParams p;  // max_travel_turn_rate 15 deg/s, confirm_travel 0.5 m
    LegPeopleTracker tr(p);
    for (int k = 0; k <= 20; ++k) {
      const double t = 0.1 * k;
      const auto [l, r] = pedtrack::test::walkerLegs(t, 0, 1.0);
      std::vector<LegDetection> legs{{l + Eigen::Vector2d(1, 2), 0.5, kSensor, 0},
                                     {r + Eigen::Vector2d(1, 2), 0.5, kSensor, 1}};
      tr.step(t, legs, {}, {}, true, {}, {}, t < turning ? turn : 0.0);
      for (const PersonState& s : tr.people())
        if (s.confirmed) return s.p.x();
    }
    return double(NAN);
  };
  const double straight = confirmedAt(0, 0);
  REQUIRE_FALSE(std::isnan(straight));
  CHECK(straight >= 1.45);  // confirm_travel from where the pair formed (x >= 1)
  CHECK(straight < 1.8);
  // Turning at 20 deg/s throughout: never; for the first second: confirmed only after going
  // confirm_travel since the turn ended (at x ~ 2).
  CHECK(std::isnan(confirmedAt(20 * M_PI / 180, 3)));
  const double after_turn = confirmedAt(20 * M_PI / 180, 1);
  REQUIRE_FALSE(std::isnan(after_turn));
  CHECK(after_turn >= 2.45);
  CHECK(after_turn < 2.7);
  // Slower than the limit: as if driving straight.
  CHECK(confirmedAt(10 * M_PI / 180, 3) == Catch::Detail::Approx(straight));
}
