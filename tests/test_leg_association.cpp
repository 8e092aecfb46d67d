// leg_people's association of leg objects to leg circles: a confirmed person standing still
// keeps their legs within standing_gate (0.25 m) of where they stand, so a scan that misses a
// leg while clutter shows 0.35 m beside it does not drag the person onto the clutter; with
// standing_gate 0 every leg has the general gate (0.45 m) and the leg slides over.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "leg_people/leg_people_tracker.h"
#include "leg_walker.h"

using namespace pedtrack::track;

namespace {

// Where the walker of walkThenStand (standing at (-0.5, 0) from 1.5 s) is after standing 2.5 s,
// then 3 scans in which only their right leg and a bag 0.35 m beside their left leg are seen,
// then 5 scans of both legs. Returns the largest distance of their estimate from (-0.5, 0) over
// those 8 scans.
double drift(double standing_gate) {
  LegPeopleParams p;
  p.standing_gate = standing_gate;
  LegPeopleTracker tr{p};
  double t = 0;
  const long id = pedtrack::test::walkThenStand(tr, t, 40);
  REQUIRE(id > 0);
  const Eigen::Vector2d sensor(0, -5), left(-0.5, 0.09), right(-0.5, -0.09);
  const Eigen::Vector2d bag = left + Eigen::Vector2d(0.2, 0.287);  // 0.35 m from the left leg
  double worst = 0;
  for (int k = 0; k < 8; ++k, t += 0.1) {
    std::vector<LegDetection> seen{{right, 0.9, sensor, -1}};
    seen.push_back({k < 3 ? bag : left, k < 3 ? 0.3 : 0.9, sensor, -1});
    tr.step(t, seen, {});
    for (const PersonState& s : tr.people())
      if (s.id == id) worst = std::max(worst, (s.p - Eigen::Vector2d(-0.5, 0)).norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("a standing person's leg does not slide onto clutter beside it (standing_gate)",
          "[legs]") {
  CHECK(drift(LegPeopleParams().standing_gate) < 0.05);
  CHECK(drift(0) > 0.1);  // the general gate: the leg takes the bag, the person follows
}
