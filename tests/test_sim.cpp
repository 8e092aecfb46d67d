// Simulator: motion scripts, ray-cast geometry against hand computation, the VLP-16 as MRPT
// decodes it, occlusion, point density over distance, determinism, the CLI and the plugin.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>

#include "pedtrack/errors.h"
#include "pedtrack/eval/object_table.h"
#include "pedtrack/sim/simulator.h"
#include "pedtrack/velodyne_decode.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::sim;
using namespace pedtrack::test;

namespace {

constexpr double kDeg = M_PI / 180.0;

SimFrame firstFrame(const std::string& text) {
  Simulator s(scenarioFromText(text, "t.ini"));
  SimFrame f;
  REQUIRE(s.next(f));
  return f;
}

const mrpt::obs::CObservation2DRangeScan& scanOf(const SimFrame& f) {
  auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(f.observations.back());
  REQUIRE(scan);
  return *scan;
}

// A 2D UTM-30LX at torso height (1.0 m), no noise, one person standing still.
std::string scan2D(const std::string& people) {
  return "[scenario]\nduration = 0.1\n[sensor]\nmodel = utm30lx\nz = 1.0\nrange_noise = 0\n" +
         people;
}

// Range along the beam at angle `a` from the origin to the ellipse centred at (cx, 0) with
// semi-axis `u` along x and `v` along y: solve ((t cos a - cx)/u)² + (t sin a / v)² = 1.
double rangeToEllipse(double a, double cx, double u, double v) {
  const double A = std::pow(std::cos(a) / u, 2) + std::pow(std::sin(a) / v, 2);
  const double B = -2 * cx * std::cos(a) / (u * u), C = cx * cx / (u * u) - 1;
  return (-B - std::sqrt(B * B - 4 * A * C)) / (2 * A);
}

int visible(const SimFrame& f, int id) {
  for (const auto& r : f.truth)
    if (r.id == id) return r.visible_points;
  return -1;
}

}  // namespace

TEST_CASE("motion scripts give the commanded distance, time and heading", "[sim]") {
  MotionLimits lim;
  lim.speed = 1.2;
  lim.accel = 0.8;
  lim.turn_rate = 90 * kDeg;
  // 2 m at 1.2 m/s with 0.8 m/s² ramps: 2/1.2 + 1.2/0.8 = 3.1667 s.
  auto walk = Trajectory::fromScript("walk 2", 0, 0, 0, lim, "t");
  CHECK(walk.duration() == Approx(2 / 1.2 + 1.2 / 0.8).margin(0.02));
  CHECK(walk.at(10).x == Approx(2).margin(1e-6));
  CHECK(std::hypot(walk.at(1.58).vx, walk.at(1.58).vy) == Approx(1.2).margin(0.01));
  auto turn = Trajectory::fromScript("turn 90", 1, 1, 0, lim, "t");
  CHECK(turn.duration() == Approx(1.0).margin(0.02));
  CHECK(turn.at(5).yaw == Approx(M_PI / 2).margin(1e-3));
  CHECK(turn.at(5).x == Approx(1));
  auto circle = Trajectory::fromScript("arc 1 360", 0, 0, 0, lim, "t");
  CHECK(circle.at(circle.duration() + 1).x == Approx(0).margin(1e-3));
  CHECK(std::abs(circle.at(circle.duration() / 2).y) == Approx(2).margin(0.01));
  auto side = Trajectory::fromScript("right 1", 0, 0, 0, lim, "t");
  CHECK(side.at(10).y == Approx(-1).margin(1e-6));
  CHECK(side.at(10).yaw == Approx(0).margin(1e-9));  // sidestepping keeps the facing
  CHECK_THROWS_WITH(Trajectory::fromScript("walk 1; jump 2", 0, 0, 0, lim, "f.ini: [p] script"),
                    Catch::Contains("f.ini: [p] script: unknown motion command 'jump'"));
  CHECK_THROWS_WITH(Trajectory::fromScript("walk x", 0, 0, 0, lim, "f.ini: [p] script"),
                    Catch::Contains("'x' is not a number"));
  // Bounds that keep the sampling finite (fuzz_scenario: a stop of 2e51 s overflowed the sample
  // count; fuzz/regressions/fuzz_scenario/stop_duration_overflow.ini).
  CHECK_THROWS_WITH(Trajectory::fromScript("walk 1; stop 2e51", 0, 0, 0, lim, "f.ini: [p] script"),
                    Catch::Contains("'stop 2e51': duration (s) beyond 36000"));
  CHECK_THROWS_WITH(Trajectory::fromScript("walk nan", 0, 0, 0, lim, "t"),
                    Catch::Contains("'nan' is not a number"));
  CHECK_THROWS_WITH(Trajectory::fromScript("walk 1e5", 0, 0, 0, lim, "t"),
                    Catch::Contains("distance (m) beyond 10000"));
  CHECK_THROWS_WITH(Trajectory::fromScript("turn 4000", 0, 0, 0, lim, "t"),
                    Catch::Contains("angle (deg) beyond 3600"));
  std::string far;
  for (int i = 0; i < 11; ++i) far += "walk 10000; ";
  CHECK_THROWS_WITH(Trajectory::fromScript(far, 0, 0, 0, lim, "t"),
                    Catch::Contains("the script walks farther than 100 km"));
  CHECK_THROWS_WITH(Trajectory::fromScript("stop 30000; stop 30000", 0, 0, 0, lim, "t"),
                    Catch::Contains("the script lasts longer than 36000 s"));
}

TEST_CASE("a 2D beam hits a known torso ellipse at the hand-computed range", "[sim]") {
  // Person facing +x at (3, 0): beta (0.12) along x, alpha (0.20) across.
  const SimFrame f = firstFrame(scan2D("[person.a]\nx = 3\ny = 0\nalpha = 0.2\nbeta = 0.12\n"));
  const auto& scan = scanOf(f);
  const int n = int(scan.getScanSize());
  REQUIRE(n == 1081);
  CHECK(scan.aperture == Approx(270 * kDeg).margin(1e-6));
  const int mid = n / 2;
  CHECK(scan.getScanRange(mid) == Approx(3 - 0.12).margin(0.0006));
  for (int k : {-6, -3, 3, 6}) {  // 0.75°..1.5° off axis: still on the torso
    const double a = -scan.aperture / 2 + (mid + k) * scan.aperture / (n - 1);
    INFO("beam " << k);
    REQUIRE(scan.getScanRangeValidity(mid + k));
    CHECK(scan.getScanRange(mid + k) == Approx(rangeToEllipse(a, 3, 0.12, 0.2)).margin(0.0006));
  }
  // Turned 90°: alpha now lies along the beam, and the arm hanging outside the shoulder
  // (radius 0.045 m at alpha + 0.045 from the centre) is what the beam meets first.
  const SimFrame g =
      firstFrame(scan2D("[person.a]\nx = 3\ny = 0\nyaw = 90\nalpha = 0.2\nbeta = 0.12\n"));
  CHECK(scanOf(g).getScanRange(mid) == Approx(3 - 0.2 - 0.045 - 0.045).margin(0.0006));
  CHECK(visible(g, 1) > 10);
}

TEST_CASE("a person behind another is occluded", "[sim]") {
  const std::string front = "[person.a]\nx = 3\ny = 0\n", back = "[person.b]\nx = 6\ny = 0.1\n";
  const SimFrame alone = firstFrame(scan2D(back));
  const SimFrame both = firstFrame(scan2D(front + back));
  CHECK(visible(alone, 1) > 20);
  CHECK(visible(both, 1) > 20);  // the front person
  CHECK(visible(both, 2) == 0);  // hidden in the front person's shadow at torso height
  // The VLP-16 sees the taller parts over the shoulder only where rings pass above it.
  const std::string v = "[scenario]\nduration = 0.1\n[sensor]\nmodel = vlp16\nz = 1.2\n";
  const int far_alone = visible(firstFrame(v + "[person.b]\nx = 6\ny = 0.1\n"), 1);
  const int far_behind = visible(firstFrame(v + front + back), 2);
  CHECK(far_alone > 50);
  CHECK(far_behind < far_alone / 3);
}

TEST_CASE("VLP-16 rings decode through MRPT at the datasheet elevations and azimuths", "[sim]") {
  // Sensor in a closed 10 m x 10 m room with 6 m walls and a pole ahead-left at (3, 2).
  const std::string text =
      "[scenario]\nduration = 0.1\n[sensor]\nmodel = vlp16\nz = 1.0\nrange_noise = 0\n"
      "[object.n]\ntype = wall\nx = -5\ny = 5\nx2 = 5\ny2 = 5\nheight = 6\n"
      "[object.s]\ntype = wall\nx = -5\ny = -5\nx2 = 5\ny2 = -5\nheight = 6\n"
      "[object.e]\ntype = wall\nx = 5\ny = -5\nx2 = 5\ny2 = 5\nheight = 6\n"
      "[object.w]\ntype = wall\nx = -5\ny = -5\nx2 = -5\ny2 = 5\nheight = 6\n"
      "[object.p]\ntype = pole\nx = 3\ny = 2\nradius = 0.1\nheight = 3\n";
  const SimFrame f = firstFrame(text);
  auto velo = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(f.observations.back());
  REQUIRE(velo);
  CHECK(velo->scan_packets.size() == 75);  // 1800 columns of 0.2°, 24 per packet
  const auto pts = decodeVelodyne(*velo);
  CHECK(pts.size() == 16 * 1800);  // closed room: every ray returns
  std::map<int, std::pair<double, int>> elev;
  for (const auto& q : pts) {
    auto& e = elev[q.laser];
    e.first += std::atan2(q.z, std::hypot(q.x, q.y));
    e.second++;
  }
  REQUIRE(elev.size() == 16);
  const int expected[16] = {-15, 1, -13, 3, -11, 5, -9, 7, -7, 9, -5, 11, -3, 13, -1, 15};
  for (const auto& [laser, e] : elev) {
    INFO("laser " << laser);
    CHECK(e.second == 1800);
    CHECK(e.first / e.second / kDeg == Approx(expected[laser]).margin(0.01));
  }
  // MRPT's own decoder (first firing of each block only, see velodyne_decode.h) yields a
  // subset of the same points: our azimuth and elevation decoding agrees with MRPT's.
  velo->generatePointCloud();
  const auto& pc = velo->point_cloud;
  CHECK(pc.size() == 16 * 900);
  std::size_t same = 0;
  for (std::size_t i = 0; i < pc.size(); i += 97) {
    for (const auto& q : pts)
      if (std::abs(q.x - pc.x[i]) < 2e-3 && std::abs(q.y - pc.y[i]) < 2e-3 &&
          std::abs(q.z - pc.z[i]) < 2e-3) {
        ++same;
        break;
      }
  }
  CHECK(same == (pc.size() + 96) / 97);
  // The pole at (3, 2) is seen ahead-left (MRPT +y is left), none of it mirrored at (3, -2).
  int at_pole = 0, mirrored = 0;
  for (const auto& q : pts) {
    if (q.z < -0.5) continue;  // the ground ring passes near both
    if (std::hypot(q.x - 3, q.y - 2) < 0.15) ++at_pole;
    if (std::hypot(q.x - 3, q.y + 2) < 0.15) ++mirrored;
  }
  CHECK(at_pole > 20);
  CHECK(mirrored == 0);
  // Points on the east wall (x = 5 - 0.075) lie on it, whatever the ring.
  for (const auto& q : pts)
    if (std::abs(q.y) < 1 && q.x > 4 && q.z > -0.9) {
      REQUIRE(q.x == Approx(4.925).margin(0.004));
    }
}

TEST_CASE("frame clouds of simulated VLP-16 scans are in the robot frame", "[sim]") {
  const std::string dir = freshDir("sim_cloud");
  writeFile(dir + "/s.ini",
            "[scenario]\nduration = 0.2\n[sensor]\nmodel = vlp16\nz = 1.2\nrange_noise = 0\n");
  const auto frames = readAllFrames(
      "[pipeline]\nstages = source\n[source]\nplugin = sim\n"
      "scenario = " +
      dir + "/s.ini\n");
  REQUIRE(frames.size() == 2);
  const auto& cloud = frames[0].cloud();
  REQUIRE(cloud.size() > 1000);  // the 8 downward rings hit the ground
  double zmax = -1e9, zmin = 1e9;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    float x, y, z;
    cloud.getPoint(i, x, y, z);
    zmax = std::max<double>(zmax, z);
    zmin = std::min<double>(zmin, z);
  }
  CHECK(zmin == Approx(0).margin(0.01));  // ground at z = 0 below the 1.2 m mount
  CHECK(zmax == Approx(0).margin(0.01));
}

TEST_CASE("returns on a person fall with distance as in P1 Fig. 1", "[sim]") {
  std::vector<int> counts;
  for (double d : {5.0, 10.0, 20.0, 30.0}) {
    const std::string text =
        "[scenario]\nduration = 0.1\n[sensor]\nmodel = vlp16\nz = 1.0\nrange_noise = 0\n"
        "[person.a]\nyaw = 90\ny = 0\nx = " +
        std::to_string(d) + "\n";
    counts.push_back(visible(firstFrame(text), 1));
  }
  INFO(counts[0] << " " << counts[1] << " " << counts[2] << " " << counts[3]);
  CHECK(counts[0] > counts[1]);
  CHECK(counts[1] > counts[2]);
  CHECK(counts[2] > counts[3]);
  CHECK(counts[3] > 0);
  // Columns shrink as 1/d and rings as 1/d: about 1/d² overall.
  CHECK(double(counts[0]) / counts[2] > 8);
}

TEST_CASE("scenario errors name file, section and key", "[sim]") {
  CHECK_THROWS_WITH(scenarioFromText("[scenario]\nduration = 1\n[persn.a]\nx = 1\n", "s.ini"),
                    Catch::Contains("s.ini: [persn.a]: unknown section"));
  CHECK_THROWS_WITH(
      scenarioFromText("[scenario]\nduration = 1\n[person.a]\nx = 1\ny = 0\nspead = 2\n", "s.ini"),
      Catch::Contains("s.ini: [person.a] spead: unknown key") && Catch::Contains("'speed'"));
  CHECK_THROWS_WITH(scenarioFromText("[scenario]\nduration = 1\n[person.a]\ny = 0\n", "s.ini"),
                    Catch::Contains("s.ini: [person.a] x: missing required key"));
  CHECK_THROWS_WITH(
      scenarioFromText("[scenario]\nduration = 1\n[sensor]\nmodel = vlp32\n", "s.ini"),
      Catch::Contains("s.ini: [sensor] model:"));
  CHECK_THROWS_WITH(scenarioFromText("[scenario]\nduration = 1\n[person.a]\nx = 0\ny = 0\n"
                                     "path = script\nscript = walk 1; fly 2\n",
                                     "s.ini"),
                    Catch::Contains("s.ini: [person.a] script: unknown motion command 'fly'"));
}

TEST_CASE("pedtrack sim: same seed same bytes, another seed other noise", "[sim][cli]") {
  const std::string dir = freshDir("sim_seed");
  const std::string scen = std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/p0_c_path.ini";
  for (const char* sub : {"a", "b"})
    REQUIRE(runHost({"sim", scen, "--out", dir + "/" + sub, "-q"}).exit_code == 0);
  REQUIRE(runHost({"sim", scen, "--out", dir + "/c", "--seed", "7", "-q"}).exit_code == 0);
  CHECK(readFile(dir + "/a/sim.rawlog") == readFile(dir + "/b/sim.rawlog"));
  CHECK(readFile(dir + "/a/truth.csv") == readFile(dir + "/b/truth.csv"));
  CHECK(readFile(dir + "/a/sim.rawlog") != readFile(dir + "/c/sim.rawlog"));
  CHECK(readFile(dir + "/a/truth.csv") == readFile(dir + "/c/truth.csv"));  // truth has no noise
  const auto r = runHost({"sim", dir + "/missing.ini", "--out", dir + "/d"});
  CHECK(r.exit_code == 2);
  CHECK(r.output == "error: " + dir + "/missing.ini: scenario file not found\n");
}

TEST_CASE("every shipped scenario simulates and rawlog-edit reads its rawlog", "[sim][cli]") {
  const std::string dir = freshDir("sim_all");
  int scenarios = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PEDTRACK_SOURCE_DIR) +
                                                               "/configs/scenarios")) {
    if (entry.path().extension() != ".ini") continue;
    ++scenarios;
    const std::string name = entry.path().stem().string(), out = dir + "/" + name;
    INFO(name);
    // Under the sanitizers (scripts/check.sh) the simulator runs ~40 times slower: the first
    // second of each scenario there, every scenario whole in a normal build.
    std::vector<std::string> args{"sim", entry.path().string(), "--out", out, "-q"};
#ifdef PEDTRACK_SANITIZED
    args.insert(args.end(), {"--duration", "1"});
#endif
    const auto r = runHost(args);
    REQUIRE(r.exit_code == 0);
    Scenario sc = loadScenario(entry.path().string());
#ifdef PEDTRACK_SANITIZED
    sc.duration = std::min(sc.duration, 1.0);
#endif
    const long frames = std::lround(std::floor(sc.duration * sc.sensor.rate + 1e-9));
    CHECK(lines(readFile(out + "/truth.csv")).size() > std::size_t(frames));
    const auto info = runShell("rawlog-edit --info -i " + out + "/sim.rawlog");
    REQUIRE(info.exit_code == 0);
    CHECK_THAT(info.output,
               Catch::Contains(sc.sensor.label + " /") && Catch::Contains("ODOMETRY /"));
    // The sensor's row of the table: "LABEL /  <count> /<rate> /<duration>", count right-aligned.
    CHECK_THAT(info.output, Catch::Matches("[\\s\\S]*" + sc.sensor.label + " / +" +
                                           std::to_string(frames) + " /[\\s\\S]*"));
  }
  CHECK(scenarios >= 11);
}

TEST_CASE("the sim plugin drives a pipeline and writes the truth", "[sim][cli]") {
  const std::string dir = freshDir("sim_plugin");
  writeFile(dir + "/p.ini", "[pipeline]\nstages = source\n[source]\nplugin = sim\nscenario = " +
                                std::string(PEDTRACK_SOURCE_DIR) +
                                "/configs/scenarios/p4_crossing.ini\ntruth = " + dir +
                                "/truth.csv\n");
  const auto r = runHost({"run", dir + "/p.ini", "--out", dir + "/out"});
  REQUIRE(r.exit_code == 0);
  const std::string json = readFile(dir + "/out/run.json");
  CHECK(jsonNumber(json, "frames_read") == 80);
  CHECK(lines(readFile(dir + "/truth.csv")).size() == 1 + 2 * 80);
  // Same truth as `pedtrack sim` writes.
  REQUIRE(runHost({"sim", std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/p4_crossing.ini",
                   "--out", dir + "/sim", "-q"})
              .exit_code == 0);
  CHECK(readFile(dir + "/truth.csv") == readFile(dir + "/sim/truth.csv"));
  // truth = auto (the default) puts it next to tracks.csv.
  writeFile(dir + "/auto.ini", "[pipeline]\nstages = source\n[source]\nplugin = sim\nscenario = " +
                                   std::string(PEDTRACK_SOURCE_DIR) +
                                   "/configs/scenarios/p4_crossing.ini\n");
  REQUIRE(runHost({"run", dir + "/auto.ini", "--out", dir + "/auto"}).exit_code == 0);
  CHECK(readFile(dir + "/auto/truth.csv") == readFile(dir + "/sim/truth.csv"));
  // A truth path that cannot be written stops the run before anything is written.
  const auto bad = runHost({"run", dir + "/auto.ini", "--set", "source.truth=/proc/no/truth.csv",
                            "--out", dir + "/bad"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.output ==
        "error: " + dir + "/auto.ini: [source] truth: cannot write '/proc/no/truth.csv'\n");
  CHECK_FALSE(std::filesystem::exists(dir + "/bad"));
  // The P4 crossing hides the far person for about 1 s: 5 frames at 5 Hz with no return.
  int hidden = 0;
  for (const auto& row : readObjectTable(dir + "/truth.csv").rows)
    if (row.id == 1 && row.visible_points == 0) ++hidden;
  CHECK(hidden == 5);
  // The simulator benchmark runs the same scenario (its figures are for Release builds only).
  const auto bench =
      runHost({"bench", "--scenario",
               std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/p4_crossing.ini"});
  CHECK(bench.exit_code == 0);
  CHECK_THAT(bench.output,
             Catch::Contains("simulation (sim source") && Catch::Contains(": 80 frames"));
}

TEST_CASE("ground tilt, range noise and dropout are what the scenario says", "[sim]") {
  // Ground rising 5° towards +x: every VLP-16 ground return lies on z = tan(5°)·x.
  {
    const SimFrame f = firstFrame(
        "[scenario]\nduration = 0.1\n[sensor]\nmodel = vlp16\nz = 1.0\n"
        "range_noise = 0\n[ground]\ntilt = 5\ndirection = 0\n");
    auto velo =
        std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(f.observations.back());
    REQUIRE(velo);
    const auto pts = decodeVelodyne(*velo);
    REQUIRE(pts.size() > 5000);
    double worst = 0;
    for (const auto& q : pts)
      worst = std::max(worst, std::abs(q.z + 1.0 - std::tan(5 * kDeg) * q.x));
    CHECK(worst < 0.01);
  }
  // A wall 5 m ahead: residuals of a 2 cm sensor are N(0, 0.02²); 30 % dropout loses 30 %.
  auto wall = [](const std::string& sensor_keys) {
    return "[scenario]\nduration = 0.1\n[sensor]\nmodel = utm30lx\nz = 1.0\n" + sensor_keys +
           "[object.w]\ntype = wall\nx = 5\ny = -10\nx2 = 5\ny2 = 10\nthickness = 0.2\n";
  };
  const SimFrame noisy = firstFrame(wall("range_noise = 0.02\n"));
  const auto& scan = scanOf(noisy);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::size_t i = 0; i < scan.getScanSize(); ++i) {
    const double a = -scan.aperture / 2 + i * scan.aperture / (scan.getScanSize() - 1);
    if (std::abs(a) > 30 * kDeg || !scan.getScanRangeValidity(i)) continue;
    const double e = scan.getScanRange(i) - 4.9 / std::cos(a);
    sum += e;
    sum2 += e * e;
    ++n;
  }
  REQUIRE(n > 230);
  CHECK(sum / n == Approx(0).margin(0.005));
  CHECK(std::sqrt(sum2 / n) == Approx(0.02).margin(0.004));
  // The frame is kept: the scan is a reference into it (ASan caught it read after the frame died).
  const auto dropped_frame = firstFrame(wall("dropout = 0.3\n"));
  const auto& dropped = scanOf(dropped_frame);
  int lost = 0;
  for (int i = 540 - 120; i <= 540 + 120; ++i) lost += !dropped.getScanRangeValidity(i);
  CHECK(lost / 241.0 == Approx(0.3).margin(0.07));
}

TEST_CASE("sweep_motion poses a walker when the VLP-16 beam passes it", "[sim]") {
  // A walker 3 m to the left (azimuth +90°) at 1 m/s along +x. The VLP-16 turns clockwise from
  // forward, so it reaches +90° after 270° of its 0.1 s turn: the walker is seen 75 ms later,
  // 7.5 cm further on.
  auto meanX = [](const std::string& sweep) {
    Simulator s(scenarioFromText(
        "[scenario]\nduration = 3\n[sensor]\nmodel = vlp16\nz = 1.0\nrange_noise = 0\n"
        "sweep_motion = " +
            sweep + "\n[person.a]\nx = -2\ny = 3\npath = straight\nlength = 10\nspeed = 1\n",
        "t.ini"));
    SimFrame f;
    for (int k = 0; k <= 25; ++k) REQUIRE(s.next(f));
    auto velo =
        std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(f.observations.back());
    double sum = 0;
    int n = 0;
    for (const auto& q : decodeVelodyne(*velo))
      if (q.y > 2.5 && q.z > -0.7) {
        sum += q.x;
        ++n;
      }
    REQUIRE(n > 50);
    return sum / n;
  };
  CHECK(meanX("true") - meanX("false") == Approx(0.075).margin(0.015));
}

TEST_CASE("the social-force crowd keeps people apart and away from objects", "[sim]") {
  const Scenario sc =
      loadScenario(std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/crowd.ini");
  REQUIRE(sc.people.size() == 20);
  double closest = 1e9, moved = 0;
  for (double t = 0; t <= sc.duration; t += 0.1) {
    for (std::size_t i = 0; i < sc.people.size(); ++i) {
      const MotionSample a = sc.people[i].path.at(t);
      moved += std::hypot(a.vx, a.vy) * 0.1;
      for (std::size_t j = i + 1; j < sc.people.size(); ++j) {
        const MotionSample b = sc.people[j].path.at(t);
        closest = std::min(closest, std::hypot(a.x - b.x, a.y - b.y));
      }
    }
  }
  double from_objects = 1e9;
  for (double t = 0; t <= sc.duration; t += 0.1)
    for (const auto& p : sc.people) {
      const MotionSample a = p.path.at(t);
      for (const Primitive& o : sc.objects) {
        if (o.shape != Shape::EllipticCylinder || o.z0 > 0.5) continue;  // poles, bins, trunks
        from_objects = std::min(from_objects, std::hypot(a.x - o.a.x(), a.y - o.a.y()) - o.ru);
      }
    }
  CHECK(closest > 0.35);                                // torso centres stay apart (README: 0.52 m)
  CHECK(from_objects > 0.15);                           // nobody walks through a pole, bin or trunk
  CHECK(moved / sc.people.size() > 0.5 * sc.duration);  // and they do walk (m per person)
}

TEST_CASE("legs swing at the gait's cadence and step length", "[sim]") {
  // Truth legs of a walker seen at 50 Hz: the sagittal separation of the legs at the scan height
  // crosses zero `cadence` times a second, with amplitude step_length scaled to that height.
  auto gait = [](const std::string& extra, double& crossings_per_s, double& amplitude) {
    Simulator s(scenarioFromText(
        "[scenario]\nduration = 8\nleg_height = 0.4\n[sensor]\nmodel = custom2d\nz = 0.4\n"
        "fov = 180\nresolution = 1\nmax_range = 10\nrate = 50\n"
        "[person.a]\nx = 1\ny = 2\npath = straight\nlength = 30\nspeed = 1.2\n"
        "step_length = 0.6\n" +
            extra,
        "t.ini"));
    SimFrame f;
    double last = 0, peak = 0;
    int crossings = 0;
    for (int k = 0; s.next(f); ++k) {
      const TruthRow& r = f.truth.at(0);
      const double sep = r.left_leg_x - r.right_leg_x;  // walking along +x
      if (k >= 150) {                                   // from 3 s: at full speed
        if (k > 150 && (sep > 0) != (last > 0)) ++crossings;
        peak = std::max(peak, std::abs(sep));
      }
      last = sep;
    }
    crossings_per_s = crossings / 5.0;
    amplitude = peak;
  };
  const double u = (0.4 - 0.08) / (0.50 * 1.70 - 0.08);  // leg_height along ankle→hip
  double rate = 0, amp = 0;
  gait("", rate, amp);
  CHECK(rate == Approx(1.2 / 0.6).margin(0.25));  // derived cadence: speed / step length
  CHECK(amp == Approx(0.6 * (1 - u)).margin(0.01));
  gait("cadence = 1.6\n", rate, amp);
  CHECK(rate == Approx(1.6).margin(0.25));
}

TEST_CASE("motion respects facing_rate at corners and accel at speed changes", "[sim]") {
  MotionLimits lim;
  lim.speed = 1.2;
  lim.accel = 0.5;
  lim.facing_rate = 30 * kDeg;
  // A 90° goto corner: the body turns at no more than facing_rate, and the walker slows down.
  const auto corner = Trajectory::fromScript("goto 3 0; goto 3 3", 0, 0, 0, lim, "t");
  double max_rate = 0, min_speed_mid = 1e9, max_accel = 0;
  const auto& S = corner.samples();
  for (std::size_t k = 1; k < S.size(); ++k) {
    max_rate = std::max(max_rate,
                        std::abs(mrpt::math::wrapToPi(S[k].yaw - S[k - 1].yaw)) / Trajectory::kDt);
    if (std::hypot(S[k].x - 3, S[k].y) < 0.05)
      min_speed_mid = std::min(min_speed_mid, std::hypot(S[k].vx, S[k].vy));
  }
  CHECK(max_rate <= 30 * kDeg * 1.001);
  CHECK(min_speed_mid < 0.7);  // (1 + cos 90°) / 2 of 1.2 m/s
  // speed 1.2 → 0.3 within one run: the deceleration stays within accel.
  const auto slow = Trajectory::fromScript("walk 3; speed 0.3; walk 1", 0, 0, 0, lim, "t");
  const auto& T = slow.samples();
  for (std::size_t k = 2; k + 2 < T.size(); ++k) {
    const double v0 = std::hypot(T[k - 2].vx, T[k - 2].vy),
                 v1 = std::hypot(T[k + 2].vx, T[k + 2].vy);
    max_accel = std::max(max_accel, std::abs(v1 - v0) / (4 * Trajectory::kDt));
  }
  CHECK(max_accel < 0.5 * 1.05);
  CHECK(slow.at(slow.duration() + 1).x == Approx(4));
}

TEST_CASE("odometry error is a random walk of the documented size at any frame rate", "[sim]") {
  // 10 m straight at 1 m/s with odometry_noise 0.1 m/√m: RMS position error 0.1·√10 = 0.32 m.
  auto rms = [](int rate) {
    double sum2 = 0;
    const int runs = 60;
    for (int seed = 1; seed <= runs; ++seed) {
      Simulator s(scenarioFromText(
          "[scenario]\nduration = 13\nseed = " + std::to_string(seed) +
              "\n[sensor]\nmodel = custom2d\nfov = 90\nresolution = 10\nmax_range = 5\nrate = " +
              std::to_string(rate) +
              "\n[robot]\nscript = walk 10\nspeed = 1\nodometry_noise = 0.1\n",
          "t.ini"));
      SimFrame f;
      while (s.next(f)) {
      }
      sum2 += std::pow(f.robot_odometry.x() - f.robot_true.x(), 2) +
              std::pow(f.robot_odometry.y() - f.robot_true.y(), 2);
    }
    return std::sqrt(sum2 / runs);
  };
  const double at5 = rms(5), at40 = rms(40);
  INFO(at5 << " " << at40);
  CHECK(at5 == Approx(0.1 * std::sqrt(10.0)).epsilon(0.3));
  CHECK(at40 == Approx(0.1 * std::sqrt(10.0)).epsilon(0.3));
}

TEST_CASE("truth is in the odometry frame, world positions alongside", "[sim]") {
  // With drifting odometry, x,y is where the person is relative to the robot's belief.
  Simulator s(scenarioFromText(
      "[scenario]\nduration = 5\n[sensor]\nmodel = utm30lx\nz = 1.0\nrange_noise = 0\n"
      "[robot]\nscript = walk 4\nspeed = 1\nodometry_noise = 0.2\nodometry_yaw_drift = 0.05\n"
      "[person.a]\nx = 6\ny = 1\n",
      "t.ini"));
  SimFrame f;
  while (s.next(f)) {
  }
  const TruthRow& r = f.truth.at(0);
  CHECK(r.world_x == Approx(6));
  CHECK(r.world_y == Approx(1));
  double rx = 0, ry = 0, ox = 0, oy = 0, sz = 0;
  f.robot_true.inverseComposePoint(6, 1, 0, rx, ry, sz);
  f.robot_odometry.composePoint(rx, ry, 0, ox, oy, sz);
  CHECK(r.x == Approx(ox).margin(1e-9));
  CHECK(r.y == Approx(oy).margin(1e-9));
  CHECK(std::hypot(r.x - 6, r.y - 1) > 1e-3);  // the odometry did drift
}

TEST_CASE("clutter robot_clearance keeps drawn objects off the robot's path", "[sim]") {
  // 40 poles drawn in a 10 x 4 m strip the robot drives down the middle of: without the key
  // some stand in its way, with it every one is at least 0.6 m (surface) from the path.
  auto nearest = [](const std::string& clearance) {
    const Scenario sc = scenarioFromText(
        "[scenario]\nduration = 12\nseed = 5\n[sensor]\nmodel = custom2d\nz = 0.4\nfov = 180\n"
        "resolution = 1\nmax_range = 10\nrate = 10\n[robot]\nscript = walk 10\nspeed = 1\n"
        "[clutter]\ncount = 40\narea = 0 -2 10 2\ntypes = pole\n" +
            clearance,
        "t.ini");
    REQUIRE(sc.objects.size() == 40);
    double d = 1e9;
    for (const MotionSample& m : sc.robot.path.samples())
      for (const Primitive& o : sc.objects)
        d = std::min(d, std::hypot(m.x - o.a.x(), m.y - o.a.y()) - o.ru);
    return d;
  };
  CHECK(nearest("") < 0.3);
  CHECK(nearest("robot_clearance = 0.6\n") >= 0.6);
}
