// eval::legCoverage (tracks against hand-labelled legs) on hand-made frames.
#include <catch2/catch.hpp>
#include <utility>

#include "pedtrack/eval/leg_coverage.h"

using namespace pedtrack::eval;
using Catch::Detail::Approx;

TEST_CASE("leg coverage counts labelled legs with a track near them and tracks near no leg",
          "[eval]") {
  auto obj = [](long id, double x, double y) {
    Object o;
    o.id = id;
    o.x = x;
    o.y = y;
    return o;
  };
  std::vector<EvalFrame> frames(2);
  // Scan 1: a person's two legs 0.2 m apart, their track between them covers both; a track on
  // a wall 7 m away covers nothing.
  frames[0].truths = {obj(0, 0, 0), obj(1, 0.2, 0)};
  frames[0].estimates = {obj(1, 0.1, 0), obj(2, 5, 5)};
  // Scan 2: the person's track lags 0.5 m behind their one labelled leg.
  frames[1].truths = {obj(0, 1, 1)};
  frames[1].estimates = {obj(1, 1.5, 1)};
  const LegCoverage c = legCoverage(frames, 0.35);
  CHECK(c.legs == 3);
  CHECK(c.covered == 2);
  CHECK(c.recall() == Approx(2.0 / 3));
  CHECK(c.rows == 3);
  CHECK(c.unsupported == 2);
  CHECK(c.per_track.at(1) == std::make_pair(2L, 1L));
  CHECK(c.per_track.at(2) == std::make_pair(1L, 0L));
  CHECK(c.tracksOnNoPerson() == 1);     // the wall's
  CHECK(c.tracksOnNoPerson(0.5) == 2);  // the person's too: half its rows near a leg
  // Within 0.5 m the lagging track covers its leg as well.
  CHECK(legCoverage(frames, 0.5).covered == 3);
}
