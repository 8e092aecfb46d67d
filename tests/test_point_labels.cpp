// Per-point label files: the container round trip, and the simulator's per-point truth checked
// against the ray each decoded return came from.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <thread>

#include "pedtrack/errors.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack;

namespace {

// Who the ray from `o` along unit `d` meets first, and how far: the scenario's objects, the
// frame's posed people and the ground, exactly as the simulator casts them.
std::pair<int, double> firstHit(const sim::Simulator& s, const Eigen::Vector3d& o,
                                const Eigen::Vector3d& d) {
  double best = s.scenario().ground.intersect(o, d);
  int owner = sim::kOwnerGround;
  for (const auto* list : {&s.scenario().objects, &s.posedPeople()})
    for (const sim::Primitive& p : *list) {
      const double t = sim::intersect(p, o, d);
      if (t < best) {
        best = t;
        owner = p.owner;
      }
    }
  return {owner, best};
}

struct Check {
  std::size_t points = 0, agree = 0, people = 0, objects = 0, ground = 0;
};

// Every return of `frames` frames: its label against the first hit of its own ray.
Check checkScenario(const std::string& text, int frames) {
  sim::Simulator s(sim::scenarioFromText(text, "t.ini"));
  Check c;
  sim::SimFrame f;
  for (int k = 0; k < frames && s.next(f); ++k) {
    Frame frame;
    frame.observations.push_back(f.observations.back());  // the scan (sensorPose = mount)
    const auto& cloud = frame.cloud();
    REQUIRE(f.point_truth.size() == cloud.size());
    const Eigen::Vector3d o(f.sensor_true.x(), f.sensor_true.y(), f.sensor_true.z());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      float x, y, z;
      cloud.getPoint(i, x, y, z);
      double wx, wy, wz;
      f.robot_true.composePoint(x, y, z, wx, wy, wz);
      const Eigen::Vector3d v = Eigen::Vector3d(wx, wy, wz) - o;
      const auto [owner, t] = firstHit(s, o, v.normalized());
      const std::int32_t label = f.point_truth[i];
      ++c.points;
      // The decoded return lies on its ray within the range resolution (2 mm VLP-16, 1 mm 2D).
      if (owner == label && std::abs(t - v.norm()) < 0.005)
        ++c.agree;
      else
        UNSCOPED_INFO("frame " << k << " point " << i << ": label " << label << ", ray meets "
                               << owner << " at " << t << " m, return at " << v.norm() << " m");
      c.people += truth_label::isPerson(label);
      c.objects += truth_label::isObject(label);
      c.ground += label == truth_label::kGround;
    }
  }
  return c;
}

const char* kScene = R"(
[scenario]
duration = 0.3
seed     = 3
[sensor]
model       = %MODEL%
z           = %Z%
range_noise = 0
[ground]
tilt      = 4
direction = 30
[person.a]
x = 3
y = 1
path = straight
[person.b]
x = -2
y = -2.5
yaw = 45
path = C
[object.wall]
type = wall
x = -6
y = 5
x2 = 8
y2 = 5
[object.pole]
type = pole
x = 4
y = -1
[object.box]
type = box
x = -3
y = 1.5
[object.tree]
type = tree
x = 6
y = 2
)";

std::string scene(const std::string& model, const std::string& z) {
  std::string t = kScene;
  t.replace(t.find("%MODEL%"), 7, model);
  t.replace(t.find("%Z%"), 3, z);
  return t;
}

}  // namespace

TEST_CASE("label files round-trip frames, planes and clearances", "[labels]") {
  const std::string path = test::freshDir("labels_roundtrip") + "/l.bin";
  {
    LabelFileWriter w(path, LabelKind::Truth);
    LabelFrame a;
    a.index = 7;
    a.t = 1.7e9 + 0.25;
    a.plane.valid = true;
    a.plane.nz = 1;
    a.plane.d = -0.3;
    a.labels = {0, 3, -2, 3};
    a.people = {{3, 0.75f}};
    w.write(a);
    LabelFrame b;
    b.index = 9;
    w.write(b);
  }
  LabelFileReader r(path);
  CHECK(r.kind() == LabelKind::Truth);
  LabelFrame f;
  REQUIRE(r.next(f));
  CHECK(f.index == 7);
  CHECK(f.t == 1.7e9 + 0.25);
  CHECK(f.plane.valid);
  CHECK(f.plane.d == -0.3);
  CHECK(f.labels == std::vector<std::int32_t>{0, 3, -2, 3});
  REQUIRE(f.people.size() == 1);
  CHECK(f.people[0].clearance == 0.75f);
  REQUIRE(r.next(f));
  CHECK(f.index == 9);
  CHECK(f.labels.empty());
  CHECK_FALSE(f.plane.valid);
  CHECK_FALSE(r.next(f));
  test::writeFile(path, "not a label file");
  CHECK_THROWS_AS(LabelFileReader(path), ConfigError);
}

TEST_CASE("label files: the same frames give the same bytes, however slowly they are written",
          "[labels]") {
  // Flushing by the wall clock made a simulation written twice differ byte for byte (the
  // same labels, compressed with flushes at other places). 25 frames over 2.4 s of frame time:
  // two flushes by the frames' clock; one file is written with a wall-clock pause longer than
  // the old one-second period.
  const std::string dir = test::freshDir("labels_bytes");
  auto write = [&](const std::string& path, bool pause) {
    LabelFileWriter w(path, LabelKind::Run);
    for (int k = 0; k < 25; ++k) {
      LabelFrame f;
      f.index = std::uint64_t(k);
      f.t = 1.7e9 + 0.1 * k;
      f.labels.assign(5000, k % 7 - 2);
      w.write(f);
      if (pause && k == 12) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    }
  };
  write(dir + "/a.bin", false);
  write(dir + "/b.bin", true);
  CHECK(test::readFile(dir + "/a.bin") == test::readFile(dir + "/b.bin"));
  LabelFileReader r(dir + "/b.bin");
  LabelFrame f;
  int n = 0;
  while (r.next(f)) CHECK(f.index == std::uint64_t(n++));
  CHECK(n == 25);
}

TEST_CASE("VLP-16 truth: every decoded return's label is what its ray hit first", "[labels]") {
  const Check c = checkScenario(scene("vlp16", "1.0"), 3);
  CHECK(c.points > 50000);
  CHECK(c.agree == c.points);
  CHECK(c.people > 300);
  CHECK(c.objects > 1000);
  CHECK(c.ground > 10000);
}

TEST_CASE("2D truth: every return's label is what its beam hit first", "[labels]") {
  const Check c = checkScenario(scene("utm30lx", "0.4"), 5);
  CHECK(c.points > 2000);
  CHECK(c.agree == c.points);
  CHECK(c.people > 50);
  CHECK(c.objects > 500);
}

TEST_CASE("truth clearance: a person next to a pole, and one in the open", "[labels]") {
  sim::Simulator s(sim::scenarioFromText(R"(
[scenario]
duration = 0.1
[sensor]
model = vlp16
[person.near]
x = 3
y = 0
[person.far]
x = -4
y = 3
[object.pole]
type   = pole
x      = 3
y      = -0.45
radius = 0.05
)",
                                         "t.ini"));
  sim::SimFrame f;
  REQUIRE(s.next(f));
  REQUIRE(f.clearance.size() == 2);
  // Ids follow the section names: far = 1, near = 2. The pole's surface is 0.40 m from the near
  // person's torso axis; the torso (0.2 m across the shoulders, facing +x: 0.2 m toward the
  // pole) and the arm hanging outside it come closer still.
  CHECK(f.clearance[0].id == 1);
  CHECK(f.clearance[0].clearance == Approx(kClearanceCap));
  CHECK(f.clearance[1].id == 2);
  CHECK(f.clearance[1].clearance < 0.2);
}
