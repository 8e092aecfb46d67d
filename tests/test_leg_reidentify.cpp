// leg_people's re-identification (LegPeopleTracker::lostPersonNear) of a confirmed person who is
// not seen by both legs: a new leg pair formed within a leg gate of them is them again. Here a
// person standing still loses sight of both legs for 0.6 s while a bag appears beside them: one
// leg object slides onto the bag (the other is dropped after object_max_coast), so the person is
// held up by the bag alone when their legs come back as a new pair. Other re-identification
// cases (people lost from sight): test_legs.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "leg_people/leg_people_tracker.h"
#include "leg_walker.h"

using namespace pedtrack::track;

TEST_CASE("a person held up by one leg on a bag beside them takes back their legs", "[legs]") {
  LegPeopleTracker tr{LegPeopleParams{}};
  double t = 0;
  const long id = pedtrack::test::walkThenStand(tr, t, 40);  // stands at (-0.5, 0) from 1.5 s
  REQUIRE(id > 0);
  const Eigen::Vector2d sensor(0, -5), bag(-0.4, 0.25), centre(-0.5, 0);
  for (int k = 0; k < 16; ++k, t += 0.1) {
    std::vector<LegDetection> seen{{bag, 0.3, sensor, -1}};
    if (k >= 6) {
      seen.push_back({centre + Eigen::Vector2d(0, 0.09), 0.9, sensor, -1});
      seen.push_back({centre - Eigen::Vector2d(0, 0.09), 0.9, sensor, -1});
    }
    tr.step(t, seen, {});
  }
  // The person is where their legs are, on their own track (before: on the bag, 0.33 m off, and
  // the legs a second person).
  int confirmed = 0;
  for (const PersonState& s : tr.people()) {
    if (!s.confirmed) continue;
    ++confirmed;
    CHECK(s.id == id);
    CHECK((s.p - centre).norm() < 0.05);
  }
  CHECK(confirmed == 1);
}
