// The rosbag source on the real leg_tracker bags, and `pedtrack import` of one to a rawlog; robot
// poses and mounts from /tf and the INI; several scanners merged into one frame.
#include <mrpt/core/Clock.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <tuple>

#include "pedtrack/pipeline.h"
#include "pedtrack/ros_checked_message.h"
#include "pedtrack/ros_wire_check.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

std::string demoBag() {
  return requiredDataFile("leg_tracker/demo_stationary_simple_environment.bag");
}

std::vector<Frame> replay(const std::string& plugin, const std::string& file,
                          const std::string& extra = "") {
  return readAllFrames("[pipeline]\nstages = source\n[source]\nplugin = " + plugin +
                       "\nfile = " + file + "\n" + extra);
}

// The bag's own LaserScan messages, read with rosbag_storage alone.
std::vector<sensor_msgs::LaserScan> bagScans(const std::string& file) {
  rosbag::Bag bag(file, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery("/scan"));
  std::vector<sensor_msgs::LaserScan> scans;
  for (const auto& m : view)
    if (auto s = m.instantiate<sensor_msgs::LaserScan>()) scans.push_back(*s);
  return scans;
}

// The MRPT beam that looks where ROS beam k of `s` looks (MRPT's beams span the aperture
// symmetrically about the observation's own x axis, which may be turned on the laser's), or -1.
long mrptBeam(const mrpt::obs::CObservation2DRangeScan& o, const mrpt::poses::CPose3D& laser,
              const sensor_msgs::LaserScan& s, std::size_t k) {
  const double own_turn = (o.sensorPose - laser).yaw();
  const double step = o.aperture / double(o.getScanSize() - 1);
  const double ros = s.angle_min + double(k) * s.angle_increment;
  const double j = (ros - own_turn + 0.5 * o.aperture) / step;
  const long jr = std::lround(j);
  if (std::abs(j - double(jr)) > 1e-3 || jr < 0 || jr >= long(o.getScanSize())) return -1;
  return jr;
}

// Every valid return of the bag is a valid MRPT beam looking the same way with the same range,
// and MRPT has no other valid beam.
void checkSameRanges(const std::vector<Frame>& frames,
                     const std::vector<sensor_msgs::LaserScan>& scans) {
  REQUIRE(frames.size() == scans.size());
  std::size_t compared = 0, mismatched = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    REQUIRE(frames[i].observations.size() == 1);
    const auto* o =
        dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(frames[i].observations[0].get());
    REQUIRE(o != nullptr);
    const auto& s = scans[i];
    CHECK(frames[i].t == Approx(s.header.stamp.toSec()).margin(1e-6));
    const mrpt::poses::CPose3D laser = frames[i].sensorMount();
    std::size_t valid_ros = 0, valid_mrpt = 0;
    for (std::size_t j = 0; j < o->getScanSize(); ++j) valid_mrpt += o->getScanRangeValidity(j);
    for (std::size_t k = 0; k < s.ranges.size(); ++k) {
      const float r = s.ranges[k];
      const bool valid = std::isfinite(r) && r >= s.range_min && r <= s.range_max;
      if (!valid) continue;
      ++compared, ++valid_ros;
      const long j = mrptBeam(*o, laser, s, k);
      if (j < 0 || !o->getScanRangeValidity(std::size_t(j)) ||
          o->getScanRange(std::size_t(j)) != r) {
        ++mismatched;
        std::cerr << "scan " << i << " beam " << k << ": bag " << r << ", mrpt beam " << j << "\n";
      }
    }
    CHECK(valid_mrpt == valid_ros);
  }
  CHECK(compared > 100000);
  CHECK(mismatched == 0);
}

// A bag of one scan of `n` beams from angle_min by increment (radians), every range 2 m but
// NaN at `hole`.
std::string writeOneScanBag(const std::string& path, std::size_t n, double angle_min,
                            double increment, std::size_t hole) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  sensor_msgs::LaserScan scan;
  scan.header.stamp = ros::Time(1600000000.0);
  scan.header.frame_id = "laser";
  scan.angle_min = float(angle_min);
  scan.angle_increment = float(increment);
  scan.angle_max = float(angle_min + double(n - 1) * increment);
  scan.range_min = 0.02f;
  scan.range_max = 5.6f;
  scan.ranges.assign(n, 2.0f);
  scan.ranges[hole] = NAN;
  bag.write("/scan", scan.header.stamp, scan);
  bag.close();
  return path;
}

}  // namespace

TEST_CASE("the leg_tracker demo bag replays as 1265 frames whose ranges equal the bag's",
          "[rosbag]") {
  const std::string bag = demoBag();
  const auto scans = bagScans(bag);
  CHECK(scans.size() == 1265);
  checkSameRanges(replay("rosbag", bag, "topic = /scan\n"), scans);
}

TEST_CASE("a bag topic that does not exist is named with a suggestion", "[rosbag]") {
  const std::string bag = demoBag();
  CHECK_THROWS_WITH(replay("rosbag", bag, "topic = /scn\n"),
                    Catch::Contains("[source] topic: '/scn' is not in bag") &&
                        Catch::Contains("did you mean '/scan'?"));
}

TEST_CASE("pedtrack import writes the bag as a rawlog that rawlog-edit and the rawlog source read",
          "[rosbag]") {
  const std::string bag = demoBag();
  const std::string out = freshDir("rosbag_import") + "/demo.rawlog";
  const auto r = runHost({"import", bag, "--out", out, "--topic", "/scan", "-q"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("wrote 1265 observations"));
  const auto info = runShell("rawlog-edit --info -i '" + out + "'");
  CHECK(info.exit_code == 0);
  CHECK_THAT(
      info.output,
      Catch::Matches("(.|\n)*Sensor \\(Label/Occurs/Rate/Durat\\.\\) : +/scan / +1265 /(.|\n)*"));
  checkSameRanges(replay("rawlog", out), bagScans(bag));
}

namespace {

// odom → base_link at (x, 0), heading +x, on /tf at t.
void writeOdomTf(rosbag::Bag& bag, const ros::Time& t, double x) {
  tf2_msgs::TFMessage tf;
  geometry_msgs::TransformStamped p;
  p.header.stamp = t;
  p.header.frame_id = "odom";
  p.child_frame_id = "base_link";
  p.transform.translation.x = x;
  p.transform.rotation.w = 1;
  tf.transforms.push_back(p);
  bag.write("/tf", t, tf);
}

// A LaserScan of 301 beams over ±1.5 rad, every range 3 m.
sensor_msgs::LaserScan flatScan(const ros::Time& stamp, const std::string& frame) {
  sensor_msgs::LaserScan s;
  s.header.stamp = stamp;
  s.header.frame_id = frame;
  s.angle_min = -1.5;
  s.angle_max = 1.5;
  s.angle_increment = 0.01;
  s.range_min = 0.1;
  s.range_max = 10;
  s.ranges.assign(301, 3.0f);
  return s;
}

// A small bag: a robot driving along x at 1 m/s (odom → base_link on /tf, or nav_msgs/Odometry on
// /odom), a laser mounted at (0.2, 0, 0.3) on it (/tf_static), and a 10 Hz LaserScan.
std::string writeMovingRobotBag(
    const std::string& path, bool use_tf,
    rosbag::compression::CompressionType compression = rosbag::compression::Uncompressed) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setCompression(compression);
  const double t0 = 1600000000.0;
  tf2_msgs::TFMessage mount;
  geometry_msgs::TransformStamped m;
  m.header.stamp = ros::Time(t0);
  m.header.frame_id = "base_link";
  m.child_frame_id = "laser";
  m.transform.translation.x = 0.2;
  m.transform.translation.z = 0.3;
  m.transform.rotation.w = 1;
  mount.transforms.push_back(m);
  if (use_tf) bag.write("/tf_static", ros::Time(t0), mount);
  for (int k = 0; k <= 40; ++k) {  // pose messages every 50 ms
    const ros::Time t(t0 + 0.05 * k);
    if (use_tf) {
      writeOdomTf(bag, t, 0.05 * k);
    } else {
      nav_msgs::Odometry o;
      o.header.stamp = t;
      o.header.frame_id = "odom";
      o.pose.pose.position.x = 0.05 * k;
      o.pose.pose.orientation.w = 1;
      bag.write("/odom", t, o);
    }
  }
  for (int k = 1; k <= 15; ++k) {  // scans at 10 Hz, stamped between pose messages
    const ros::Time t(t0 + 0.1 * k + 0.025);
    bag.write("/scan", t, flatScan(t, use_tf ? "laser" : "base_link"));
  }
  bag.close();
  return path;
}

}  // namespace

TEST_CASE("robot poses come from interpolated /tf with the sensor mounting or else from /odom",
          "[rosbag]") {
  const std::string dir = freshDir("rosbag_tf");
  const auto tf_frames = replay("rosbag", writeMovingRobotBag(dir + "/tf.bag", true));
  REQUIRE(tf_frames.size() == 15);
  for (std::size_t i = 0; i < tf_frames.size(); ++i) {
    const double x = 0.1 * (i + 1) + 0.025;  // 1 m/s along x, interpolated between tf messages
    CHECK(tf_frames[i].robot_pose.x() == Approx(x).margin(1e-6));
    CHECK(tf_frames[i].sensor_pose.x() == Approx(x + 0.2).margin(1e-6));
    CHECK(tf_frames[i].sensor_pose.z() == Approx(0.3).margin(1e-6));
    CHECK(tf_frames[i].has_odometry);
  }
  const auto odom_frames = replay("rosbag", writeMovingRobotBag(dir + "/odom.bag", false));
  REQUIRE(odom_frames.size() == 15);
  // Without tf: the last odometry message at or before the scan (0.025 s earlier: 2.5 cm behind).
  CHECK(odom_frames[4].robot_pose.x() == Approx(0.5).margin(1e-6));
  CHECK(odom_frames[4].sensor_pose.x() == Approx(0.5).margin(1e-6));
  CHECK(odom_frames[4].has_odometry);
}

namespace {

// Two scanners on the moving robot of writeMovingRobotBag: `left` placed by /tf_static at
// (0.2, 0.3, 0.1) facing left, `right` (no tf) 40 ms after it; both at 10 Hz, 10 turns.
std::string writeTwoScannerBag(const std::string& path) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const double t0 = 1600000000.0;
  tf2_msgs::TFMessage mount;
  geometry_msgs::TransformStamped m;
  m.header.stamp = ros::Time(t0);
  m.header.frame_id = "base_link";
  m.child_frame_id = "left";
  m.transform.translation.x = 0.2;
  m.transform.translation.y = 0.3;
  m.transform.translation.z = 0.1;
  m.transform.rotation.z = std::sin(M_PI / 4);  // yaw 90°
  m.transform.rotation.w = std::cos(M_PI / 4);
  mount.transforms.push_back(m);
  bag.write("/tf_static", ros::Time(t0), mount);
  for (int k = 0; k <= 24; ++k) {
    const ros::Time t(t0 + 0.05 * k);
    writeOdomTf(bag, t, 0.05 * k);
  }
  for (int k = 1; k <= 10; ++k)
    for (const auto& [topic, frame, dt] :
         {std::tuple<std::string, std::string, double>{"/left_scan", "left", 0.01},
          {"/right_scan", "right", 0.05}}) {
      const ros::Time t(t0 + 0.1 * k + dt);
      bag.write(topic, t, flatScan(t, frame));
    }
  bag.close();
  return path;
}

}  // namespace

TEST_CASE("several topics merge into frames with each scanner's mounting pose", "[rosbag]") {
  const std::string bag = writeTwoScannerBag(freshDir("rosbag_merge") + "/two.bag");
  const std::string topics = "topic = /left_scan,/right_scan\n";
  const auto frames = replay("rosbag", bag, topics + "mounts = /right_scan: 0.2 -0.3 0.1 -90\n");
  REQUIRE(frames.size() == 10);
  const double t0 = 1600000000.0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    const double tl = 0.1 * (i + 1) + 0.01, tr = tl + 0.04;  // robot x = t - t0 (1 m/s)
    REQUIRE(f.observations.size() == 2);
    REQUIRE(f.sensors.size() == 2);
    CHECK(f.t == Approx(t0 + tr).margin(1e-6));  // the newest stamp
    CHECK(f.robot_pose.x() == Approx(tr).margin(1e-6));
    // Left from /tf_static, right from `mounts`, each where the robot was at its own stamp.
    CHECK(f.sensors[0].label == "/left_scan");
    CHECK(f.sensors[0].pose.distanceTo(mrpt::poses::CPose3D(tl + 0.2, 0.3, 0.1, M_PI / 2, 0, 0)) <
          1e-6);
    CHECK(f.sensors[1].label == "/right_scan");
    CHECK(f.sensors[1].pose.distanceTo(mrpt::poses::CPose3D(tr + 0.2, -0.3, 0.1, -M_PI / 2, 0, 0)) <
          1e-6);
    CHECK(f.sensor_pose.distanceTo(f.sensors[0].pose) < 1e-12);
    // In the robot frame at t the left scan was taken 4 cm further back.
    mrpt::poses::CPose3D left_on_robot;
    f.observations[0]->getSensorPose(left_on_robot);
    CHECK(left_on_robot.x() == Approx(0.2 - 0.04).margin(1e-6));
  }
  // A window shorter than the 40 ms between the scanners, or 0: one message per frame.
  CHECK(replay("rosbag", bag, topics + "merge_window = 0.03\n").size() == 20);
  const auto single = replay("rosbag", bag, topics + "merge_window = 0\n");
  REQUIRE(single.size() == 20);
  for (std::size_t i = 1; i < single.size(); ++i) {
    CHECK(single[i].observations.size() == 1);
    CHECK(single[i].sensors.size() == 1);
    CHECK(single[i].t >= single[i - 1].t);
  }
}

TEST_CASE("a scan not centred on the laser's axis keeps each return on its own bearing",
          "[rosbag]") {
  // leg_tracker's benchmark Hokuyo: 245 beams from -34.5 deg to 51.3 deg. MRPT's own conversion
  // (ros1bridge) wrapped the beams past one end round to the other and misplaced the rest by
  // whole beams.
  const std::string dir = freshDir("rosbag_asymmetric");
  struct Case {
    std::size_t n;
    double angle_min, increment;
  };
  for (const Case c : {Case{245, -0.6013204, 0.00613592}, Case{512, -M_PI / 2, 0.00613592},
                       Case{100, 0.3, -0.01}}) {
    INFO("angle_min " << c.angle_min << ", increment " << c.increment);
    const std::size_t hole = 17;
    const auto frames =
        replay("rosbag", writeOneScanBag(dir + "/one.bag", c.n, c.angle_min, c.increment, hole));
    REQUIRE(frames.size() == 1);
    const auto& cloud = frames[0].cloud();
    REQUIRE(cloud.size() == c.n - 1);  // no return made up, the NaN one left out
    // Every point 2 m away on the bearing of its beam (beam k at angle_min + k increment).
    std::vector<double> bearings;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      float x, y, z;
      cloud.getPoint(i, x, y, z);
      CHECK(std::hypot(x, y) == Approx(2.0).margin(1e-5));
      bearings.push_back(std::atan2(y, x));
    }
    std::sort(bearings.begin(), bearings.end());
    std::vector<double> want;
    for (std::size_t k = 0; k < c.n; ++k)
      if (k != hole) want.push_back(c.angle_min + double(k) * c.increment);
    std::sort(want.begin(), want.end());
    for (std::size_t i = 0; i < want.size(); ++i)
      CHECK(bearings[i] == Approx(want[i]).margin(1e-5));
  }
}

TEST_CASE("a bad mounts entry is named with its key", "[rosbag]") {
  const std::string bag = writeTwoScannerBag(freshDir("rosbag_mounts") + "/two.bag");
  const std::string topics = "topic = /left_scan,/right_scan\n";
  CHECK_THROWS_WITH(replay("rosbag", bag, topics + "mounts = /right_scan: 0.2 -0.3 x 90\n"),
                    Catch::Contains("[source] mounts: bad entry '/right_scan: 0.2 -0.3 x 90'") &&
                        Catch::Contains("'x' is not a number"));
  CHECK_THROWS_WITH(
      replay("rosbag", bag, topics + "mounts = /right_scan: 1 2 3 4; /rigth_scan 1\n"),
      Catch::Contains("[source] mounts: bad entry '/rigth_scan 1'"));
  CHECK_THROWS_WITH(replay("rosbag", bag, topics + "mounts = /right_scan: 1 2 3\n"),
                    Catch::Contains("3 numbers, not 4 to 6"));
  CHECK_THROWS_WITH(replay("rosbag", bag, topics + "mounts = /rigth_scan: 1 2 3 4\n"),
                    Catch::Contains("[source] mounts: topic '/rigth_scan' is not a scan topic") &&
                        Catch::Contains("did you mean '/right_scan'?"));
}

TEST_CASE("negative_2.bag's three scanners merge into frames of three observations", "[rosbag]") {
  const std::string data = sharedDataDir();
  requireData(data.empty() ? "" : data + "/leg_tracker/negative_2.bag");
  // The config's own path: its model and other relative paths resolve against configs/.
  const std::string config = std::string(PEDTRACK_SOURCE_DIR) + "/configs/negative_2_merged.ini";
  std::string text = readFile(config);
  const std::string var = "${PEDTRACK_DATA}";
  text.replace(text.find(var), var.size(), data);
  const auto frames = readAllFrames(text, config);
  // 435 left, 435 rear and 434 right scans, always in that order: the last turn lacks its right.
  REQUIRE(frames.size() == 435);
  std::size_t full = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    if (i > 0) CHECK(f.t >= frames[i - 1].t);
    if (f.observations.size() != 3) continue;
    ++full;
    REQUIRE(f.sensors.size() == 3);
    CHECK(f.sensors[0].label == "/left_scan");
    CHECK(f.sensors[1].label == "/rear_scan");
    CHECK(f.sensors[2].label == "/right_scan");
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = a + 1; b < 3; ++b)
        CHECK(f.sensors[a].pose.distanceTo(f.sensors[b].pose) > 0.4);
    CHECK(f.t == Approx(mrpt::Clock::toDouble(f.observations[2]->timestamp)).margin(1e-6));
  }
  CHECK(full == 434);
  // The mounts of the config reached the observations (no /tf, no odometry: robot = fixed).
  mrpt::poses::CPose3D rear;
  frames[0].observations[1]->getSensorPose(rear);
  CHECK(rear.x() == Approx(-0.27).margin(1e-9));
  // The config's yaw (whole beams: these Hokuyo scans are centred to within a beam).
  CHECK(mrpt::math::wrapToPi(rear.yaw()) ==
        Approx(mrpt::math::wrapToPi(176.576 * M_PI / 180)).margin(1e-6));
}

namespace {

// The bag's top-level records: (position, header fields as raw bytes, data position, data size).
struct RawRecord {
  std::size_t at, data_at, data_size;
  std::string header;
};
std::vector<RawRecord> rawRecords(const std::string& bytes) {
  std::vector<RawRecord> out;
  auto u32 = [&](std::size_t p) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + p, 4);
    return v;
  };
  for (std::size_t p = 13; p + 8 <= bytes.size();) {
    const std::uint32_t hl = u32(p);
    RawRecord r{p, p + 8 + hl, u32(p + 4 + hl), bytes.substr(p + 4, hl)};
    out.push_back(r);
    p = r.data_at + r.data_size;
  }
  return out;
}

std::string replayError(const std::string& bag) {
  try {
    replay("rosbag", bag);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("bz2 and lz4 chunks pass the bag check and replay as the uncompressed bag", "[rosbag]") {
  const std::string dir = freshDir("rosbag_compressed");
  const auto plain = replay("rosbag", writeMovingRobotBag(dir + "/none.bag", true));
  for (const auto c : {rosbag::compression::BZ2, rosbag::compression::LZ4}) {
    const auto frames = replay("rosbag", writeMovingRobotBag(dir + "/c.bag", true, c));
    REQUIRE(frames.size() == plain.size());
    CHECK(frames.back().robot_pose.x() == Approx(plain.back().robot_pose.x()).margin(1e-9));
  }
}

TEST_CASE("a bag whose lengths point past their records is refused before rosbag reads it",
          "[rosbag]") {
  // rosbag_storage reads a record header's fields by their own lengths, and a message at
  // whatever offset the index names (fuzz_rosbag: reads past its buffers, under ASan a crash).
  const std::string dir = freshDir("rosbag_damaged");
  const std::string good = readFile(writeMovingRobotBag(dir + "/good.bag", true));
  // A message record's op field (inside the uncompressed chunk) claiming 200 bytes.
  std::string field = good;
  const std::size_t op = field.find(std::string("\x04\x00\x00\x00op=\x02", 8));
  REQUIRE(op != std::string::npos);
  field[op] = char(200);
  writeFile(dir + "/field.bag", field);
  const std::string e1 = replayError(dir + "/field.bag");
  CHECK_THAT(e1, Catch::Contains("[source] file: cannot open bag '" + dir + "/field.bag'") &&
                     Catch::Contains("a header field longer than its header at byte"));
  CHECK(e1.find('\n') == std::string::npos);
  // An index entry one byte past its message.
  std::string index = good;
  std::size_t entries = 0;
  for (const RawRecord& r : rawRecords(good))
    if (r.header.find(std::string("op=\x04", 4)) != std::string::npos && !entries)
      entries = r.data_at;
  REQUIRE(entries > 0);
  index[entries + 8] = char(index[entries + 8] + 1);  // entry 0: time (8 bytes), offset (4)
  writeFile(dir + "/index.bag", index);
  CHECK_THAT(replayError(dir + "/index.bag"),
             Catch::Contains("an index entry that names no message of its chunk"));
  // A chunk info naming a position that is no chunk.
  std::string info = good;
  std::size_t chunk_pos = 0;
  for (const RawRecord& r : rawRecords(good)) {
    const std::size_t f = r.header.find("chunk_pos=");
    if (f != std::string::npos) chunk_pos = r.at + 4 + f + 10;
  }
  REQUIRE(chunk_pos > 0);
  info[chunk_pos] = char(info[chunk_pos] + 1);
  writeFile(dir + "/info.bag", info);
  CHECK_THAT(replayError(dir + "/info.bag"), Catch::Contains("a chunk info naming no chunk"));
  // The undamaged bag still replays.
  CHECK(replayError(dir + "/good.bag").empty());
}

namespace {

template <class M>
std::vector<std::uint8_t> serialized(const M& m) {
  std::vector<std::uint8_t> out(ros::serialization::serializationLength(m));
  ros::serialization::OStream s(out.data(), static_cast<std::uint32_t>(out.size()));
  ros::serialization::serialize(s, m);
  return out;
}

void putU32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  std::memcpy(&b[at], &v, 4);
}

}  // namespace

TEST_CASE("a message's counts are checked against its bytes before roscpp sizes by them",
          "[rosbag][fuzz]") {
  // roscpp resizes an array to the count in front of it before reading it: fuzz_rosbag's /tf
  // message claimed 1,644,167,425 transforms (223 GB).
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";  // header: 12 bytes, then 4 + 5
  scan.ranges = {1, 2, 3};
  scan.intensities = {7};
  std::vector<std::uint8_t> b = serialized(scan);
  CHECK(rosWireProblem("sensor_msgs/LaserScan", b.data(), b.size()) == "");
  const auto back = checkedDeserialize<sensor_msgs::LaserScan>(b.data(), b.size());
  CHECK(back->ranges == scan.ranges);
  CHECK(back->intensities == scan.intensities);
  const std::size_t ranges_at = 12 + 4 + 5 + 7 * 4;  // after the header and 7 float32
  putU32(b, ranges_at, 1000000000);
  CHECK(rosWireProblem("sensor_msgs/LaserScan", b.data(), b.size()) ==
        "ranges count 1000000000 does not fit in the 20 bytes left");
  CHECK_THROWS_WITH(checkedDeserialize<sensor_msgs::LaserScan>(b.data(), b.size()),
                    "a sensor_msgs/LaserScan message that does not fit its 73 bytes: ranges count "
                    "1000000000 does not fit in the 20 bytes left");
  putU32(b, ranges_at, 4);  // one float more: the intensity 7.0 is read as the next count
  CHECK(rosWireProblem("sensor_msgs/LaserScan", b.data(), b.size()) ==
        "intensities count 1088421888 does not fit in the 0 bytes left");

  tf2_msgs::TFMessage tf;
  tf.transforms.resize(2);
  tf.transforms[1].child_frame_id = "laser";
  std::vector<std::uint8_t> t = serialized(tf);
  CHECK(rosWireProblem("tf2_msgs/TFMessage", t.data(), t.size()) == "");
  putU32(t, 0, 3);  // a third transform of at least 76 bytes does not fit
  CHECK(rosWireProblem("tf2_msgs/TFMessage", t.data(), t.size()) ==
        "transforms count 3 does not fit in the 157 bytes left");
  putU32(t, 0, 2);
  t.pop_back();  // the last transform cut short
  CHECK(rosWireProblem("tf2_msgs/TFMessage", t.data(), t.size()) ==
        "transform (56 bytes) past the message's end");
  putU32(t, 0, 1644167425);
  CHECK(rosWireProblem("tf2_msgs/TFMessage", t.data(), t.size()) ==
        "transforms count 1644167425 does not fit in the " + std::to_string(t.size() - 4) +
            " bytes left");

  sensor_msgs::PointCloud2 cloud;
  cloud.fields.resize(1);
  cloud.fields[0].name = "x";
  cloud.data.assign(12, 0);
  std::vector<std::uint8_t> c = serialized(cloud);
  CHECK(rosWireProblem("sensor_msgs/PointCloud2", c.data(), c.size()) == "");
  const std::size_t data_at = 12 + 4 + 8 + 4 + (4 + 1 + 4 + 1 + 4) + 1 + 4 + 4;
  putU32(c, data_at, 14);  // 12 bytes of data and is_dense are left
  CHECK(rosWireProblem("sensor_msgs/PointCloud2", c.data(), c.size()) ==
        "data count 14 does not fit in the 13 bytes left");
  // A type pedtrack does not read is not checked.
  CHECK(rosWireProblem("std_msgs/String", c.data(), 2) == "");
}

TEST_CASE("a bag found by fuzzing (a /tf message claiming 1.6 G transforms) is one error",
          "[rosbag][fuzz]") {
  const std::string bag = std::string(PEDTRACK_SOURCE_DIR) +
                          "/fuzz/regressions/fuzz_rosbag/tf_transforms_count_huge.bag";
  const std::string e = replayError(bag);
  CHECK_THAT(e, Catch::Contains("tf_transforms_count_huge.bag: reading /tf and odometry: a "
                                "tf2_msgs/TFMessage message that does not fit its 94 bytes: "
                                "transforms count 1644167425 does not fit"));
  CHECK(e.find('\n') == std::string::npos);
  // A scan whose ranges count is patched in a bag: the error names the file and the message.
  const std::string dir = freshDir("rosbag_counts");
  std::string good = readFile(writeMovingRobotBag(dir + "/good.bag", true));
  // The bag's scans have 301 ranges of 3 m (serialized: the count, then 301 float32).
  std::string count(8, '\0');
  const std::uint32_t n = 301;
  const float three = 3.0f;
  std::memcpy(&count[0], &n, 4);
  std::memcpy(&count[4], &three, 4);
  const std::size_t at = good.find(count);
  REQUIRE(at != std::string::npos);
  good[at + 3] = char(0x40);
  writeFile(dir + "/ranges.bag", good);
  CHECK_THAT(replayError(dir + "/ranges.bag"),
             Catch::Contains(dir + "/ranges.bag: message ") &&
                 Catch::Contains("a sensor_msgs/LaserScan message that does not fit its"));
}
