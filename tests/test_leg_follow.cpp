// The leg_people stage following a person (track.follow), driven through a pipeline's stage as
// a run drives it, on hand-made frames of leg circles: the person standing in front is confirmed
// and marked `following`; lost from sight for 1.5 s (legs merged, turned edge-on), they are still
// written and still followed (follow_coast 2 s), where anyone else is written only report_coast
// (0.5 s) past their last sighting; back in view, they are the same track. Out of follow_zone for
// longer than follow_coast, the person followed is let go.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

// A pipeline of one leg_people stage (the source is never read) with the given extra keys.
struct FollowStage : DrivenStages {
  explicit FollowStage(const std::string& keys)
      : DrivenStages("[pipeline]\nstages = source track\n[source]\nplugin = sim\nscenario = " +
                     std::string(PEDTRACK_SOURCE_DIR) +
                     "/configs/scenarios/legs_standing_60s.ini\n"
                     "[track]\nplugin = leg_people\nfollow = nearest\n" +
                     keys) {}
};

// A frame at t with two leg circles 0.2 m apart across the line of sight at (x, 0), or none.
Frame legsAt(std::size_t index, double t, double x, bool seen) {
  Frame f;
  f.index = index;
  f.t = t;
  if (seen)
    for (double y : {-0.1, 0.1}) {
      Cluster c;
      c.cx = x;
      c.cy = y;
      f.clusters.push_back(c);
    }
  return f;
}

// Per frame index, the statuses written (10 Hz: 3 s seen, `gap` s unseen, 1 s seen again).
struct Written {
  std::map<std::size_t, std::string> status;
  std::set<long> ids;
};

Written follow(const std::string& keys, double gap) {
  FollowStage stage(keys);
  Written w;
  const int seen_before = 30, unseen = int(std::lround(gap * 10)),
            total = seen_before + unseen + 10;
  for (int k = 0; k < total; ++k) {
    Frame f =
        legsAt(std::size_t(k), 1000 + 0.1 * k, 1.5, k < seen_before || k >= seen_before + unseen);
    stage.run(f);
    for (const Track& t : f.tracks) {
      w.status[std::size_t(k)] = t.status;
      w.ids.insert(t.id);
    }
  }
  return w;
}

}  // namespace

TEST_CASE("a followed person lost from sight for 1.5 s is written and followed throughout",
          "[legs][follow]") {
  const Written w = follow("", 1.5);
  // Confirmed by standing in the follow zone (follow_confirm_time 0.5 s) within the first second.
  std::size_t first = 1000;
  for (const auto& [k, s] : w.status) first = std::min(first, k);
  CHECK(first <= 10);
  for (std::size_t k = first; k < 55; ++k) {
    INFO("frame " << k);
    REQUIRE(w.status.count(k) == 1);
    CHECK(w.status.at(k) == "following");
  }
  CHECK(w.ids.size() == 1);  // the same track when back in view
}

TEST_CASE("with follow_coast at report_coast the followed person goes unwritten like anyone else",
          "[legs][follow]") {
  const Written w = follow("follow_coast = 0.5\n", 1.5);
  // Last seen at frame 29: written up to 0.5 s later, not from 0.6 s on until seen again (45).
  CHECK(w.status.count(34) == 1);
  for (std::size_t k = 36; k < 45; ++k) CHECK(w.status.count(k) == 0);
  CHECK(w.status.count(46) == 1);
}

TEST_CASE("the person followed is let go once out of follow_zone for longer than follow_coast",
          "[legs][follow]") {
  // Standing 1.5 m ahead for 3 s (followed), then walking off straight ahead at 1 m/s to 4.5 m
  // (follow_zone ends at 3 m, which they pass at 4.5 s) and standing there, seen throughout: still
  // the person followed up to 2 s after leaving the zone, then only confirmed (no one else to
  // follow).
  FollowStage stage("");
  std::map<int, std::string> status;
  for (int k = 0; k < 100; ++k) {
    const double t = 0.1 * k, x = std::clamp(1.5 + (t - 3.0), 1.5, 4.5);
    Frame f = legsAt(std::size_t(k), 1000 + t, x, true);
    stage.run(f);
    for (const Track& tr : f.tracks) status[k] = tr.status;
  }
  REQUIRE(status.count(30) == 1);
  CHECK(status.at(30) == "following");
  CHECK(status.at(60) == "following");  // out of the zone 1.5 s
  CHECK(status.at(70) == "confirmed");  // 2.5 s
  CHECK(status.at(99) == "confirmed");
}
