// The `rosbag` source replaying a detector's geometry_msgs/PoseArray topics as frames of
// detections: placed in the fixed frame through /tf and the sensor's mount, the header stamp or
// else the bag's record time, a real leg_tracker bag's labelled legs, and mixed topics refused.
#include <geometry_msgs/PoseArray.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const double kT0 = 1600000000.0;

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child,
                                          const ros::Time& t, double x, double z) {
  geometry_msgs::TransformStamped p;
  p.header.stamp = t;
  p.header.frame_id = parent;
  p.child_frame_id = child;
  p.transform.translation.x = x;
  p.transform.translation.z = z;
  p.transform.rotation.w = 1;
  return p;
}

// A robot driving along x at 1 m/s (odom -> base_link on /tf every 50 ms), a laser at (0.2, 0,
// 0.3) on it, and a detector's PoseArray on /people at 10 Hz in the laser's frame: a person 3 m
// ahead facing left (yaw 90 degrees) and one at (2, 1) with no heading (a zero quaternion). The
// last message has no header stamp; it was recorded at t0 + 0.6 s.
std::string writePeopleBag(const std::string& path) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  tf2_msgs::TFMessage mount;
  mount.transforms.push_back(transform("base_link", "laser", ros::Time(kT0), 0.2, 0.3));
  bag.write("/tf_static", ros::Time(kT0), mount);
  for (int k = 0; k <= 20; ++k) {
    const ros::Time t(kT0 + 0.05 * k);
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(transform("odom", "base_link", t, 0.05 * k, 0));
    bag.write("/tf", t, tf);
  }
  for (int k = 1; k <= 6; ++k) {
    const ros::Time t(kT0 + 0.1 * k);
    geometry_msgs::PoseArray a;
    a.header.stamp = k < 6 ? t : ros::Time();
    a.header.frame_id = "laser";
    geometry_msgs::Pose facing;
    facing.position.x = 3;
    facing.orientation.z = std::sin(M_PI / 4);
    facing.orientation.w = std::cos(M_PI / 4);
    geometry_msgs::Pose plain;
    plain.position.x = 2;
    plain.position.y = 1;
    a.poses = {facing, plain};
    bag.write("/people", t, a);
    sensor_msgs::LaserScan s;
    s.header = a.header;
    s.angle_min = -1, s.angle_max = 1, s.angle_increment = 0.5, s.range_max = 10;
    s.ranges.assign(5, 3.0f);
    bag.write("/scan", t, s);
  }
  bag.close();
  return path;
}

std::string bagPipeline(const std::string& bag, const std::string& topic) {
  return "[pipeline]\nstages = source\n[source]\nplugin = rosbag\nfile = " + bag +
         "\ntopic = " + topic + "\nfixed_frame = odom\n";
}

}  // namespace

TEST_CASE("a PoseArray topic replays as detections placed by /tf and the mount", "[rosbag]") {
  const std::string bag = writePeopleBag(freshDir("rosbag_people") + "/people.bag");
  const auto frames = readAllFrames(bagPipeline(bag, "/people"));
  REQUIRE(frames.size() == 6);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Frame& f = frames[k];
    INFO("frame " << k);
    CHECK(f.observations.empty());
    CHECK(f.has_odometry);
    // Stamped t0 + 0.1 (k + 1); the last by its record time, which is the same.
    CHECK(f.t == Approx(kT0 + 0.1 * double(k + 1)).margin(1e-6));
    const double robot_x = 0.1 * double(k + 1);  // 1 m/s since t0
    REQUIRE(f.detections.size() == 2);
    CHECK(f.detections[0].x == Approx(robot_x + 0.2 + 3).margin(1e-6));
    CHECK(f.detections[0].y == Approx(0).margin(1e-6));
    CHECK(f.detections[0].yaw == Approx(M_PI / 2).margin(1e-6));
    CHECK(f.detections[0].score == 1);
    CHECK(f.detections[1].x == Approx(robot_x + 0.2 + 2).margin(1e-6));
    CHECK(f.detections[1].y == Approx(1).margin(1e-6));
    CHECK(f.detections[1].yaw == Approx(0).margin(1e-12));
  }
  // A frame of detections has no range data, and that is no fault.
  const std::string out = freshDir("rosbag_people_run");
  writeFile(out + "/p.ini", bagPipeline(bag, "/people"));
  const auto run = runHost({"run", out + "/p.ini", "--out", out + "/r", "-q"});
  REQUIRE(run.exit_code == 0);
  CHECK(jsonValue(readFile(out + "/r/run.json"), "empty_frames") == 0);
  CHECK(lines(readFile(out + "/r/detections.csv")).size() == 13);
  // Scans and detections are not mixed in one replay.
  CHECK_THROWS_WITH(readAllFrames(bagPipeline(bag, "/scan,/people")),
                    Catch::Contains("topic: give scan topics or geometry_msgs/PoseArray topics"));
}

TEST_CASE("leg_tracker's labelled legs replay as detections, one frame a message",
          "[rosbag][data]") {
  const std::string bag = sharedDataDir() + "/leg_tracker/positive_1_extracted.bag";
  requireData(bag);
  rosbag::Bag b(bag, rosbag::bagmode::Read);
  rosbag::View view(b, rosbag::TopicQuery(std::vector<std::string>{"/leg_cluster_positions"}));
  std::size_t messages = 0, legs = 0;
  for (const rosbag::MessageInstance& m : view) {
    ++messages;
    legs += m.instantiate<geometry_msgs::PoseArray>()->poses.size();
  }
  const auto frames = readAllFrames(bagPipeline(bag, "/leg_cluster_positions"));
  REQUIRE(frames.size() == messages);
  std::size_t detections = 0;
  for (const Frame& f : frames) detections += f.detections.size();
  CHECK(detections == legs);
  CHECK(legs > 300);
}
