#pragma once
// Robot and sensor poses from the live /tf (tf2_ros listener) and odometry, by the rules of the
// rosbag source's BagPoses: the sensor's mount from tf, else from the INI `mounts`, else the
// identity; the robot in the fixed frame at the scan's stamp from tf, else (a robot that
// publishes no tf) from nav_msgs/Odometry, else the last known pose.
#include <mrpt/poses/CPose3D.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "bag_poses.h"  // MountTable

namespace pedtrack::ros_plugins {

class LivePoses {
 public:
  /// `tf_timeout`: how long a lookup may wait for /tf (or odometry) to reach a scan's stamp (s).
  /// `odom_topic`: nav_msgs/Odometry subscribed to for robots without a fixed→base tf; empty:
  /// none.
  LivePoses(std::string fixed_frame, std::string base_frame, rosbag_source::MountTable mounts,
            bool warn_unmounted, double tf_timeout, const std::string& odom_topic);
  ~LivePoses();

  /// The robot in the fixed frame and the sensor's mount on the robot at `stamp`. Returns
  /// whether /tf has placed the robot in the fixed frame at or before this scan.
  bool lookup(const std::string& sensor_frame, const std::string& topic, const ros::Time& stamp,
              mrpt::poses::CPose3D& robot, mrpt::poses::CPose3D& mount);

  long waits() const { return waits_; }    ///< lookups that had to wait for /tf
  long misses() const { return misses_; }  ///< robot poses /tf could not give (last one used)
  long odomPoses() const { return odom_poses_; }  ///< robot poses taken from odometry
  long odomWaits() const { return odom_waits_; }  ///< lookups that waited for odometry

 private:
  bool tryTf(const std::string& target, const std::string& source, const ros::Time& t, double wait,
             mrpt::poses::CPose3D& out);
  // The robot's odometry pose at `stamp` (BagPoses' rule: the last at or before it, the first
  // before odometry starts), once odometry has reached it or tf_timeout passed. False when no
  // odometry is published.
  bool odomAt(const ros::Time& stamp, mrpt::poses::CPose3D& out);
  void odometry(const nav_msgs::Odometry::ConstPtr& m);

  std::string fixed_, base_;
  rosbag_source::MountTable mounts_;
  bool warn_unmounted_;
  double tf_timeout_;
  tf2_ros::Buffer buffer_;
  std::unique_ptr<tf2_ros::TransformListener> listener_;
  mrpt::poses::CPose3D last_robot_;
  bool robot_known_ = false;
  long waits_ = 0, misses_ = 0, odom_poses_ = 0, odom_waits_ = 0;
  WarnOnce warn_{"ros_topic: "};
  // Odometry: its own queue and thread, as the tf listener has.
  std::string odom_topic_;
  ros::CallbackQueue odom_queue_;
  ros::Subscriber odom_sub_;
  std::unique_ptr<ros::AsyncSpinner> odom_spinner_;
  std::mutex odom_m_;
  std::condition_variable odom_cv_;
  std::deque<std::pair<ros::Time, mrpt::poses::CPose3D>> odom_;  // by stamp, the last minute
};

}  // namespace pedtrack::ros_plugins
