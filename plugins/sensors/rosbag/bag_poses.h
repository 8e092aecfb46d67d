#pragma once
// Robot poses from a bag's /tf (+ /tf_static) and, where tf has no fixed→base link, its
// nav_msgs/Odometry topic. Everything is read once up front: tf data is small next to scans.
#include <geometry_msgs/TransformStamped.h>
#include <mrpt/poses/CPose3D.h>
#include <rosbag/bag.h>
#include <tf2/buffer_core.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pedtrack/param_table.h"
#include "pedtrack/text.h"

namespace pedtrack::rosbag_source {

/// Where a ROS source finds its robot and sensors: the keys the bag source and the live topic
/// source (ros_topic) both declare.
struct RobotFrameParams {
  std::string fixed_frame = "odom";      ///< tf frame tracking happens in
  std::string base_frame = "base_link";  ///< tf frame of the robot body
  std::string mounts;                    ///< mounting poses of sensors /tf does not place
  double merge_window = 0.1;             ///< s: messages of several topics within it are a frame
  std::string odom_topic = "/odom";      ///< nav_msgs/Odometry where tf has no fixed→base link
};
const ParamTable<RobotFrameParams>& robotFrameTable();

/// A tf transform as an MRPT pose.
mrpt::poses::CPose3D toPose(const geometry_msgs::TransformStamped& t);

/// The robot's odometry pose at `t`, from (stamp, pose) pairs sorted by stamp (not empty): the
/// last at or before `t`, the first when `t` comes before them all. The rule of both ROS sources.
template <typename Poses>
const mrpt::poses::CPose3D& odometryAt(const Poses& odom, const ros::Time& t) {
  auto it = std::upper_bound(odom.begin(), odom.end(), t,
                             [](const ros::Time& v, const auto& e) { return v < e.first; });
  return (it == odom.begin() ? it : std::prev(it))->second;
}

/// Mounting poses on the robot by topic, from the INI `mounts` key.
using MountTable = std::map<std::string, mrpt::poses::CPose3D>;

/// Parses `topic: x y z yaw_deg [pitch_deg [roll_deg]]` entries separated by ';' (m, degrees).
/// ConfigError starting with `where` and naming the bad entry for anything else.
MountTable parseMounts(const std::string& text, const std::string& where);

/// Where a sensor sits on the robot, by the rules the bag and live ROS sources share: /tf's
/// mount when `from_tf`, else the topic's `mounts` entry, else the identity, in which case
/// `base` becomes the sensor's own frame (the robot pose is then looked up for the sensor).
/// `warn` is told once when neither placed a sensor that is merged with others
/// (`warn_unmounted`: an identity mount puts one scanner on top of another).
void resolveMount(bool from_tf, const MountTable& mounts, const std::string& topic,
                  const std::string& base_frame, const std::string& sensor_frame,
                  bool warn_unmounted, WarnOnce& warn, mrpt::poses::CPose3D& mount,
                  std::string& base);

class BagPoses {
 public:
  /// `mounts`: mounting poses for topics whose frame /tf does not place on the robot;
  /// `warn_unmounted`: warn once per topic that has neither (several sensors are merged, so an
  /// identity mount puts one on top of another).
  BagPoses(const rosbag::Bag& bag, std::string fixed_frame, std::string base_frame,
           const std::string& odom_topic, MountTable mounts = {}, bool warn_unmounted = false);

  /// The robot pose in the fixed frame and the mounting pose on the robot at `stamp` of the
  /// sensor publishing `topic` in `sensor_frame`: /tf's, else the `mounts` entry of the topic.
  /// Falls back (once warned) to odometry, the last known pose, or the identity. Returns whether
  /// the bag has given a robot pose (tf to the fixed frame or odometry) at or before `stamp`.
  bool lookup(const std::string& sensor_frame, const std::string& topic, const ros::Time& stamp,
              mrpt::poses::CPose3D& robot, mrpt::poses::CPose3D& mount);

  std::size_t tfCount() const { return tf_count_; }
  std::size_t odomCount() const { return odom_.size(); }

 private:
  bool tryTf(const std::string& target, const std::string& source, const ros::Time& t,
             mrpt::poses::CPose3D& out) const;
  bool odomAt(const ros::Time& t, mrpt::poses::CPose3D& out) const;

  std::string fixed_, base_;
  MountTable mounts_;
  bool warn_unmounted_;
  std::unique_ptr<tf2::BufferCore> tf_;
  std::size_t tf_count_ = 0;
  std::vector<std::pair<ros::Time, mrpt::poses::CPose3D>> odom_;  // sorted by time
  mrpt::poses::CPose3D last_robot_;
  bool robot_known_ = false;  // a robot pose has come from tf or odometry
  WarnOnce warn_;
};

}  // namespace pedtrack::rosbag_source
