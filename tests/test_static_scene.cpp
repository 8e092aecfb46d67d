// Static-scene suppression: walls become static after `persist` seconds and not before; a tracked
// person standing for a minute never does, nor do the cells a passer-by leaves; prior maps (ROS
// map_server, MRPT) load with their geometry; bad map files are named in the error; the grid
// follows a moving robot; the 3D (points) entry behaves like the scan one, and with heights a
// static cell holds only returns near the heights it was hit at. Prints update() cost.
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>

#include "pedtrack/errors.h"
#include "pedtrack/track/static_scene.h"
#include "ray_world.h"
#include "test_support.h"

using namespace pedtrack;
using pedtrack::track::StaticScene;
using V2 = Eigen::Vector2d;

namespace {

using World = pedtrack::test::RayWorld;
using pedtrack::test::castRay;

// One 768-beam, 270° scan (a Hokuyo-like sensor) of `w` taken at time t from `robot`, with the
// sensor mounted at `mount` on the robot.
Frame scanFrame(const World& w, double t, const mrpt::poses::CPose3D& robot = {},
                const mrpt::poses::CPose3D& mount = mrpt::poses::CPose3D(0.2, 0, 0.3, 0, 0, 0)) {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->aperture = float(270 * M_PI / 180);
  scan->rightToLeft = true;
  scan->maxRange = 30;
  scan->sensorPose = mount;
  scan->resizeScan(768);
  const mrpt::poses::CPose3D sensor = robot + mount;
  for (std::size_t i = 0; i < 768; ++i) {
    const double a = sensor.yaw() + scan->getScanAngle(i);
    const double r = castRay(w, sensor.x(), sensor.y(), std::cos(a), std::sin(a));
    scan->setScanRange(i, r < 29 ? float(r) : 0.f);
    scan->setScanRangeValidity(i, r < 29);
  }
  Frame f;
  f.t = t;
  f.robot_pose = robot;
  f.sensor_pose = sensor;
  f.observations.push_back(scan);
  return f;
}

constexpr double kT0 = 1.7e9;    // UNIX seconds, as a rawlog's
constexpr double kDt = 0.025;    // 40 Hz
constexpr double kWallX = 4.02;  // mid-cell for 5 cm cells on a grid aligned to 0

// Wide enough that rays to it cross x = 2 for |y| < 3.8.
World wallAhead() {
  return World{{{kWallX, -8, kWallX, 8}}, {}};
}

void addLegs(World& w, double x, double y, double spread_y) {
  w.circles.push_back({x, y + spread_y, 0.06});
  w.circles.push_back({x, y - spread_y, 0.06});
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f << bytes;
}

}  // namespace

TEST_CASE("a wall is static once seen for persist seconds and not before", "[static_scene]") {
  StaticScene ss;  // defaults: persist 3 s
  const World w = wallAhead();
  double t = kT0;
  for (; t < kT0 + 1.0; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK(ss.occupancy(kWallX, 0) > 0.9);    // occupied at once...
  CHECK_FALSE(ss.isStatic(kWallX, 0, t));  // ...but not static yet
  for (; t < kT0 + 2.9; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK_FALSE(ss.isStatic(kWallX, 0, t));
  for (; t < kT0 + 3.2; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK(ss.isStatic(kWallX, 0, t));
  CHECK(ss.isStatic(kWallX, 2.5, t));
  // The free space before the wall is neither occupied nor static; a leg-circle centre fitted
  // a few cm behind the wall surface finds it with a radius.
  CHECK(ss.occupancy(2.0, 0) < 0.1);
  CHECK_FALSE(ss.isStatic(2.0, 0, t));
  CHECK_FALSE(ss.isStatic(kWallX + 0.07, 0, t));
  CHECK(ss.isStatic(kWallX + 0.07, 0, t, 0.1));
  // The debugging picture of the grid.
  const std::string png = test::freshDir("static_scene_png") + "/grid.png";
  CHECK(ss.saveImage(png));
  CHECK(test::readFile(png).size() > 100);
}

TEST_CASE("forget() drops what the grid learned; it learns again from scratch", "[static_scene]") {
  // The robot moved by an unknown amount (Frame::motion_unknown): the wall may be anywhere now.
  StaticScene ss;
  const World w = wallAhead();
  double t = kT0;
  for (; t < kT0 + 3.2; t += kDt) ss.update(scanFrame(w, t), {});
  REQUIRE(ss.isStatic(kWallX, 0, t));
  ss.forget();
  CHECK_FALSE(ss.isStatic(kWallX, 0, t));
  CHECK(ss.occupancy(kWallX, 0) == Approx(0.5));  // unknown
  // Seen again, it takes persist seconds again.
  const double t1 = t;
  for (; t < t1 + 2.9; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK_FALSE(ss.isStatic(kWallX, 0, t));
  for (; t < t1 + 3.2; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK(ss.isStatic(kWallX, 0, t));
}

TEST_CASE("a tracked person standing still for a minute never becomes static", "[static_scene]") {
  StaticScene ss;
  World w = wallAhead();
  const V2 person(2.0, 0.5);
  addLegs(w, person.x(), person.y(), 0.12);
  double t = kT0;
  // The first half second the tracker has not confirmed the person yet: nothing is excluded.
  for (; t < kT0 + 0.5; t += kDt) ss.update(scanFrame(w, t), {});
  CHECK(ss.occupancy(person.x() - 0.055, person.y() + 0.12) > 0.5);  // the near leg surface
  for (; t < kT0 + 60.5; t += kDt) ss.update(scanFrame(w, t), {person});
  for (double r : {0.0, 0.1, 0.2}) CHECK_FALSE(ss.isStatic(person.x(), person.y(), t, r));
  for (double dy : {-0.12, 0.12}) CHECK_FALSE(ss.isStatic(person.x(), person.y() + dy, t, 0.1));
  // The wall beside them is static.
  CHECK(ss.isStatic(kWallX, -2.0, t));
}

TEST_CASE("cells passers-by (not excluded) walked through are not static after they leave",
          "[static_scene]") {
  // Two people cross in front of the robot on the same line at 1 m/s, legs swinging, 5 s
  // apart; then they are gone.
  auto legsAt = [](double t) {
    const double y = -3 + 1.0 * t, swing = 0.25 * std::sin(2 * M_PI * 0.9 * t);
    return std::array<V2, 2>{V2(2.0, y + swing), V2(2.1, y - swing)};
  };
  for (const bool wall : {true, false}) {
    INFO("wall behind the path: " << wall);
    StaticScene ss;
    double t = kT0;
    int static_while_walking = 0;
    for (; t < kT0 + 14.0; t += kDt) {
      World w = wall ? wallAhead() : World{};
      for (const double start : {0.0, 5.0})
        if (t >= kT0 + start && t < kT0 + start + 6.0)
          for (const V2& l : legsAt(t - kT0 - start)) w.circles.push_back({l.x(), l.y(), 0.06});
      ss.update(scanFrame(w, t), {});
      for (const double start : {0.0, 5.0})
        if (t >= kT0 + start && t < kT0 + start + 6.0)
          for (const V2& l : legsAt(t - kT0 - start))
            static_while_walking += ss.isStatic(l.x(), l.y(), t, 0.1);
    }
    CHECK(static_while_walking == 0);
    int occupied = 0;
    for (double y = -2.5; y <= 2.5; y += 0.05)
      for (double x = 1.9; x <= 2.2; x += 0.05) {
        CHECK_FALSE(ss.isStatic(x, y, t));
        occupied += ss.occupancy(x, y) >= ss.options().occupied;
      }
    // With the wall behind, the rays to it cleared the path (free space). Without it nothing
    // clears the path: the cells stay occupied, and only the short time each was hit (and
    // the runs ending after max_gap) keeps them, and the second walker, from being static.
    if (wall)
      CHECK(occupied == 0);
    else
      CHECK(occupied > 0);
  }
}

TEST_CASE("a static wall stays static while a tracked person stands in front of it",
          "[static_scene]") {
  StaticScene ss;
  const V2 person(3.7, 0);
  double t = kT0;
  for (; t < kT0 + 4; t += kDt) ss.update(scanFrame(wallAhead(), t), {});
  REQUIRE(ss.isStatic(kWallX, 0, t));
  World w = wallAhead();
  addLegs(w, person.x(), person.y(), 0.12);
  for (; t < kT0 + 14; t += kDt) {
    ss.update(scanFrame(w, t), {person});
    REQUIRE(ss.isStatic(kWallX, 0, t));
  }
  // They leave: the wall behind them is static at once, not persist seconds later.
  ss.update(scanFrame(wallAhead(), t), {});
  CHECK(ss.isStatic(kWallX, 0, t));
}

TEST_CASE("the grid follows a moving robot and keeps what it saw", "[static_scene]") {
  StaticScene::Options o;
  o.extent = 8;
  o.max_range = 6;
  StaticScene ss(o);
  const World w{{{-5, 2.02, 60, 2.02}}, {}};
  double t = kT0;
  for (; t < kT0 + 25; t += kDt) {
    const mrpt::poses::CPose3D robot(1.0 * (t - kT0), 0, 0, 0, 0, 0);  // 1 m/s along the wall
    ss.update(scanFrame(w, t, robot), {});
  }
  const double x = t - kT0;
  const auto& g = ss.grid();
  CHECK(std::abs(0.5 * (g.getXMin() + g.getXMax()) - x) <= 0.25 * o.extent + o.cell);
  CHECK(g.getXMax() - g.getXMin() == Approx(2 * o.extent).margin(o.cell));
  // Wall seen for longer than persist around and behind the robot (across re-centring) is
  // static; what is no longer in the grid is forgotten.
  for (double dx : {-5.0, -2.0, 0.0}) CHECK(ss.isStatic(x + dx, 2.02, t));
  CHECK_FALSE(ss.isStatic(0.0, 2.02, t));
}

TEST_CASE("points of a 3D sensor: walls become static, excluded people do not", "[static_scene]") {
  StaticScene ss;
  const V2 sensor(0, 0), person(2.0, -0.5);
  std::vector<V2> pts;
  for (double y = -3; y <= 3; y += 0.02)
    for (int layer = 0; layer < 3; ++layer) pts.emplace_back(kWallX, y);  // one wall, 3 rings
  for (double a = 0; a < 2 * M_PI; a += 0.2) pts.emplace_back(person + 0.15 * V2(cos(a), sin(a)));
  double t = kT0;
  for (; t < kT0 + 20; t += 0.1) ss.updatePoints(t, sensor, pts, {person});
  CHECK(ss.isStatic(kWallX, 1.0, t));
  CHECK_FALSE(ss.isStatic(person.x(), person.y(), t, 0.2));
  CHECK(ss.occupancy(person.x(), person.y() + 0.15) <= 0.5);
  // A box left for 5 s then removed is cleared by the wall points behind it.
  std::vector<V2> with_box = pts;
  for (double y = 0.8; y <= 1.2; y += 0.02) with_box.emplace_back(3.01, y);
  for (double t1 = t + 5; t < t1; t += 0.1) ss.updatePoints(t, sensor, with_box, {person});
  CHECK(ss.isStatic(3.01, 1.0, t));
  for (double t1 = t + 2; t < t1; t += 0.1) ss.updatePoints(t, sensor, pts, {person});
  CHECK_FALSE(ss.isStatic(3.01, 1.0, t));
  CHECK(ss.occupancy(3.01, 1.0) < 0.5);
}

TEST_CASE("with heights, a static cell holds only returns near the heights it was hit at",
          "[static_scene]") {
  // A bench back 0.9 m high, seen on rings at 0.3, 0.6 and 0.85 m, learned for 5 s. A sitter's
  // head at 1.25 m beside it is no part of it; their chest at 0.8 m is.
  StaticScene ss;
  const V2 sensor(0, 0);
  std::vector<V2> pts;
  std::vector<float> z;
  for (double y = -0.9; y <= 0.9; y += 0.02)
    for (const float h : {0.3f, 0.6f, 0.85f}) {
      pts.emplace_back(kWallX, y);
      z.push_back(h);
    }
  double t = kT0;
  for (; t < kT0 + 5; t += 0.1) ss.updatePoints(t, sensor, pts, {}, &z);
  const double x = kWallX - 0.2;                       // 0.2 m in front of the bench back
  CHECK(ss.isStatic(x, 0, t, 0.3));                    // 2D: on it
  CHECK(ss.isStatic(x, 0, 0.8, 0.25, t, 0.3));         // within its heights
  CHECK(ss.isStatic(x, 0, 1.05, 0.25, t, 0.3));        // within the margin above its top
  CHECK_FALSE(ss.isStatic(x, 0, 1.25, 0.25, t, 0.3));  // a head above it
  CHECK_FALSE(ss.isStatic(x, 0, 0.8, 0.25, t, 0.1));   // nor near it at all
  CHECK(ss.isStatic(x, 0, NAN, 0.25, t, 0.3));         // a return without height: 2D
  // Cells learned without heights (a 2D scan's, or a sensor that gives none) hold every height.
  StaticScene flat;
  for (t = kT0; t < kT0 + 5; t += 0.1) flat.updatePoints(t, sensor, pts, {});
  CHECK(flat.isStatic(x, 0, 1.25, 0.25, t, 0.3));
}

TEST_CASE("rays clear free space in every direction, diagonals included", "[static_scene]") {
  // A ring of obstacles 2 m round the sensor, then the ring moves out to 4 m: every cell of the
  // old ring, whatever its bearing (octant boundaries and exact diagonals too), is crossed by
  // rays to the new one and cleared.
  StaticScene ss;
  const V2 sensor(0.31, -0.18);  // ring points at 0° and 90° not on cell edges
  auto ring = [&](double r) {
    std::vector<V2> pts;
    for (int k = 0; k < 7200; ++k)
      pts.push_back(sensor + r * V2(cos(k * M_PI / 3600), sin(k * M_PI / 3600)));
    return pts;
  };
  double t = kT0;
  for (int k = 0; k < 5; ++k, t += 0.1) ss.updatePoints(t, sensor, ring(2.0), {});
  int occupied_before = 0, occupied_after = 0;
  for (int deg = 0; deg < 360; ++deg) {
    const V2 p = sensor + 2.0 * V2(cos(deg * M_PI / 180), sin(deg * M_PI / 180));
    occupied_before += ss.occupancy(p.x(), p.y()) >= ss.options().occupied;
  }
  for (int k = 0; k < 20; ++k, t += 0.1) ss.updatePoints(t, sensor, ring(4.0), {});
  for (int deg = 0; deg < 360; ++deg) {
    INFO("bearing " << deg << " deg");
    const V2 p = sensor + 2.0 * V2(cos(deg * M_PI / 180), sin(deg * M_PI / 180));
    occupied_after += ss.occupancy(p.x(), p.y()) >= ss.options().occupied;
    CHECK(ss.occupancy(p.x(), p.y()) < 0.5);
  }
  CHECK(occupied_before == 360);
  CHECK(occupied_after == 0);
}

TEST_CASE("a ROS map_server map marks its occupied pixels static where they are",
          "[static_scene]") {
  const std::string dir = test::freshDir("static_scene_ros");
  // 6x4 P5 image as map_saver writes it: 0 = occupied, 254 = free, 205 = unknown.
  const int W = 6, H = 4;
  std::string px(W * H, char(254));
  px[0 * W + 1] = char(0);    // row 0 (top), column 1
  px[3 * W + 4] = char(0);    // row 3 (bottom), column 4
  px[1 * W + 2] = char(205);  // unknown
  writeBytes(dir + "/map.pgm", "P5\n# CREATOR: map_saver.cpp 0.500 m/pix\n6 4\n255\n" + px);
  auto yaml = [&](int negate) {
    return "image: map.pgm\nresolution: 0.5\norigin: [-2.0, 1.0, 0.0]\nnegate: " +
           std::to_string(negate) + "\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  };
  test::writeFile(dir + "/map.yaml", yaml(0));
  // Pixel (column c, row r) covers x ∈ -2 + 0.5·[c, c+1], y ∈ 1 + 0.5·[H−1−r, H−r]: image row 0
  // is the top of the map, the largest y.
  auto centre = [&](int c, int r) { return V2(-2 + 0.5 * (c + 0.5), 1 + 0.5 * (H - 1 - r + 0.5)); };
  StaticScene::Options o;
  o.prior_map = dir + "/map.yaml";
  StaticScene ss(o);
  REQUIRE(ss.prior() != nullptr);
  CHECK(ss.prior()->getSizeX() == W);
  CHECK(ss.prior()->getSizeY() == H);
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < W; ++c) {
      INFO("pixel column " << c << " row " << r);
      const V2 p = centre(c, r);
      const bool occ = (r == 0 && c == 1) || (r == 3 && c == 4);
      CHECK(ss.isStatic(p.x(), p.y(), kT0) == occ);
    }
  // Just inside and outside the top-left occupied pixel's corners.
  CHECK(ss.isStatic(-1.49, 2.99, kT0));
  CHECK_FALSE(ss.isStatic(-1.51, 2.99, kT0));
  CHECK_FALSE(ss.isStatic(-1.49, 3.01, kT0));
  CHECK_FALSE(ss.isStatic(-1.49, 2.49, kT0));
  CHECK(ss.isStatic(-1.49, 2.49, kT0, 0.05));

  // negate: 1 swaps black and white.
  test::writeFile(dir + "/map.yaml", yaml(1));
  StaticScene neg(o);
  CHECK_FALSE(neg.isStatic(centre(1, 0).x(), centre(1, 0).y(), kT0));
  CHECK(neg.isStatic(centre(0, 0).x(), centre(0, 0).y(), kT0));
}

TEST_CASE("an MRPT grid map file (gzipped) is a prior map too", "[static_scene]") {
  const std::string dir = test::freshDir("static_scene_gridmap");
  mrpt::maps::COccupancyGridMap2D g(-1, 1, -1, 1, 0.1f);
  g.setPos(0.55f, -0.25f, 0.0f);  // MRPT cells hold freeness: 0 = occupied
  {
    mrpt::io::CFileGZOutputStream out(dir + "/prior.gridmap.gz");
    mrpt::serialization::archiveFrom(out) << g;
  }
  StaticScene::Options o;
  o.prior_map = dir + "/prior.gridmap.gz";
  StaticScene ss(o);
  CHECK(ss.isStatic(0.55, -0.25, kT0));
  CHECK_FALSE(ss.isStatic(0.35, -0.25, kT0));
  CHECK_FALSE(ss.isStatic(5, 5, kT0));  // off the map: unknown
}

TEST_CASE("bad prior map files give a ConfigError naming the file", "[static_scene]") {
  const std::string dir = test::freshDir("static_scene_bad");
  StaticScene::Options o;
  auto fails = [&](const std::string& file, const std::string& what) {
    o.prior_map = file;
    INFO(file);
    CHECK_THROWS_AS(StaticScene(o), ConfigError);
    CHECK_THROWS_WITH(StaticScene(o),
                      Catch::Matchers::Contains(file) && Catch::Matchers::Contains(what));
  };
  fails(dir + "/absent.yaml", "no such file");
  test::writeFile(dir + "/no_res.yaml",
                  "image: map.pgm\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                  "free_thresh: 0.196\n");
  fails(dir + "/no_res.yaml", "missing key 'resolution'");
  test::writeFile(dir + "/list.yaml", "- image\n- resolution\n");
  fails(dir + "/list.yaml", "not a ROS map_server map");
  test::writeFile(dir + "/no_image.yaml",
                  "image: gone.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                  "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  fails(dir + "/no_image.yaml", "gone.pgm not found");
  test::writeFile(dir + "/garbage.gridmap", "this is not a grid map");
  fails(dir + "/garbage.gridmap", "not a ROS map .yaml nor a serialized MRPT");
  // Bad options too.
  StaticScene::Options bad;
  bad.persist = -1;
  CHECK_THROWS_AS(StaticScene(bad), ConfigError);
}

TEST_CASE("update cost of a 768-beam scan (printed, not asserted)", "[static_scene][timing]") {
  // A 11 m x 9 m room round the robot (returns at 3-8 m) with three people in it.
  World w{{{-3, -4, 8, -4}, {8, -4, 8, 5}, {8, 5, -3, 5}, {-3, 5, -3, -4}}, {}};
  const std::vector<V2> people{{2, 1}, {4, -2}, {-1, 3}};
  for (const V2& p : people) addLegs(w, p.x(), p.y(), 0.12);
  const Frame f = scanFrame(w, kT0);
  auto perScan = [&](const StaticScene::Options& o, int n) {
    StaticScene ss(o);
    Frame g = f;
    ss.update(g, people);  // the grid's first allocation is not part of the per-scan cost
    // CPU time, not wall time: other processes share the machine.
    const std::clock_t start = std::clock();
    for (int k = 1; k <= n; ++k) {
      g.t = kT0 + k * kDt;
      ss.update(g, people);
    }
    return 1e6 * double(std::clock() - start) / CLOCKS_PER_SEC / n;
  };
  StaticScene::Options def, every_beam, coarse;
  every_beam.clear_every = 1;
  coarse.cell = 0.1;
  // The least of a few runs (cache and frequency noise). Under the sanitizers, where the time
  // means nothing, the same calls a few times each.
  const int scans = pedtrack::test::kSanitized ? 40 : 2000;
  auto best = [&](const StaticScene::Options& o) {
    double us = 1e9;
    for (int run = 0; run < 3; ++run) us = std::min(us, perScan(o, scans));
    return us;
  };
  const double a = best(def), b = best(every_beam), c = best(coarse);
  std::printf(
      "static_scene update() per 768-beam scan: %.1f us (defaults: 5 cm cells, clear_every 4), "
      "%.1f us (clear_every 1), %.1f us (10 cm cells)\n",
      a, b, c);
  // updatePoints() with a 3D sensor's 20000 obstacle points (the room's walls at 3 heights).
  std::vector<V2> pts;
  for (int k = 0; k < 20000; ++k) {
    const double a = 2 * M_PI * k / 20000;
    const double r = castRay(w, 0, 0, std::cos(a), std::sin(a));
    pts.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  double us = 1e9;
  for (int run = 0; run < 3; ++run) {
    StaticScene ss;
    ss.updatePoints(kT0, V2(0, 0), pts, people);
    const std::clock_t start = std::clock();
    const int clouds = pedtrack::test::kSanitized ? 5 : 200;
    for (int k = 1; k <= clouds; ++k) ss.updatePoints(kT0 + 0.1 * k, V2(0, 0), pts, people);
    us = std::min(us, 1e6 * double(std::clock() - start) / CLOCKS_PER_SEC / clouds);
  }
  std::printf("static_scene updatePoints() per 20000-point cloud: %.1f us\n", us);
  CHECK(a > 0);
}
