// The simulator's street scenes: the objects real streets are full of (facades with doorways,
// cars, vans, bicycles, benches, sign posts, foliage), what a scanner's physics does to returns
// (dark surfaces fading out, mixed pixels at depth edges), and the people in them (carrying
// things, sitting, walking in pairs).
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::sim;

namespace {

// One noise-free scan of a UTM-30LX `z` m up looking along +x at the scene `body`.
struct Scan2D {
  std::vector<double> range;  // per beam, NaN when invalid
  std::vector<double> bearing;
  std::vector<int> owner;  // per beam, 0 when invalid
};

Scan2D scan2D(const std::string& body, double z, long seed = 1) {
  Simulator s(scenarioFromText(
      "[scenario]\nduration = 0.1\nseed = " + std::to_string(seed) +
          "\n[sensor]\nmodel = utm30lx\nrange_noise = 0\nz = " + std::to_string(z) + "\n" + body,
      "t.ini"));
  SimFrame f;
  REQUIRE(s.next(f));
  auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(f.observations.back());
  REQUIRE(scan);
  Scan2D out;
  std::size_t k = 0;
  for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
    out.bearing.push_back(-0.5 * scan->aperture + i * scan->aperture / (scan->getScanSize() - 1));
    const bool ok = scan->getScanRangeValidity(i);
    out.range.push_back(ok ? scan->getScanRange(i) : NAN);
    out.owner.push_back(ok ? f.point_truth[k++] : 0);
  }
  return out;
}

// Returns of owner `o` within `half` rad of bearing 0.
std::vector<double> rangesOf(const Scan2D& s, int o, double half = 0.5) {
  std::vector<double> r;
  for (std::size_t i = 0; i < s.range.size(); ++i)
    if (s.owner[i] == o && std::abs(s.bearing[i]) < half) r.push_back(s.range[i]);
  return r;
}

}  // namespace

TEST_CASE("a parked car shows its side at sill height and its wheels below", "[sim][scene]") {
  // A car broadside 6 m ahead (its length across the beams), 1.7-1.85 m wide: its near side at
  // 5.08-5.15 m.
  const std::string car = "[object.car]\ntype = car\nx = 6\ny = 0\nyaw = 90\n";
  const auto body = rangesOf(scan2D(car, 0.6), -1);
  REQUIRE(body.size() > 50);
  CHECK(*std::min_element(body.begin(), body.end()) == Approx(6 - 0.9).margin(0.05));
  // Under the sill (0.3 m) the beam passes between the wheels to a wheel or the far side.
  const auto low = scan2D(car, 0.15);
  CHECK(rangesOf(low, -1).size() < body.size() / 2);
  // Above the roof (1.5 m) nothing.
  CHECK(rangesOf(scan2D(car, 1.6), -1).empty());
  // A van's roof is higher.
  CHECK(rangesOf(scan2D("[object.van]\ntype = van\nx = 6\ny = 0\nyaw = 90\n", 1.7), -1).size() >
        20);
}

TEST_CASE("a facade's doorways are recesses, its wall above them", "[sim][scene]") {
  const std::string facade = "[object.f]\ntype = facade\nx = 5\ny = -20\nx2 = 5\ny2 = 20\n";
  const auto scan = scan2D(facade, 1.0), high = scan2D(facade, 3.0);
  const auto at_legs = rangesOf(scan, -1, 1.3);
  const auto above = rangesOf(high, -1, 1.3);
  REQUIRE(at_legs.size() > 500);
  // Above the doors every beam meets the face (x = 5 - 0.15); at 1 m some go 0.3-0.8 m deeper.
  std::size_t recessed = 0;
  for (std::size_t i = 0; i < scan.range.size(); ++i)
    if (scan.owner[i] == -1 && std::abs(scan.bearing[i]) < 1.3)
      recessed += scan.range[i] * std::cos(scan.bearing[i]) > 4.85 + 0.25;
  CHECK(recessed > 10);
  std::size_t recessed_above = 0;
  for (std::size_t i = 0; i < high.range.size(); ++i)
    if (high.owner[i] == -1 && std::abs(high.bearing[i]) < 1.3)
      recessed_above += high.range[i] * std::cos(high.bearing[i]) > 4.85 + 0.25;
  CHECK(recessed_above == 0);
  CHECK(above.size() > 500);
}

TEST_CASE("foliage returns from inside its volume and lets some beams through", "[sim][scene]") {
  // A sparse bush (0.8 m between leaves on a ray) of radius 0.8 m at 5 m, its centre at the
  // scanner's height, before a wall at 9 m.
  const std::string scene =
      "[object.bush]\ntype = bush\nx = 5\ny = 0\nradius = 0.8\nheight = 1.6\nfoliage = 0.8\n"
      "[object.wall]\ntype = wall\nx = 9\ny = -5\nx2 = 9\ny2 = 5\n";
  const auto s = scan2D(scene, 0.8);
  const auto bush = rangesOf(s, -1, 0.12), wall = rangesOf(s, -2, 0.12);
  REQUIRE(bush.size() > 20);
  // A solid ball's near surface lies within 4.2-5 m; foliage spreads returns deeper inside it.
  double deeper = 0;
  for (double r : bush) deeper += r > 5.0;
  CHECK(deeper > 0.1 * bush.size());
  CHECK(!wall.empty());  // beams that passed through reach the wall behind
  // Solid (foliage = 0): no beam through, every return on the near surface.
  const auto solid = scan2D(
      "[object.bush]\ntype = bush\nx = 5\ny = 0\nradius = 0.8\nheight = 1.6\nfoliage = 0\n"
      "[object.wall]\ntype = wall\nx = 9\ny = -5\nx2 = 9\ny2 = 5\n",
      0.8);
  for (double r : rangesOf(solid, -1, 0.12)) CHECK(r <= 5.0);
  std::size_t behind = 0;
  for (std::size_t i = 0; i < solid.range.size(); ++i)
    behind += solid.owner[i] == -2 && std::abs(solid.bearing[i]) < 0.1;
  CHECK(behind == 0);
}

TEST_CASE("a bicycle gives few scattered returns, a bench a low slab", "[sim][scene]") {
  const auto bike =
      rangesOf(scan2D("[object.b]\ntype = bicycle\nx = 4\ny = 0\nyaw = 90\n", 0.5), -1, 0.5);
  CHECK(bike.size() > 2);
  CHECK(bike.size() < 25);  // the rims and tubes, not a solid side
  // A bench's seat at 0.42-0.47 m: a beam at 0.45 m meets it, one at 1.2 m does not.
  const std::string bench = "[object.b]\ntype = bench\nx = 4\ny = 0\nyaw = 90\n";
  CHECK(rangesOf(scan2D(bench, 0.45), -1).size() > 20);
  CHECK(rangesOf(scan2D(bench, 1.2), -1).empty());
  // A sign post's plate is 0.6 m wide at the top, its pole 7 cm below it.
  const std::string sign = "[object.s]\ntype = signpost\nx = 4\ny = 0\nheight = 2.8\nyaw = 90\n";
  CHECK(rangesOf(scan2D(sign, 2.5), -1).size() > 3 * rangesOf(scan2D(sign, 1.0), -1).size());
}

TEST_CASE("a scanner loses dark surfaces at range and mixes ranges at depth edges",
          "[sim][scene]") {
  // Walls of many reflectivities at 20 m and at 60 m, seen by a VLP-16-like 100 m scanner:
  // at 20 m every wall is within reach (half max_range at 10 %: the darkest, 5 %, to 35 m).
  SensorSpec spec = sensorDefaults("custom2d");
  spec.max_range = 100;
  spec.dark_dropout = true;
  ObservationMaker maker(spec, 7);
  RangeImage img;
  img.reset(1, 400);
  for (int c = 0; c < 400; ++c) {
    img.range[std::size_t(c)] = c < 200 ? 20 : 60;
    img.owner[std::size_t(c)] = -(1 + c % 100);  // 100 objects of their own reflectivity
  }
  maker.applyReturnPhysics(img);
  int near_lost = 0, far_lost = 0;
  for (int c = 0; c < 400; ++c)
    (c < 200 ? near_lost : far_lost) += !std::isfinite(img.range[std::size_t(c)]);
  CHECK(near_lost == 0);
  CHECK(far_lost > 20);   // the darker walls
  CHECK(far_lost < 180);  // not the bright ones (reach 50 sqrt(R / 10) m > 60 m from R = 15)
  // Mixed pixels: a 0.5 m step gets returns in between; a 4 m step does not (two returns).
  SensorSpec mix = sensorDefaults("custom2d");
  mix.max_range = 30;
  mix.mixed_pixels = 1;
  ObservationMaker mixer(mix, 7);
  img.reset(1, 8);
  const double r[8] = {5, 5, 5, 5.5, 5.5, 9.5, 9.5, 9.5};
  for (int c = 0; c < 8; ++c) img.range[std::size_t(c)] = r[c], img.owner[std::size_t(c)] = -1;
  mixer.applyReturnPhysics(img);
  CHECK(img.range[0] == 5);
  CHECK(img.range[2] > 5);
  CHECK(img.range[2] < 5.5);
  CHECK(img.range[3] > 5);
  CHECK(img.range[3] < 5.5);
  CHECK(img.range[6] == 9.5);
  CHECK(img.range[7] == 9.5);
}

TEST_CASE("carried things and a seated pose belong to the person", "[sim][scene]") {
  MotionSample still;
  still.x = 5, still.y = 0, still.yaw = 0;
  GaitClock gait;
  gait.advance(still, BodySpec());
  auto top = [](const BodyPose& p, double& zmax, double& umax) {
    zmax = umax = -1e9;
    for (const auto& q : p.parts) {
      Eigen::Vector3d c;
      double r = 0;
      q.bound(c, r);
      zmax =
          std::max(zmax, q.shape == Shape::Sphere || q.shape == Shape::Capsule ? c.z() + r : q.z1);
      umax = std::max(umax, c.x() + r);
    }
  };
  BodySpec b;
  double stand_z, stand_u, sit_z, sit_u, pram_z, pram_u;
  top(poseBody(b, still, gait, 0, 0.4, 1), stand_z, stand_u);
  b.sitting = true;
  top(poseBody(b, still, gait, 0, 0.4, 1), sit_z, sit_u);
  CHECK(stand_z == Approx(1.70).margin(0.03));
  CHECK(sit_z == Approx(0.45 + 0.42 * 1.70 + 0.11).margin(0.15));  // seat + torso + head
  CHECK(sit_u > stand_u + 0.2);                                    // thighs forward
  b.sitting = false;
  b.carry = Carry::Pram;
  const BodyPose pram = poseBody(b, still, gait, 0, 0.4, 3);
  top(pram, pram_z, pram_u);
  CHECK(pram_u > 5 + 1.1);  // pushed ahead
  for (const auto& q : pram.parts) CHECK(q.owner == 3);
}

TEST_CASE("a crowd's companions walk beside their leader; carry shares are drawn", "[sim][scene]") {
  const std::string text =
      "[scenario]\nduration = 20\nseed = 5\n[sensor]\nmodel = vlp16\n"
      "[crowd]\ncount = 6\narea = 0 -5 15 5\npair_share = 1\ncarry_share = 1\n";
  const Scenario sc = scenarioFromText(text, "t.ini");
  REQUIRE(sc.people.size() == 12);
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(sc.people[i].body.carry != Carry::None);
    for (double t = 0; t <= 20; t += 1) {
      const MotionSample a = sc.people[i].path.at(t), c = sc.people[6 + i].path.at(t);
      CHECK(std::hypot(a.x - c.x, a.y - c.y) == Approx(0.675).margin(0.08));
    }
  }
  // Without the shares the crowd is as before: the same paths.
  const Scenario plain = scenarioFromText(
      "[scenario]\nduration = 20\nseed = 5\n[sensor]\nmodel = vlp16\n"
      "[crowd]\ncount = 6\narea = 0 -5 15 5\n",
      "t.ini");
  REQUIRE(plain.people.size() == 6);
  CHECK(plain.people[3].path.at(10).x == sc.people[3].path.at(10).x);
}
