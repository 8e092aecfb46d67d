// leg_people's support_gate: a confirmed walker whose legs no circle shows (one or two returns a
// leg: far away, or all but hidden behind someone) stays seen and followed from those returns;
// returns on the static scene, or with support_gate 0, leave them coasting.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "leg_people/leg_people_tracker.h"

using namespace pedtrack::track;

namespace {

const Eigen::Vector2d kSensor{0, -5};

// Leg centres of a walker at x along y = 0 at time t, scissoring 0.25 m at 0.9 Hz.
std::pair<Eigen::Vector2d, Eigen::Vector2d> legsAt(double x, double t) {
  const double lp = 0.25 * std::sin(2 * M_PI * 0.9 * t);
  return {{x + lp / 2, 0.09}, {x - lp / 2, -0.09}};
}

// A walker along +x at 1 m/s seen as two leg circles for 2 s (confirmed), then for 2 s only as
// one return a leg: the point of each leg nearest the scanner (0.05 m in front of its centre).
// Returns their state at the end (id 0: not confirmed by then).
PersonState walkThenReturnsOnly(const LegPeopleParams& p,
                                const std::function<bool(double, double)>& is_static = {}) {
  LegPeopleTracker tr(p);
  double t = 0;
  for (; t < 2; t += 0.1) {
    const auto [l, r] = legsAt(-2 + t, t);
    tr.step(t, {{l, 0.9, kSensor, -1}, {r, 0.9, kSensor, -1}}, {});
  }
  long id = 0;
  for (const PersonState& s : tr.people())
    if (s.confirmed) id = s.id;
  REQUIRE(id > 0);
  for (; t < 4; t += 0.1) {
    const auto [l, r] = legsAt(-2 + t, t);
    const auto surface = [](const Eigen::Vector2d& c) {
      return LegReturn{c + 0.05 * (kSensor - c).normalized(), kSensor};
    };
    tr.step(t, {}, is_static, {surface(l), surface(r)});
  }
  for (const PersonState& s : tr.people())
    if (s.id == id) return s;
  return {};
}

}  // namespace

TEST_CASE("a confirmed walker seen by one return a leg stays seen and followed", "[legs]") {
  const PersonState s = walkThenReturnsOnly(LegPeopleParams{});
  REQUIRE(s.id > 0);
  CHECK(s.seen);
  CHECK(s.unseen == 0);
  // At t = 3.9 s the walker is at x = 1.9; the returns, moved back a leg radius, put them there.
  CHECK(std::abs(s.p.x() - 1.9) < 0.1);
  CHECK(std::abs(s.p.y()) < 0.1);
}

TEST_CASE("without support_gate, or on the static scene, returns do not hold a person", "[legs]") {
  LegPeopleParams off;
  off.support_gate = 0;
  const PersonState a = walkThenReturnsOnly(off);
  CHECK_FALSE(a.seen);
  CHECK(a.unseen > 1.8);
  // The same returns where the static scene says furniture stands.
  const PersonState b = walkThenReturnsOnly(LegPeopleParams{}, [](double, double) { return true; });
  CHECK_FALSE(b.seen);
  CHECK(b.unseen > 1.8);
}
