// Where MOTA's errors are: misses by the returns on the person, ID switches by the gap before
// them, false positives by the nearest person and coasting, on frames worked out by hand.
#include <catch2/catch.hpp>
#include <cmath>
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

// ID switches, frames 0.1 s apart. Truth A: track 1 (frames 0-1), unscored in frames 2-4 (out of
// sight), missed in 5, then track 2 in frame 6: a switch 0.5 s after A was last matched (frame
// 1), its gap 4 frames present of which 3 unscored (out of sight), by a track new to anyone.
// Truth B: track 3 (frame 0), then track 4 (frame 1): a switch 0.1 s after its last match, by a
// track new to anyone. Truth D: track 5 (frames 0-1); D gone, track 5 takes the new truth C over
// in frame 2: a switch at C's first match, by a track from another person.
TEST_CASE("error budget: ID switches by the gap before them", "[eval][budget]") {
  std::vector<EvalFrame> f(7);
  for (std::size_t k = 0; k < f.size(); ++k) f[k].t = 0.1 * double(k);
  f[0].truths = {truth(1, 0, 20), truth(2, 10, 20), truth(4, 30, 20)};
  f[0].estimates = {track(1, 0), track(3, 10), track(5, 30)};
  f[1].truths = {truth(1, 0, 20), truth(2, 10, 20), truth(4, 30, 20)};
  f[1].estimates = {track(1, 0), track(4, 10), track(5, 30)};
  f[2].truths = {truth(1, 0, 0, false), truth(3, 20, 20)};
  f[2].estimates = {track(5, 20)};
  f[3].truths = {truth(1, 0, 0, false)};
  f[4].truths = {truth(1, 0, 0, false)};
  f[5].truths = {truth(1, 0, 20)};
  f[6].truths = {truth(1, 0, 20)};
  f[6].estimates = {track(2, 0)};
  const ClearMotResult cm = clearMot(f, {});
  REQUIRE(cm.counts.id_switches == 3);
  REQUIRE(cm.switches.size() == 3);
  CHECK(cm.switches[0].truth == 2);
  CHECK(cm.switches[0].gap == Approx(0.1));
  CHECK_FALSE(cm.switches[0].track_from_other);
  CHECK(cm.switches[1].truth == 3);
  CHECK(std::isnan(cm.switches[1].gap));
  CHECK(cm.switches[1].track_from_other);
  CHECK(cm.switches[2].truth == 1);
  CHECK(cm.switches[2].gap == Approx(0.5));
  CHECK(cm.switches[2].gap_frames == 4);
  CHECK(cm.switches[2].gap_unscored == 3);
  const ErrorBudget b = errorBudget(f, cm);
  using G = std::array<std::size_t, ErrorBudget::kGapBins>;
  CHECK(b.switches_by_gap == G{1, 1, 0, 1});  // B 0.1 s; A 0.5 s; C at first match
  CHECK(b.switches_from_other_by_gap == G{0, 0, 0, 1});
  CHECK(b.switches_unseen_by_gap == G{0, 1, 0, 0});
  ErrorBudget twice = b;
  twice += b;
  CHECK(twice.switches_by_gap == G{2, 2, 0, 2});
}
