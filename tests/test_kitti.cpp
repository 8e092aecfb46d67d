// KITTI: the `kitti` source (scans, sequences, KITTI raw times, OXTS motion), the label and
// calibration reader, and `pedtrack eval --kitti` on the three shared HDL-64 frames.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "pedtrack/errors.h"
#include "pedtrack/eval/kitti_labels.h"
#include "pedtrack/pipeline.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
namespace fs = std::filesystem;

namespace {

void writeScan(const std::string& path, const std::vector<std::array<float, 4>>& pts) {
  std::ofstream f(path, std::ios::binary);
  for (const auto& p : pts) f.write(reinterpret_cast<const char*>(p.data()), 16);
}

std::string kittiPipeline(const std::string& file, const std::string& extra = "") {
  return "[pipeline]\nstages = source\n[source]\nplugin = kitti\nfile = " + file + "\n" + extra;
}

// KITTI raw's layout: DRIVE/velodyne_points/{data,timestamps.txt}, DRIVE/oxts/data.
std::string rawDrive(const std::string& tag, double second_lon_east_m, double second_yaw) {
  const fs::path drive = freshDir(tag);
  fs::create_directories(drive / "velodyne_points" / "data");
  fs::create_directories(drive / "oxts" / "data");
  writeScan((drive / "velodyne_points/data/0000000000.bin").string(),
            {{{5, 0, -1.7f, 0.2f}}, {{5, 1, 0, 0.4f}}, {{-3, 2, 0.5f, 0.9f}}});
  writeScan((drive / "velodyne_points/data/0000000001.bin").string(), {{{4, 0, -1.7f, 0.2f}}});
  writeFile((drive / "velodyne_points/timestamps.txt").string(),
            "2011-09-26 13:02:25.000000000\n2011-09-26 13:02:25.103000000\n");
  // One metre east at 49 deg north: a longitude step of 1 / (cos(49) R pi / 180) degrees.
  const double lat = 49, scale = std::cos(lat * M_PI / 180);
  const double dlon = second_lon_east_m / (scale * 6378137 * M_PI / 180);
  writeFile((drive / "oxts/data/0000000000.txt").string(),
            "49 8.4 100 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
  writeFile((drive / "oxts/data/0000000001.txt").string(),
            mrpt::format("49 %.12f 100 0 0 %.9f 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n",
                         8.4 + dlon, second_yaw));
  return (drive / "velodyne_points" / "data").string();
}

}  // namespace

TEST_CASE("a KITTI raw sequence replays with its times, points and OXTS motion", "[kitti]") {
  const auto frames = readAllFrames(kittiPipeline(rawDrive("kitti_raw", 1.0, 0)));
  REQUIRE(frames.size() == 2);
  CHECK(frames[1].t - frames[0].t == Approx(0.103).margin(1e-6));
  CHECK(frames[0].t == Approx(1317042145.0).margin(1e-3));  // 2011-09-26 13:02:25 UTC
  REQUIRE(frames[0].cloud().size() == 3);
  // The robot frame is on the road under the scanner (mount_z 1.73).
  CHECK(frames[0].cloud().getPointsBufferRef_z()[0] == Approx(0.03).margin(1e-5));
  CHECK(frames[0].sensor_pose.z() == Approx(1.73));
  CHECK(frames[0].has_odometry);
  // One metre east with yaw 0 (facing east): one metre forward.
  CHECK(frames[0].robot_pose.x() == Approx(0).margin(1e-9));
  CHECK(frames[1].robot_pose.x() == Approx(1.0).margin(1e-3));
  CHECK(frames[1].robot_pose.y() == Approx(0).margin(1e-3));
}

TEST_CASE("a turn of the OXTS unit swings the robot frame round the unit", "[kitti]") {
  // Turning 90 deg in place about the unit moves the scanner, 0.81 m ahead and 0.32 m to the
  // right of it: R90 (0.81, -0.32) - (0.81, -0.32) = (-0.49, 1.13).
  const auto frames = readAllFrames(kittiPipeline(rawDrive("kitti_turn", 0, M_PI / 2)));
  REQUIRE(frames.size() == 2);
  CHECK(frames[1].robot_pose.x() == Approx(-0.49).margin(1e-6));
  CHECK(frames[1].robot_pose.y() == Approx(1.13).margin(1e-6));
  CHECK(frames[1].robot_pose.yaw() == Approx(M_PI / 2));
  // oxts = none: no motion is known.
  const auto still = readAllFrames(kittiPipeline(rawDrive("kitti_none", 1, 0), "oxts = none\n"));
  CHECK_FALSE(still[1].has_odometry);
  CHECK(still[1].robot_pose.x() == 0);
}

TEST_CASE("a scan file or a folder without times plays at scan_rate", "[kitti]") {
  const std::string dir = freshDir("kitti_object");
  writeScan(dir + "/000007.bin", {{{1, 2, 3, 0.5f}}});
  writeScan(dir + "/000008.bin", {{{1, 2, 3, 0.5f}}, {{2, 2, 3, 0.5f}}});
  const auto one = readAllFrames(kittiPipeline(dir + "/000008.bin"));
  REQUIRE(one.size() == 1);
  CHECK(one[0].t == Approx(0.8));
  CHECK(one[0].cloud().size() == 2);
  CHECK_FALSE(one[0].has_odometry);
  const auto seq = readAllFrames(kittiPipeline(dir));
  REQUIRE(seq.size() == 2);
  CHECK(seq[0].t == Approx(0.7));
  // --input of a .bin or of a folder selects the kitti source.
  PipelineOverrides ov;
  ov.input = dir;
  const auto cfg = PipelineConfig::fromText("[pipeline]\nstages = source\n[source]\nplugin = sim\n",
                                            "t.ini", ov, testRegistry());
  CHECK(cfg.stages[0].params.getString("file") == fs::absolute(dir).string());
  CHECK(cfg.stages[0].descriptor->params.front().name == "file");
  CHECK(cfg.stages[0].params.has("oxts"));  // a kitti key
}

TEST_CASE("bad KITTI scans are refused naming the file", "[kitti]") {
  const std::string dir = freshDir("kitti_bad");
  writeFile(dir + "/000000.bin", std::string(20, '\0'));
  try {
    readAllFrames(kittiPipeline(dir + "/000000.bin"));
    FAIL("a 20-byte scan was read");
  } catch (const DataError& e) {
    CHECK_THAT(e.what(), Catch::Contains("000000.bin: 20 bytes is not a whole number of points"));
  }
  fs::create_directories(dir + "/empty");
  CHECK_THROWS_WITH(readAllFrames(kittiPipeline(dir + "/empty")),
                    Catch::Contains("empty: no .bin scans in the folder"));
  // A KITTI raw folder whose timestamps.txt is short.
  const std::string data = rawDrive("kitti_short", 1, 0);
  writeFile(fs::path(data).parent_path().string() + "/timestamps.txt",
            "2011-09-26 13:02:25.000000000\n");
  CHECK_THROWS_WITH(readAllFrames(kittiPipeline(data)),
                    Catch::Contains("timestamps.txt: no time for scan"));
  // An OXTS record that is not one.
  const std::string data2 = rawDrive("kitti_oxts", 1, 0);
  writeFile(fs::path(data2).parent_path().parent_path().string() + "/oxts/data/0000000001.txt",
            "49 x\n");
  CHECK_THROWS_WITH(readAllFrames(kittiPipeline(data2)),
                    Catch::Contains("0000000001.txt: line 1: expected lat lon alt roll pitch yaw"));
}

namespace {

// A calibration whose camera sees along the Velodyne's x: velo (x, y, z) = cam (-y... ) as KITTI
// mounts them, with no rectification and a 700 px focal length.
const char* kCalib =
    "P0: 700 0 600 0 0 700 180 0 0 0 1 0\nP2: 700 0 600 45 0 700 180 0 0 0 1 0\n"
    "R0_rect: 1 0 0 0 1 0 0 0 1\nTr_velo_to_cam: 0 -1 0 0 0 0 -1 0 1 0 0 -0.27\n";

}  // namespace

TEST_CASE("KITTI labels become boxes in the Velodyne frame", "[kitti]") {
  const std::string dir = freshDir("kitti_labels");
  writeFile(dir + "/calib.txt", kCalib);
  writeFile(dir + "/label.txt",
            "Pedestrian 0.00 0 -0.20 712 143 810 307 1.80 0.60 1.00 2.00 1.70 10.00 0.00\n"
            "Car 0.00 1 1.85 387 181 423 203 1.5 1.8 4.0 -3.00 1.70 20.00 1.5707963\n"
            "DontCare -1 -1 -10 503 169 590 190 -1 -1 -1 -1000 -1000 -1000 -10\n");
  const auto calib = eval::readKittiCalib(dir + "/calib.txt");
  const auto objs = eval::readKittiObjectLabels(dir + "/label.txt", calib, 3);
  REQUIRE(objs.size() == 3);
  // Camera (2, 1.7, 10): 10.27 m ahead, 2 m to the right, 1.7 m below the scanner.
  CHECK(objs[0].x == Approx(10.27));
  CHECK(objs[0].y == Approx(-2.0));
  CHECK(objs[0].z == Approx(-1.7));
  CHECK(objs[0].yaw == Approx(-M_PI / 2));  // rotation_y 0: the box's length along the camera x
  CHECK(objs[0].person());
  CHECK(objs[0].frame == 3);
  // Length 1 m across the Velodyne's y, width 0.6 m along its x.
  CHECK(objs[0].contains(10.27, -2.45, 0));
  CHECK_FALSE(objs[0].contains(10.65, -2.0, 0));
  CHECK(objs[0].contains(10.65, -2.0, 0.1));
  CHECK(std::abs(objs[1].yaw) == Approx(M_PI).margin(1e-6));  // rotation_y pi/2: along -x
  CHECK(objs[2].dontCare());
  CHECK(calib.inCameraView({10, 0, 0}));
  CHECK_FALSE(calib.inCameraView({-10, 0, 0}));
  CHECK_FALSE(calib.inCameraView({1, 5, 0}));  // 79 deg left: outside the 80 deg-wide image
  // The called clusters: one on the pedestrian, one on the car, one on nothing, one behind.
  const auto m = eval::matchKittiFrame(3, objs, calib,
                                       {{1, 10.3, -2.1, 0.9, false, -1},
                                        {2, 20.3, 3.0, 0.7, false, -1},
                                        {3, 15, 0, 0.6, false, -1},
                                        {4, -8, 0, 0.8, false, -1}},
                                       0.3);
  CHECK(m.detected_by[0] == 0);
  CHECK(m.detected_by[1] == 1);
  CHECK(m.called[1].object == 1);
  CHECK(m.called[2].object == -1);
  CHECK(m.called[2].in_view);
  CHECK_FALSE(m.called[3].in_view);
  // A label line short of values names its line.
  writeFile(dir + "/short.txt", "Pedestrian 0 0\n");
  CHECK_THROWS_WITH(eval::readKittiObjectLabels(dir + "/short.txt", calib, 0),
                    Catch::Contains("short.txt: line 1: expected 15 values, got 3"));
  writeFile(dir + "/nocalib.txt", "P2: 1 2 3\n");
  CHECK_THROWS_WITH(eval::readKittiCalib(dir + "/nocalib.txt"),
                    Catch::Contains("nocalib.txt: P2: expected 12 numbers, got 3"));
}

TEST_CASE("the HDL-64 pipeline runs on the shared KITTI frames and eval lists its persons",
          "[kitti][data]") {
  const std::string data = sharedDataDir() + "/kitti_object";
  requireData(data);
  const std::string out = freshDir("kitti_hdl64");
  const auto run =
      runHost({"run", std::string(PEDTRACK_SOURCE_DIR) + "/configs/people_3d_hdl64.ini", "--input",
               data + "/velodyne", "--out", out, "-q"});
  REQUIRE(run.exit_code == 0);
  const auto ev =
      runHost({"eval", "--kitti", data, "--detections", out + "/detections.csv", "--json"});
  REQUIRE(ev.exit_code == 0);
  CHECK(jsonValue(ev.output, "people") == 1);
  // Split from what stands beside them, the pedestrian 8.9 m ahead scores 0.80 (0.33 when
  // kept whole with the ground near their feet) and is found.
  CHECK(jsonValue(ev.output, "found") == 1);
  // Their cluster lies on them.
  bool segmented = false;
  for (const auto& l : lines(readFile(out + "/clusters.csv")))
    if (l.rfind("0.000000,0,", 0) == 0) {
      double x = 0, y = 0;
      long c = 0, n = 0;
      if (std::sscanf(l.c_str(), "0.000000,0,%ld,%ld,%lf,%lf", &c, &n, &x, &y) == 4)
        segmented |= std::hypot(x - 8.73, y + 1.86) < 0.4;
    }
  CHECK(segmented);
  // The picture with the labelled boxes and every cluster's score.
  const auto png = runHost({"render", "--rawlog", data + "/velodyne", "--run", out, "--kitti", data,
                            "--scores", "--frame", "0", "--out", out + "/f0.png", "-q"});
  CHECK(png.exit_code == 0);
  CHECK(fs::file_size(out + "/f0.png") > 10000);
  const auto bad = runHost(
      {"render", "--rawlog", data + "/velodyne", "--kitti", out, "--out", out + "/x.png", "-q"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("--kitti '" + out + "': no label_2/ folder"));
}
