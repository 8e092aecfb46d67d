// Where MOTA's errors are: misses by the returns on the person, false positives by the nearest
// person and coasting, on frames worked out by hand.
#include <catch2/catch.hpp>
#include <deque>

#include "pedtrack/eval/error_budget.h"

using namespace pedtrack;
using namespace pedtrack::eval;

namespace {

std::deque<ObjectRow> rows;  // the rows the objects point into (stable addresses)

Object truth(long id, double x, long visible, bool scored = true) {
  ObjectRow& r = rows.emplace_back();
  r.visible_points = visible;
  Object o;
  o.id = id;
  o.x = x;
  o.scored = scored;
  o.row = &r;
  return o;
}

Object track(long id, double x, const char* status = "confirmed") {
  ObjectRow& r = rows.emplace_back();
  r.status = status;
  Object o;
  o.id = id;
  o.x = x;
  o.row = &r;
  return o;
}

// Frame 0: A (5 returns) matched; B (40) with a coasting track 0.9 m off (a miss and a false
// positive under 1 m); C (15) missed; a track 10 m from anyone. Frame 1: A (3) missed with a
// track 1.5 m off; D, unscored (0 returns), absorbs a track; a truth without visible_points.
std::vector<EvalFrame> frames() {
  std::vector<EvalFrame> f(2);
  f[0].t = 0;
  f[0].truths = {truth(1, 0, 5), truth(2, 5, 40), truth(3, 10, 15)};
  f[0].estimates = {track(1, 0.1), track(2, 5.9, "coasting"), track(3, 20)};
  f[1].t = 0.1;
  f[1].truths = {truth(1, 0, 3), truth(4, 30, 0, false), truth(5, -10, -1)};
  f[1].estimates = {track(4, 1.5), track(5, 30.1), track(6, -10.2)};
  return f;
}

}  // namespace

TEST_CASE("error budget: misses by visible points, false positives by nearest person",
          "[eval][budget]") {
  const auto f = frames();
  const ClearMotResult cm = clearMot(f, {});
  REQUIRE(cm.counts.misses == 3);
  REQUIRE(cm.counts.false_positives == 3);
  const ErrorBudget b = errorBudget(f, cm);
  using V = std::array<std::size_t, ErrorBudget::kVisibleBins>;
  using D = std::array<std::size_t, ErrorBudget::kDistanceBins>;
  CHECK(b.truths_by_visible == V{2, 1, 1, 1});  // D is unscored; the last truth has no count
  CHECK(b.misses_by_visible == V{1, 1, 1, 0});  // A in frame 1, C, B
  CHECK(b.fp_by_distance == D{1, 1, 1});        // 0.9 m from B, 1.5 m from A, 10 m from C
  CHECK(b.coasting_fp_by_distance == D{1, 0, 0});
  ErrorBudget twice = b;
  twice += b;
  CHECK(twice.misses_by_visible == V{2, 2, 2, 0});
  CHECK(twice.fp_by_distance == D{2, 2, 2});
}

TEST_CASE("error budget: following counts no false positives", "[eval][budget]") {
  const auto f = frames();
  ClearMotOptions o;
  o.following = 0;  // every truth is the followed person
  const ErrorBudget b = errorBudget(f, clearMot(f, o));
  CHECK(b.misses_by_visible == std::array<std::size_t, ErrorBudget::kVisibleBins>{1, 1, 1, 0});
  CHECK(b.fp_by_distance == std::array<std::size_t, ErrorBudget::kDistanceBins>{0, 0, 0});
}
