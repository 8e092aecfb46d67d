// The multi-person leg tracker (leg_people's LegPeopleTracker) on synthetic legs: walkers kept
// apart, confirmation (classifier score, travel, scissoring), the static scene, re-identification
// of lost walkers, coasting, merging and the reported heading. One leg object alone holding a
// person up standing: test_leg_one_leg_stand.cpp. P3's pose parts against known
// values: test_leg_pose_parts.cpp; the pose estimator on synthetic walks:
// test_leg_pose_estimator.cpp; legs seen from returns of no circle: test_leg_support.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "leg_people/leg_people_tracker.h"
#include "leg_walker.h"
#include "pedtrack/track/leg_pose_estimator.h"

using namespace pedtrack::track;
using Catch::Detail::Approx;
using pedtrack::test::angleDiff;
using pedtrack::test::walkThenStand;

namespace {

// A tracker that saw a walker along +x at 1 m/s from x = -2, legs scissoring, from `sensor` for
// 2 s (confirmed, `id`; 0 if not), then nothing of them for 1.5 s (until t = 3.5 s). `standing`
// legs are seen in every scan besides.
struct HiddenWalker {
  const Eigen::Vector2d sensor{0, -5};
  LegPeopleTracker tr;
  std::vector<LegDetection> standing;
  long id = 0;
  explicit HiddenWalker(const LegPeopleParams& p, std::vector<LegDetection> also = {})
      : tr(p), standing(std::move(also)) {
    for (int k = 0; k <= 20; ++k) {
      const double t = 0.1 * k, x = -2 + t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      std::vector<LegDetection> legs = standing;
      legs.push_back({{x + lp / 2, 0.09}, 0.9, sensor, -1});
      legs.push_back({{x - lp / 2, -0.09}, 0.9, sensor, -1});
      tr.step(t, legs, {});
    }
    for (const PersonState& s : tr.people())
      if (s.confirmed) id = s.id;
    for (int k = 1; k <= 15; ++k) tr.step(2 + 0.1 * k, standing, {});
  }
  // The walker's k-th scan back (t = 3.6 + 0.1 k): walking on along +y from (0.3, 1.4), seen by
  // one leg only, the other hidden behind it. Returns where the tracker has the walker's id if
  // it saw them this scan.
  std::optional<Eigen::Vector2d> stepBackByOneLeg(int k) {
    const Eigen::Vector2d leg =
        pedtrack::test::walkerLegs(0.1 * k, M_PI / 2, 1.0).second + Eigen::Vector2d(0.3, 1.4);
    std::vector<LegDetection> legs = standing;
    legs.push_back({leg, 0.9, sensor, -1});
    tr.step(3.6 + 0.1 * k, legs, {});
    for (const PersonState& s : tr.people())
      if (s.id == id && s.seen) return s.p;
    return std::nullopt;
  }
};

}  // namespace

TEST_CASE("two people walking past each other keep their tracks", "[legs]") {
  LegPeopleParams p;
  LegPeopleTracker tr(p);
  auto person = [](double x0, double vx, double y, double t, std::vector<LegDetection>& out) {
    const double x = x0 + vx * t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    const double s = vx > 0 ? 1 : -1;
    out.push_back({{x + s * lp / 2, y + 0.09}, 0.9, {0, 0}, -1});
    out.push_back({{x - s * lp / 2, y - 0.09}, 0.9, {0, 0}, -1});
  };
  std::vector<long> ids_a, ids_b;
  for (int k = 0; k < 60; ++k) {
    const double t = 0.1 * k;
    std::vector<LegDetection> legs;
    person(-3, 1.0, 2.0, t, legs);
    person(3, -1.0, 3.0, t, legs);
    tr.step(t, legs, {});
    for (const PersonState& s : tr.people()) {
      if (!s.confirmed) continue;
      (s.p.y() < 2.5 ? ids_a : ids_b).push_back(s.id);
      CHECK(std::abs(s.p.y() - (s.p.y() < 2.5 ? 2.0 : 3.0)) < 0.1);
    }
  }
  REQUIRE(ids_a.size() > 40);
  REQUIRE(ids_b.size() > 40);
  CHECK(std::count(ids_a.begin(), ids_a.end(), ids_a.front()) == long(ids_a.size()));
  CHECK(std::count(ids_b.begin(), ids_b.end(), ids_b.front()) == long(ids_b.size()));
  CHECK(ids_a.front() != ids_b.front());
  // A static pole-like detection never becomes a confirmed person.
  LegPeopleTracker poles(p);
  for (int k = 0; k < 50; ++k) {
    std::vector<LegDetection> legs{{{1, 1}, 0.9, {0, 0}, -1}, {{1.3, 1}, 0.9, {0, 0}, -1}};
    poles.step(0.1 * k, legs, {});
    for (const PersonState& s : poles.people()) CHECK_FALSE(s.confirmed);
  }
}

TEST_CASE("legs the classifier scores low are confirmed only after moving_confirm_travel",
          "[legs]") {
  LegPeopleParams p;  // leg_score 0.25, moving_leg_score 0.05, moving_confirm_travel 0.7 m
  LegPeopleTracker tr(p);
  double first_confirmed_x = NAN, started_x = NAN;
  for (int k = 0; k < 50; ++k) {
    const double t = 0.1 * k, x = -2 + 1.0 * t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    std::vector<LegDetection> legs{{{x + lp / 2, 0.09}, 0.1, {0, 0}, -1},
                                   {{x - lp / 2, -0.09}, 0.1, {0, 0}, -1},
                                   // a static pair scored as low never becomes a person
                                   {{2, 2}, 0.1, {0, 0}, -1},
                                   {{2.25, 2}, 0.1, {0, 0}, -1}};
    tr.step(t, legs, {});
    for (const PersonState& s : tr.people()) {
      if (s.p.y() > 1) CHECK_FALSE(s.confirmed);
      if (s.p.y() < 1 && std::isnan(started_x)) started_x = s.p.x();
      if (s.confirmed && std::isnan(first_confirmed_x)) first_confirmed_x = s.p.x();
    }
  }
  REQUIRE_FALSE(std::isnan(first_confirmed_x));
  // Started once the legs' filters had picked up the walking speed (a few scans in), confirmed
  // 0.7 m (not confirm_travel's 0.5 m) later, at the first scan past it (0.1 m a scan).
  REQUIRE_FALSE(std::isnan(started_x));
  CHECK(first_confirmed_x - started_x >= 0.7);
  CHECK(first_confirmed_x - started_x < 0.85);
}

TEST_CASE("legs the classifier is sure of are confirmed after sure_confirm_travel", "[legs]") {
  // A person shuffling at 0.3 m/s, legs scissoring; the distance walked from the pair's start
  // when they are first confirmed.
  auto confirmed_after = [](double score, bool scored = true) {
    LegPeopleParams p;  // confirm_travel 0.5 m; sure_leg_score 0.7, sure_confirm_travel 0.25 m
    LegPeopleTracker tr(p);
    double started_x = NAN;
    for (int k = 0; k < 60; ++k) {
      const double t = 0.1 * k, x = -1 + 0.3 * t, lp = 0.2 * std::sin(2 * M_PI * 0.9 * t);
      std::vector<LegDetection> legs{{{x + lp / 2, 0.09}, score, {0, 0}, -1, scored},
                                     {{x - lp / 2, -0.09}, score, {0, 0}, -1, scored}};
      tr.step(t, legs, {});
      for (const PersonState& s : tr.people()) {
        if (std::isnan(started_x)) started_x = s.p.x();
        if (s.confirmed) return s.p.x() - started_x;
      }
    }
    return double(INFINITY);
  };
  const double sure = confirmed_after(0.9), likely = confirmed_after(0.5);
  CHECK(sure >= 0.25);
  CHECK(sure < 0.4);
  CHECK(likely >= 0.5);
  CHECK(likely < 0.65);
  // No classifier ran: every leg scores 1, which says nothing; confirm_travel applies.
  CHECK(confirmed_after(1.0, false) >= 0.5);
}

TEST_CASE("a pair that slides along without scissoring is not confirmed (confirm_stride)",
          "[legs]") {
  // Two leg-like objects 0.18 m apart gliding at 1 m/s for 3 s, as a wall segment does when the
  // robot's own motion is mis-estimated; a walker at the same speed swings its legs 0.25 m.
  auto run = [](double confirm_stride, double swing) {
    LegPeopleParams p;
    p.confirm_stride = confirm_stride;
    LegPeopleTracker tr(p);
    bool confirmed = false;
    for (int k = 0; k < 30; ++k) {
      const double t = 0.1 * k, x = -1.5 + 1.0 * t;
      const double lp = swing * std::sin(2 * M_PI * 0.9 * t);
      std::vector<LegDetection> legs{{{x + lp / 2, 0.09}, 0.9, {0, 0}, -1},
                                     {{x - lp / 2, -0.09}, 0.9, {0, 0}, -1}};
      tr.step(t, legs, {});
      for (const PersonState& s : tr.people()) confirmed = confirmed || s.confirmed;
    }
    return confirmed;
  };
  CHECK_FALSE(run(0.1, 0.0));  // rigid glide: never a person
  CHECK(run(0.0, 0.0));        // the rule off: confirmed by travel alone (so the rule decides)
  CHECK(run(0.1, 0.25));       // a walker's scissoring legs: confirmed
}

TEST_CASE("a passing person does not take a static door jamb as their hidden leg", "[legs]") {
  LegPeopleParams p;
  LegPeopleTracker tr(p);
  const Eigen::Vector2d jamb(0.0, 0.3);
  auto is_static = [&](double x, double y) { return (Eigen::Vector2d(x, y) - jamb).norm() < 0.1; };
  for (int k = 0; k < 70; ++k) {
    const double t = 0.1 * k, x = -3 + 1.0 * t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    std::vector<LegDetection> legs{{jamb, 0.9, {0, -5}, -1}};
    legs.push_back({{x - lp / 2, -0.09}, 0.9, {0, -5}, -1});
    // Near the jamb the leg on its side is hidden behind the other one for over a second, long
    // enough for its track to be dropped.
    if (std::abs(x) > 0.6) legs.push_back({{x + lp / 2, 0.09}, 0.9, {0, -5}, -1});
    tr.step(t, legs, is_static);
  }
  // The walker is 4 m past the jamb: no person may be left standing on it.
  for (const PersonState& s : tr.people()) CHECK((s.p - jamb).norm() > 0.5);
}

TEST_CASE("a confirmed person hidden for two seconds is re-acquired by one leg", "[legs]") {
  // The leg that comes back scores `score`: a far leg's few points score low, and where a
  // confirmed person's leg is predicted moving_leg_score (0.05) is enough, though a lone still
  // object needs leg_score (0.25).
  const double score = GENERATE(0.9, 0.06);
  CAPTURE(score);
  LegPeopleParams p;  // max_coast 3 s; gate leg_gate + 0.5 m/s unseen, at most + 0.6 m
  LegPeopleTracker tr(p);
  double t = 0;
  const long id = walkThenStand(tr, t, 40);
  REQUIRE(id > 0);
  // Hidden for 2 s by someone passing in front, meanwhile stepping 0.55 m aside, then seen by
  // one leg only (the other behind it): more than leg_gate from where the track was left.
  for (int k = 0; k < 20; ++k, t += 0.1) tr.step(t, {}, {});
  bool back = false;
  for (int k = 0; k < 10; ++k, t += 0.1) {
    tr.step(t, {{{-0.5, 0.09 + 0.55}, score, {0, -5}, -1}}, {});
    for (const PersonState& s : tr.people()) back |= s.id == id && s.seen;
  }
  CHECK(back);
}

TEST_CASE("a person lost longer than max_coast takes back only a leg-like object", "[legs]") {
  // Walks 8 s (confirmed, kept lost up to ~7 s), stops, is hidden 4 s (beyond max_coast, 3 s);
  // then a still object appears where their leg was. Scored 0.9 it is a leg and theirs; scored
  // 0.06 (moving_leg_score would do within max_coast) it is more likely a chair put there.
  auto back = [](double score) {
    LegPeopleTracker tr(LegPeopleParams{});
    long id = 0;
    double t = 0, x = -4;
    for (; t < 8; t += 0.1) {
      x = std::min(1.0, -4 + 0.8 * t);
      const double lp = x < 1.0 ? 0.25 * std::sin(2 * M_PI * 0.9 * t) : 0.0;
      tr.step(t, {{{x + lp / 2, 0.09}, 0.9, {0, -5}, -1}, {{x - lp / 2, -0.09}, 0.9, {0, -5}, -1}},
              {});
    }
    for (const PersonState& s : tr.people())
      if (s.confirmed) id = s.id;
    REQUIRE(id > 0);
    for (const double until = t + 4; t < until; t += 0.1) tr.step(t, {}, {});
    bool seen = false;
    for (int k = 0; k < 5; ++k, t += 0.1) {
      tr.step(t, {{{1.0, 0.09}, score, {0, -5}, -1}}, {});
      for (const PersonState& s : tr.people()) seen |= s.id == id && s.seen;
    }
    return seen;
  };
  CHECK(back(0.9));
  CHECK_FALSE(back(0.06));
}

TEST_CASE("with neither leg seen the velocity decays with coast_tau", "[legs]") {
  // Walk along +x at 1 m/s for 2 s, then no leg for 1 s (ten scans): each prediction scales
  // the velocity by exp(-dt / tau), so after ten 0.1 s scans it is exp(-2) of what it was and
  // the person moved v0 * 0.1 * sum_k exp(-0.2 k), k = 1..10, = 0.3905 v0 (1.0 v0 held).
  auto run = [](double tau) {
    LegPoseParams p;
    p.coast_tau = tau;
    LegPoseEstimator est(p);
    const Eigen::Vector2d sensor(0, -3);
    auto legs = [](double t) {
      const double lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      return std::make_pair(Eigen::Vector2d(t + lp / 2, 0.09), Eigen::Vector2d(t - lp / 2, -0.09));
    };
    est.start(0, legs(0).first, legs(0).second, 0);
    for (int k = 1; k <= 20; ++k) {
      est.predict(0.1 * k);
      est.update({true, legs(0.1 * k).first}, {true, legs(0.1 * k).second}, sensor);
    }
    est.predict(2.1);
    est.update({}, {}, sensor);  // the first scan without legs: predicted as usual
    const Eigen::Vector2d v0 = est.velocity(), x0(est.x(), est.y());
    for (int k = 1; k <= 10; ++k) {
      est.predict(2.1 + 0.1 * k);
      est.update({}, {}, sensor);
    }
    return std::make_tuple(v0.norm(), est.velocity().norm(),
                           (Eigen::Vector2d(est.x(), est.y()) - x0).norm());
  };
  const auto [v0, v1, moved] = run(0.5);
  REQUIRE(v0 > 0.5);
  CHECK(v1 / v0 == Approx(std::exp(-2.0)).epsilon(1e-6));
  CHECK(moved == Approx(0.3905 * v0).epsilon(0.01));
  const auto [w0, w1, held] = run(0);
  CHECK(w1 == Approx(w0).epsilon(1e-9));
  CHECK(held == Approx(w0).epsilon(1e-6));
}

TEST_CASE("a confirmed walker lost behind others keeps their id when their legs reappear nearby",
          "[legs]") {
  // Walks along +x for 2 s (confirmed), vanishes for 1.5 s behind people passing in front,
  // meanwhile turns left, and reappears walking along +y 1.3 m from where the track expects
  // them: beyond the one-leg re-acquisition gate (leg_gate + 0.6 m), inside re-identification's
  // (leg_gate + 1 m/s * 1.5 s).
  auto run = [](double reidentify_speed) {
    LegPeopleParams p;
    p.reidentify_speed = reidentify_speed;
    HiddenWalker w(p);
    long after = 0;
    for (int k = 0; k < 3; ++k) {
      const double t = 3.6 + 0.1 * k, y = 1.3 + 0.1 * k, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      w.tr.step(t,
                {{{0.3 - 0.09, y + lp / 2}, 0.9, w.sensor, -1},
                 {{0.3 + 0.09, y - lp / 2}, 0.9, w.sensor, -1}},
                {});
    }
    for (const PersonState& s : w.tr.people())
      if (s.confirmed && s.seen) after = s.id;
    return std::make_pair(w.id, after);
  };
  const auto [before, after] = run(1.0);
  REQUIRE(before > 0);
  CHECK(after == before);
  const auto [before_off, after_off] = run(0);  // off: a new, not yet confirmed person
  REQUIRE(before_off > 0);
  CHECK(after_off == 0);
}

TEST_CASE(
    "a confirmed walker back from behind others by one leg keeps their id "
    "(reidentify_leg_scans)",
    "[legs]") {
  // Walks along +x at 1 m/s for 2 s (confirmed), vanishes for 1.5 s (their leg objects are
  // dropped after object_max_coast, 0.5 s), meanwhile turns left, and walks on along +y from
  // (0.3, 1.4) with one leg seen, the other hidden behind it. That leg is 1.3 m from where
  // the track expects their legs (the coasting velocity decays: it stops ~0.5 m on), beyond the
  // one-leg re-acquisition gate (leg_gate + 0.6 m), and 1.4 m from where they were predicted,
  // inside re-identification's radius (leg_gate + 1 m/s * 1.6 s). A lone leg never forms a pair:
  // without reidentify_leg_scans the person stays lost.
  auto run = [](int scans) {
    LegPeopleParams p;
    p.reidentify_leg_scans = scans;
    HiddenWalker w(p);
    int first_back = -1;
    Eigen::Vector2d at;
    for (int k = 0; k < 10; ++k)
      if (const auto p_seen = w.stepBackByOneLeg(k); p_seen && first_back < 0)
        first_back = k, at = *p_seen;
    return std::make_tuple(w.id, first_back, at);
  };
  const auto [before, first_back, at] = run(3);
  REQUIRE(before > 0);
  // From the leg's third scan on (reidentify_leg_scans), at the walker.
  CHECK(first_back >= 2);
  CHECK(first_back <= 6);
  CHECK((at - Eigen::Vector2d(0.3, 1.4 + 0.1 * first_back)).norm() < 0.3);
  const auto [before_off, back_off, at_off] = run(0);
  REQUIRE(before_off > 0);
  CHECK(back_off == -1);
}

TEST_CASE("a lone leg beside a leg someone holds does not re-identify a lost person", "[legs]") {
  // The walker and the re-appearing leg of the test above. A person standing at (0.9, 1.8) from
  // the start (a pair 0.2 m apart, tentative: they never walk) holds two legs 0.41-0.65 m from
  // that leg, within pair_distance: the lone leg is most likely that person's other leg, not
  // the lost walker's, who stays lost. Without the standing person the walker takes it back.
  auto run = [](bool bystander) {
    const Eigen::Vector2d sensor{0, -5};
    std::vector<LegDetection> standing;
    if (bystander) standing = {{{0.8, 1.8}, 0.9, sensor, -1}, {{1.0, 1.8}, 0.9, sensor, -1}};
    HiddenWalker w(LegPeopleParams{}, standing);
    bool back = false;
    for (int k = 0; k < 10; ++k) back = w.stepBackByOneLeg(k).has_value() || back;
    return std::make_pair(w.id, back);
  };
  const auto [id, back] = run(true);
  REQUIRE(id > 0);
  CHECK_FALSE(back);
  const auto [id_alone, back_alone] = run(false);
  REQUIRE(id_alone > 0);
  CHECK(back_alone);
}

TEST_CASE("with init_speed 0 a still lone leg re-identifies a lost person at a finite place",
          "[legs]") {
  // A leg standing still has no direction of motion to face: the person keeps their facing
  // (dividing by the leg's zero speed put the hidden leg, and so the person, at NaN).
  LegPeopleParams p;
  p.init_speed = 0;
  HiddenWalker w(p);
  REQUIRE(w.id > 0);
  bool back = false;
  for (int k = 0; k < 5; ++k) {
    w.tr.step(3.6 + 0.1 * k, {{{0.3, 1.4}, 0.9, w.sensor, -1}}, {});
    for (const PersonState& s : w.tr.people())
      if (s.id == w.id && s.seen) {
        back = true;
        CHECK(std::isfinite(s.p.x()));
        CHECK(std::isfinite(s.p.y()));
        CHECK(std::isfinite(s.yaw));
      }
  }
  CHECK(back);
}

TEST_CASE("a confirmed person is kept lost for as long as they were tracked (max_coast_confirmed)",
          "[legs]") {
  // Walks along +x at 0.8 m/s for `walk` s, is hidden for 6 s (beyond max_coast, 3 s), and
  // reappears 0.5 m on from where they vanished. Tracked for ~9 s they are still kept and take
  // the new pair back; tracked for ~1 s they were deleted, and the pair is a new person.
  auto run = [](double walk) {
    LegPeopleTracker tr(LegPeopleParams{});  // max_coast 3 s, max_coast_confirmed 20 s
    const Eigen::Vector2d sensor(0, -5);
    long before = 0, after = 0;
    double x = -4, t = 0;
    auto legs = [&](double t, double x) {
      const double lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      return std::vector<LegDetection>{{{x + lp / 2, 0.09}, 0.9, sensor, -1},
                                       {{x - lp / 2, -0.09}, 0.9, sensor, -1}};
    };
    for (; t <= walk; t += 0.1, x += 0.08) tr.step(t, legs(t, x), {});
    for (const PersonState& s : tr.people())
      if (s.confirmed) before = s.id;
    const double hidden_until = t + 6;
    for (; t < hidden_until; t += 0.1) tr.step(t, {}, {});
    x += 0.5;
    for (int k = 0; k < 3; ++k, t += 0.1, x += 0.08) tr.step(t, legs(t, x), {});
    for (const PersonState& s : tr.people())
      if (s.confirmed && s.seen) after = s.id;
    return std::make_pair(before, after);
  };
  const auto [before, after] = run(10);
  REQUIRE(before > 0);
  CHECK(after == before);
  const auto [before_short, after_short] = run(1.5);
  REQUIRE(before_short > 0);
  CHECK(after_short == 0);
}

TEST_CASE("a confirmed walker still holding coasting legs takes back a new pair formed nearby",
          "[legs]") {
  // Walks along +x for 2 s (confirmed), is hidden for 0.3 s, and reappears slowed down and
  // 0.7 m to the side of their path: beyond every leg gate (the nearer new leg is 0.52 m from
  // the predicted one, the gate 0.45 m), so their old leg objects coast on unassociated (they
  // live object_max_coast = 0.5 s) while the new legs pair up. The confirmed person must take
  // the new pair (within leg_gate + 1 m/s * 0.4 s = 0.8 m of where they were predicted or last
  // seen), not leave it to start a second, unconfirmed person beside their coasting track.
  LegPeopleTracker tr{LegPeopleParams{}};
  const Eigen::Vector2d sensor(0, -5);
  long before = 0;
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.1 * k, x = -2 + t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    tr.step(t, {{{x + lp / 2, 0.09}, 0.9, sensor, -1}, {{x - lp / 2, -0.09}, 0.9, sensor, -1}}, {});
  }
  for (const PersonState& s : tr.people())
    if (s.confirmed) before = s.id;
  REQUIRE(before > 0);
  for (double t : {2.1, 2.2, 2.3}) tr.step(t, {}, {});
  tr.step(2.4, {{{0.3, 0.79}, 0.9, sensor, -1}, {{0.3, 0.61}, 0.9, sensor, -1}}, {});
  std::vector<long> seen;
  for (const PersonState& s : tr.people())
    if (s.seen) seen.push_back(s.id);
  CHECK(seen == std::vector<long>{before});
  for (const PersonState& s : tr.people())
    if (s.id == before) CHECK(s.p.y() == Approx(0.7).margin(0.02));
}

TEST_CASE("a walker seen twice by scanners merged out of step is one person (merge_distance)",
          "[legs]") {
  // Each leg is detected twice, 0.15 m apart along the walk (the second scanner's scan taken
  // 0.15 s later): two leg pairs that each look like a walker.
  auto run = [](double merge_distance) {
    LegPeopleParams p;
    p.merge_distance = merge_distance;
    LegPeopleTracker tr(p);
    std::size_t most = 0, confirmed = 0;
    for (int k = 0; k < 40; ++k) {
      const double t = 0.1 * k, x = -2 + t, lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
      std::vector<LegDetection> legs;
      for (const double dx : {0.0, 0.15}) {
        legs.push_back({{x + dx + lp / 2, 0.09}, 0.9, {0, -5}, -1});
        legs.push_back({{x + dx - lp / 2, -0.09}, 0.9, {0, -5}, -1});
      }
      tr.step(t, legs, {});
      std::size_t n = 0;
      for (const PersonState& s : tr.people()) n += s.confirmed;
      most = std::max(most, n);
      confirmed = n;
    }
    return std::make_pair(most, confirmed);
  };
  const auto [most, last] = run(0.3);
  CHECK(most == 1);
  CHECK(last == 1);
  CHECK(run(0).first == 2);  // off: the walker is reported twice
}

TEST_CASE("the reported heading is the direction of motion, held while standing", "[legs]") {
  // Walks towards 30° at 1 m/s for 4 s, then stops dead (the filter's velocity overshoots
  // backwards: the way moved does not) and stands still for 2 s.
  auto run = [](double report_heading_speed) {
    LegPeopleParams p;
    p.report_heading_speed = report_heading_speed;
    LegPeopleTracker tr(p);
    const Eigen::Vector2d sensor(0, -4);
    std::vector<double> yaws;
    for (int k = 0; k <= 60; ++k) {
      const double t = 0.1 * k;
      const auto [l, r] = pedtrack::test::walkerLegs(std::min(t, 4.0), M_PI / 6, 1.0);
      tr.step(t, {{l, 0.9, sensor, -1}, {r, 0.9, sensor, -1}}, {});
      for (const PersonState& s : tr.people())
        if (s.confirmed) yaws.push_back(s.yaw);
    }
    return yaws;
  };
  const std::vector<double> yaws = run(0.3), estimator = run(0);
  REQUIRE(yaws.size() > 40);
  REQUIRE(yaws.size() == estimator.size());
  double most_off = 0, differs = 0;
  for (std::size_t k = 0; k < yaws.size(); ++k) {
    most_off = std::max(most_off, angleDiff(yaws[k], M_PI / 6));
    differs = std::max(differs, angleDiff(yaws[k], estimator[k]));
  }
  CHECK(most_off < 0.2);                                         // walking, stopping and standing
  CHECK(angleDiff(yaws.back(), yaws[yaws.size() - 15]) < 1e-9);  // held while standing
  CHECK(differs > 1e-6);  // 0: the pose estimator's orientation, filtered apart
}

TEST_CASE("a re-identified person standing with jittering legs keeps the heading they walked",
          "[legs]") {
  // Walks towards 30° for 4 s, is hidden for 1 s, and reappears 1.2 m to their left (beyond the
  // one-leg gate: a new pair, re-identified), standing, legs jittering 12 cm across each scan.
  // The new pose's first scans settle by a few cm: no way walked, so the heading is held.
  LegPeopleTracker tr(LegPeopleParams{});
  const Eigen::Vector2d sensor(0, -4), across(-0.5, std::sqrt(3) / 2);
  long id = 0;
  double t = 0;
  for (; t <= 4.0; t += 0.1) {
    const auto [l, r] = pedtrack::test::walkerLegs(t, M_PI / 6, 1.0);
    tr.step(t, {{l, 0.9, sensor, -1}, {r, 0.9, sensor, -1}}, {});
  }
  for (const PersonState& s : tr.people())
    if (s.confirmed) id = s.id;
  REQUIRE(id > 0);
  for (const double end = t + 1.0; t < end; t += 0.1) tr.step(t, {}, {});
  const auto [l, r] = pedtrack::test::walkerLegs(4.0, M_PI / 6, 1.0);
  double most_off = 0;
  int seen = 0;
  for (int k = 0; k < 20; ++k, t += 0.1) {
    const Eigen::Vector2d at = (1.2 + (k % 2 ? 0.12 : 0.0)) * across;
    tr.step(t, {{l + at, 0.9, sensor, -1}, {r + at, 0.9, sensor, -1}}, {});
    for (const PersonState& s : tr.people())
      if (s.id == id && s.seen) {
        ++seen;
        most_off = std::max(most_off, angleDiff(s.yaw, M_PI / 6));
      }
  }
  CHECK(seen == 20);
  CHECK(most_off < 0.2);
}

TEST_CASE("a person lost while standing coasts at their recent mean velocity", "[legs]") {
  // A walker confirmed on a 2 s walk along +x stands still for 1.5 s at x = 0, and the last scan
  // before they are lost shows both legs 0.15 m further on (fits of legs partly hidden by someone
  // passing in front). The filter reads that jump as a walk; over the last second the centre
  // moved 0.15 m. Lost for 1 s, the track coasts at the slower (lost_velocity_window) and stays
  // near where they stood, instead of drifting off towards other people's legs.
  auto run = [](double window) {
    LegPeopleParams p;
    p.lost_velocity_window = window;
    LegPeopleTracker tr(p);
    const Eigen::Vector2d sensor(0, -5);
    auto step = [&](double t, double x, double lp) {
      tr.step(t, {{{x + lp / 2, 0.09}, 0.9, sensor, -1}, {{x - lp / 2, -0.09}, 0.9, sensor, -1}},
              {});
    };
    for (int k = 0; k <= 20; ++k)
      step(0.1 * k, -2 + 0.1 * k, 0.25 * std::sin(2 * M_PI * 0.9 * 0.1 * k));
    for (int k = 1; k <= 15; ++k) step(2 + 0.1 * k, 0, 0);
    step(3.6, 0.15, 0);
    long id = 0;
    for (const PersonState& s : tr.people())
      if (s.confirmed) id = s.id;
    for (int k = 1; k <= 10; ++k) tr.step(3.6 + 0.1 * k, {}, {});
    std::optional<Eigen::Vector2d> at;
    for (const PersonState& s : tr.people())
      if (s.id == id) at = s.p;
    REQUIRE(id > 0);
    REQUIRE(at);
    return at->x();
  };
  const double recent = run(1.0), filter = run(0);
  INFO("coasted to x = " << recent << " (recent mean velocity), " << filter << " (filter's)");
  CHECK(recent < 0.3);
  CHECK(filter > recent + 0.2);
}
