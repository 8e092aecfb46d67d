#pragma once
// Robot poses from a bag's /tf (+ /tf_static) and, where tf has no fixed→base link, its
// nav_msgs/Odometry topic. Everything is read once up front: tf data is small next to scans.
#include <mrpt/poses/CPose3D.h>
#include <rosbag/bag.h>
#include <tf2/buffer_core.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pedtrack::rosbag_source {

class BagPoses {
 public:
  BagPoses(const rosbag::Bag& bag, std::string fixed_frame, std::string base_frame,
           const std::string& odom_topic);

  /// The robot pose in the fixed frame and the sensor's mounting pose on the robot at `stamp`.
  /// Falls back (once warned) to odometry, the last known pose, or the identity.
  void lookup(const std::string& sensor_frame, const ros::Time& stamp, mrpt::poses::CPose3D& robot,
              mrpt::poses::CPose3D& mount);

  std::size_t tfCount() const { return tf_count_; }
  std::size_t odomCount() const { return odom_.size(); }

 private:
  bool tryTf(const std::string& target, const std::string& source, const ros::Time& t,
             mrpt::poses::CPose3D& out) const;
  bool odomAt(const ros::Time& t, mrpt::poses::CPose3D& out) const;
  void warnOnce(const std::string& msg);

  std::string fixed_, base_;
  std::unique_ptr<tf2::BufferCore> tf_;
  std::size_t tf_count_ = 0;
  std::vector<std::pair<ros::Time, mrpt::poses::CPose3D>> odom_;  // sorted by time
  mrpt::poses::CPose3D last_robot_;
  std::vector<std::string> warned_;
};

}  // namespace pedtrack::rosbag_source
