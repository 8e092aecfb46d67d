#include "live_poses.h"

#include <mrpt/ros1bridge/pose.h>
#include <tf2/exceptions.h>

#include <algorithm>
#include <iostream>

namespace pedtrack::ros_plugins {

LivePoses::LivePoses(std::string fixed_frame, std::string base_frame,
                     rosbag_source::MountTable mounts, bool warn_unmounted, double tf_timeout,
                     const std::string& odom_topic)
    : fixed_(std::move(fixed_frame)),
      base_(std::move(base_frame)),
      mounts_(std::move(mounts)),
      warn_unmounted_(warn_unmounted),
      tf_timeout_(tf_timeout),
      odom_topic_(odom_topic) {
  // Its own spin thread and callback queue: /tf keeps flowing while the source waits on it.
  listener_ = std::make_unique<tf2_ros::TransformListener>(buffer_, true);
  if (!odom_topic_.empty()) {
    ros::NodeHandle nh;
    ros::SubscribeOptions ops;
    ops.template init<nav_msgs::Odometry>(
        odom_topic_, 1000, [this](const nav_msgs::Odometry::ConstPtr& m) { odometry(m); });
    ops.callback_queue = &odom_queue_;
    ops.transport_hints = ros::TransportHints().tcpNoDelay();
    odom_sub_ = nh.subscribe(ops);
    odom_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &odom_queue_);
    odom_spinner_->start();
  }
}

LivePoses::~LivePoses() {
  if (odom_spinner_) odom_spinner_->stop();  // no callback into a half-destroyed object
}

void LivePoses::odometry(const nav_msgs::Odometry::ConstPtr& m) {
  const mrpt::poses::CPose3D pose = mrpt::ros1bridge::fromROS(m->pose.pose);
  {
    std::lock_guard<std::mutex> lk(odom_m_);
    // In stamp order (messages of one publisher come in order; a late one is put in place).
    auto at = odom_.end();
    while (at != odom_.begin() && m->header.stamp < std::prev(at)->first) --at;
    odom_.emplace(at, m->header.stamp, pose);
    // A minute back is more than any scan waits in the queue.
    while (odom_.size() > 2 && odom_.back().first - odom_.front().first > ros::Duration(60))
      odom_.pop_front();
  }
  odom_cv_.notify_all();
}

bool LivePoses::odomAt(const ros::Time& stamp, mrpt::poses::CPose3D& out) {
  if (odom_topic_.empty()) return false;
  std::unique_lock<std::mutex> lk(odom_m_);
  const auto reached = [&] { return !odom_.empty() && odom_.back().first >= stamp; };
  // Wait only for a topic that is published: a robot without odometry costs no time.
  if (!reached() && (!odom_.empty() || odom_sub_.getNumPublishers() > 0)) {
    ++odom_waits_;
    odom_cv_.wait_for(lk, std::chrono::duration<double>(tf_timeout_), reached);
  }
  if (odom_.empty()) return false;
  out = rosbag_source::odometryAt(odom_, stamp);
  return true;
}

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
  } else if (!linked && odomAt(stamp, robot)) {  // a robot that publishes odometry, not tf
    last_robot_ = robot;
    robot_known_ = true;
    ++odom_poses_;
  } else {
    robot = last_robot_;
    if (linked) {
      ++misses_;
      warn_("no tf from '" + fixed_ + "' to '" + base +
            "' at some scans' stamps: the last known pose is used");
    } else {
      warn_("/tf has no link from '" + fixed_ + "' to '" + base + "' (yet)" +
            (odom_topic_.empty() ? "" : " and no odometry on " + odom_topic_) +
            ": the robot is taken as static");
    }
  }
  return robot_known_;
}

}  // namespace pedtrack::ros_plugins
