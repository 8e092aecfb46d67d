#pragma once
// Robot poses from a bag's /tf (+ /tf_static) and, where tf has no fixed→base link, its
// nav_msgs/Odometry topic. Everything is read once up front: tf data is small next to scans.
#include <mrpt/poses/CPose3D.h>
#include <rosbag/bag.h>
#include <tf2/buffer_core.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pedtrack::rosbag_source {

/// Mounting poses on the robot by topic, from the INI `mounts` key.
using MountTable = std::map<std::string, mrpt::poses::CPose3D>;

/// Parses `topic: x y z yaw_deg [pitch_deg [roll_deg]]` entries separated by ';' (m, degrees).
/// ConfigError starting with `where` and naming the bad entry for anything else.
MountTable parseMounts(const std::string& text, const std::string& where);

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
  void warnOnce(const std::string& msg);

  std::string fixed_, base_;
  MountTable mounts_;
  bool warn_unmounted_;
  std::unique_ptr<tf2::BufferCore> tf_;
  std::size_t tf_count_ = 0;
  std::vector<std::pair<ros::Time, mrpt::poses::CPose3D>> odom_;  // sorted by time
  mrpt::poses::CPose3D last_robot_;
  bool robot_known_ = false;  // a robot pose has come from tf or odometry
  std::vector<std::string> warned_;
};

}  // namespace pedtrack::rosbag_source
