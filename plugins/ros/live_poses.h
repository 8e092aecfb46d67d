#pragma once
// Robot and sensor poses from the live /tf (tf2_ros listener), by the rules of the rosbag
// source's BagPoses: the sensor's mount from tf, else from the INI `mounts`, else the identity;
// the robot in the fixed frame at the scan's stamp, else the last known pose.
#include <mrpt/poses/CPose3D.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <string>
#include <vector>

#include "bag_poses.h"  // MountTable

namespace pedtrack::ros_plugins {

class LivePoses {
 public:
  /// `tf_timeout`: how long a lookup may wait for /tf to reach a scan's stamp (s).
  LivePoses(std::string fixed_frame, std::string base_frame, rosbag_source::MountTable mounts,
            bool warn_unmounted, double tf_timeout);
  ~LivePoses();

  /// The robot in the fixed frame and the sensor's mount on the robot at `stamp`. Returns
  /// whether /tf has placed the robot in the fixed frame at or before this scan.
  bool lookup(const std::string& sensor_frame, const std::string& topic, const ros::Time& stamp,
              mrpt::poses::CPose3D& robot, mrpt::poses::CPose3D& mount);

  long waits() const { return waits_; }    ///< lookups that had to wait for /tf
  long misses() const { return misses_; }  ///< robot poses /tf could not give (last one used)

 private:
  bool tryTf(const std::string& target, const std::string& source, const ros::Time& t, double wait,
             mrpt::poses::CPose3D& out);

  std::string fixed_, base_;
  rosbag_source::MountTable mounts_;
  bool warn_unmounted_;
  double tf_timeout_;
  tf2_ros::Buffer buffer_;
  std::unique_ptr<tf2_ros::TransformListener> listener_;
  mrpt::poses::CPose3D last_robot_;
  bool robot_known_ = false;
  long waits_ = 0, misses_ = 0;
  WarnOnce warn_{"ros_topic: "};
};

}  // namespace pedtrack::ros_plugins
