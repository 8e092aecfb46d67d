// The rosbag source on the real leg_tracker bag, and `pedtrack import` of it to a rawlog.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

#include "pedtrack/pipeline.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

std::string demoBag() {
  const std::string data = sharedDataDir();
  const std::string bag =
      data.empty() ? "" : data + "/leg_tracker/demo_stationary_simple_environment.bag";
  requireData(bag);
  return bag;
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
    REQUIRE(o->getScanSize() == s.ranges.size());
    CHECK(frames[i].t == Approx(s.header.stamp.toSec()).margin(1e-6));
    for (std::size_t k = 0; k < s.ranges.size(); ++k) {
      const float r = s.ranges[k];
      const bool valid = std::isfinite(r) && r >= s.range_min && r <= s.range_max;
      if (valid) {
        ++compared;
        if (!o->getScanRangeValidity(k) || o->getScanRange(k) != r) {
          ++mismatched;
          std::cerr << "scan " << i << " beam " << k << ": bag " << r << " [" << s.range_min << ", "
                    << s.range_max << "], mrpt " << o->getScanRange(k) << " valid "
                    << o->getScanRangeValidity(k) << "\n";
        }
      }
    }
  }
  CHECK(compared > 100000);
  CHECK(mismatched == 0);
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

// A small bag: a robot driving along x at 1 m/s (odom → base_link on /tf, or nav_msgs/Odometry on
// /odom), a laser mounted at (0.2, 0, 0.3) on it (/tf_static), and a 10 Hz LaserScan.
std::string writeMovingRobotBag(const std::string& path, bool use_tf) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
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
      tf2_msgs::TFMessage tf;
      geometry_msgs::TransformStamped p;
      p.header.stamp = t;
      p.header.frame_id = "odom";
      p.child_frame_id = "base_link";
      p.transform.translation.x = 0.05 * k;
      p.transform.rotation.w = 1;
      tf.transforms.push_back(p);
      bag.write("/tf", t, tf);
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
    sensor_msgs::LaserScan s;
    s.header.stamp = ros::Time(t0 + 0.1 * k + 0.025);
    s.header.frame_id = use_tf ? "laser" : "base_link";
    s.angle_min = -1.5;
    s.angle_max = 1.5;
    s.angle_increment = 0.01;
    s.range_min = 0.1;
    s.range_max = 10;
    s.ranges.assign(301, 3.0f);
    bag.write("/scan", s.header.stamp, s);
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
  }
  const auto odom_frames = replay("rosbag", writeMovingRobotBag(dir + "/odom.bag", false));
  REQUIRE(odom_frames.size() == 15);
  // Without tf: the last odometry message at or before the scan (0.025 s earlier: 2.5 cm behind).
  CHECK(odom_frames[4].robot_pose.x() == Approx(0.5).margin(1e-6));
  CHECK(odom_frames[4].sensor_pose.x() == Approx(0.5).margin(1e-6));
}
