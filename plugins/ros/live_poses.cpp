#include "live_poses.h"

#include <tf2/exceptions.h>

#include <algorithm>
#include <iostream>

namespace pedtrack::ros_plugins {

LivePoses::LivePoses(std::string fixed_frame, std::string base_frame,
                     rosbag_source::MountTable mounts, bool warn_unmounted, double tf_timeout)
    : fixed_(std::move(fixed_frame)),
      base_(std::move(base_frame)),
      mounts_(std::move(mounts)),
      warn_unmounted_(warn_unmounted),
      tf_timeout_(tf_timeout) {
  // Its own spin thread and callback queue: /tf keeps flowing while the source waits on it.
  listener_ = std::make_unique<tf2_ros::TransformListener>(buffer_, true);
}

LivePoses::~LivePoses() = default;

bool LivePoses::tryTf(const std::string& target, const std::string& source, const ros::Time& t,
                      double wait, mrpt::poses::CPose3D& out) {
  try {
    if (!buffer_.canTransform(target, source, t)) {
      if (wait <= 0) return false;
      ++waits_;
      if (!buffer_.canTransform(target, source, t, ros::Duration(wait))) return false;
    }
    out = rosbag_source::toPose(buffer_.lookupTransform(target, source, t));
    return true;
  } catch (const tf2::TransformException&) {
    return false;
  }
}

bool LivePoses::lookup(const std::string& sensor_frame, const std::string& topic,
                       const ros::Time& stamp, mrpt::poses::CPose3D& robot,
                       mrpt::poses::CPose3D& mount) {
  // Mounting transforms are static in practice: accept the latest when the stamp misses.
  const bool from_tf = tryTf(base_, sensor_frame, stamp, 0, mount) ||
                       tryTf(base_, sensor_frame, ros::Time(0), 0, mount);
  std::string base;
  rosbag_source::resolveMount(from_tf, mounts_, topic, base_, sensor_frame, warn_unmounted_, warn_,
                              mount, base);
  // A scan often arrives before the tf of its own instant (odometry publishes after it): wait
  // for it, but only when /tf has the link at all, so a robot without one costs no time.
  const bool linked = buffer_.canTransform(fixed_, base, ros::Time(0));
  if (linked && tryTf(fixed_, base, stamp, tf_timeout_, robot)) {
    last_robot_ = robot;
    robot_known_ = true;
  } else {
    robot = last_robot_;
    if (linked) {
      ++misses_;
      warn_("no tf from '" + fixed_ + "' to '" + base +
            "' at some scans' stamps: the last known pose is used");
    } else {
      warn_("/tf has no link from '" + fixed_ + "' to '" + base +
            "' (yet): the robot is taken as static");
    }
  }
  return robot_known_;
}

}  // namespace pedtrack::ros_plugins
