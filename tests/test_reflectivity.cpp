// The simulated VLP-16's intensity: every surface has a reflectivity of its own, drawn once
// from its class's range, the classes' ranges overlap, every return adds noise, and the draws
// leave the geometry's random numbers (ranges, truth) as they were.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <vector>

#include "pedtrack/sim/reflectivity.h"
#include "pedtrack/sim/simulator.h"

using namespace pedtrack;
using namespace pedtrack::sim;

namespace {

using Velo = mrpt::obs::CObservationVelodyneScan;

// A VLP-16 on a robot among people, poles, a wall and a bin.
const char* kScene =
    "[scenario]\nduration = 0.3\nseed = 5\n[sensor]\nmodel = vlp16\nz = 1.0\n"
    "[person.a]\nx = 4\ny = 0\n[person.b]\nx = 5\ny = 2\n[person.c]\nx = 3\ny = -3\n"
    "[person.d]\nx = 6\ny = -1\n[object.wall]\ntype = wall\nx = 8\ny = -5\nx2 = 8\ny2 = 5\n"
    "[object.p1]\ntype = pole\nx = 2\ny = 2\n[object.p2]\ntype = pole\nx = 2\ny = -1.5\n"
    "[object.bin]\ntype = bin\nx = -3\ny = 1\n";

// Each return's intensity by who it hit (the simulator lists owners in the order the decoder
// reads the packets: packet, block, firing).
std::map<int, std::vector<int>> intensitiesByOwner(const SimFrame& f) {
  std::map<int, std::vector<int>> out;
  const auto velo = std::dynamic_pointer_cast<Velo>(f.observations.back());
  REQUIRE(velo);
  std::size_t next = 0;
  for (const auto& packet : velo->scan_packets)
    for (const auto& block : packet.blocks)
      for (const auto& ret : block.laser_returns)
        if (ret.distance() > 0) {
          REQUIRE(next < f.point_truth.size());
          out[f.point_truth[next++]].push_back(ret.intensity());
        }
  CHECK(next == f.point_truth.size());
  return out;
}

double mean(const std::vector<int>& v) {
  double s = 0;
  for (int x : v) s += x;
  return s / double(v.size());
}

}  // namespace

TEST_CASE("each surface has a reflectivity of its own, from overlapping class ranges",
          "[sim][reflectivity]") {
  Reflectivity r(7);
  std::vector<double> people, objects;
  for (int id = 1; id <= 200; ++id) people.push_back(r.surface(id));
  for (int id = 1; id <= 200; ++id) objects.push_back(r.surface(-id));
  auto [pmin, pmax] = std::minmax_element(people.begin(), people.end());
  auto [omin, omax] = std::minmax_element(objects.begin(), objects.end());
  CHECK(*pmin >= Reflectivity::kPersonMin);
  CHECK(*pmax <= Reflectivity::kPersonMax);
  CHECK(*pmax - *pmin > 40);  // spread over the class, not a constant
  CHECK(*omax - *omin > 70);
  // Overlap: some objects read darker than some people and the ground's range lies in both.
  CHECK(*omin < *pmax);
  CHECK(r.surface(0) >= Reflectivity::kGroundMin);
  CHECK(r.surface(0) <= Reflectivity::kGroundMax);
  // A surface's value does not depend on the order surfaces were met in, and is seeded.
  Reflectivity backwards(7), other(8);
  CHECK(backwards.surface(-200) == objects.back());
  CHECK(backwards.surface(1) == people.front());
  CHECK(other.surface(1) != people.front());
  // Every return adds noise.
  std::set<int> readings;
  for (int i = 0; i < 100; ++i) readings.insert(r.of(1));
  CHECK(readings.size() > 5);
}

TEST_CASE("the simulated VLP-16 reports each surface's reflectivity, not its class",
          "[sim][reflectivity]") {
  Simulator s(scenarioFromText(kScene, "t.ini"));
  SimFrame f;
  REQUIRE(s.next(f));
  const auto by_owner = intensitiesByOwner(f);
  std::vector<double> person_means, object_means;
  std::set<int> person_values;
  for (const auto& [owner, values] : by_owner) {
    if (values.size() < 20) continue;
    if (owner > 0) person_means.push_back(mean(values));
    if (owner < 0) object_means.push_back(mean(values));
    if (owner > 0) person_values.insert(values.begin(), values.end());
  }
  REQUIRE(person_means.size() >= 3);
  REQUIRE(object_means.size() >= 2);
  // A constant per class (the truth in the intensity) gives one value for every person.
  CHECK(person_values.size() > 10);
  CHECK(*std::max_element(person_means.begin(), person_means.end()) -
            *std::min_element(person_means.begin(), person_means.end()) >
        5);
}
