#include "bag_poses.h"

#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/ros1bridge/pose.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/view.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/ros_checked_message.h"
#include "pedtrack/text.h"

namespace pedtrack::rosbag_source {
mrpt::poses::CPose3D toPose(const geometry_msgs::TransformStamped& t) {
  const auto& q = t.transform.rotation;
  const auto& p = t.transform.translation;
  return mrpt::poses::CPose3D(
      mrpt::poses::CPose3DQuat(p.x, p.y, p.z, mrpt::math::CQuaternionDouble(q.w, q.x, q.y, q.z)));
}

MountTable parseMounts(const std::string& text, const std::string& where) {
  MountTable out;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ';')) {
    entry = trim(entry);
    if (entry.empty()) continue;
    const auto bad = [&](const std::string& why) {
      return ConfigError(where + ": bad entry '" + entry + "': " + why +
                         " (expected 'topic: x y z yaw_deg [pitch_deg [roll_deg]]')");
    };
    const auto colon = entry.find(':');
    if (colon == std::string::npos) throw bad("no ':' after the topic");
    const std::string topic = trim(entry.substr(0, colon));
    if (topic.empty()) throw bad("no topic");
    std::vector<double> v;
    for (const auto& tok : splitList(entry.substr(colon + 1))) {
      char* end = nullptr;
      const double x = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end || !std::isfinite(x))
        throw bad("'" + tok + "' is not a number");
      v.push_back(x);
    }
    if (v.size() < 4 || v.size() > 6) throw bad(std::to_string(v.size()) + " numbers, not 4 to 6");
    v.resize(6, 0.0);
    if (!out.emplace(topic, mrpt::poses::CPose3D(v[0], v[1], v[2], v[3] * M_PI / 180,
                                                 v[4] * M_PI / 180, v[5] * M_PI / 180))
             .second)
      throw ConfigError(where + ": topic '" + topic + "' is given twice");
  }
  return out;
}

BagPoses::BagPoses(const rosbag::Bag& bag, std::string fixed_frame, std::string base_frame,
                   const std::string& odom_topic, MountTable mounts, bool warn_unmounted)
    : fixed_(std::move(fixed_frame)),
      base_(std::move(base_frame)),
      mounts_(std::move(mounts)),
      warn_unmounted_(warn_unmounted) {
  rosbag::View all(bag);
  // Keep the whole bag's history: scans are looked up at their own stamps.
  const double span = std::max(1.0, (all.getEndTime() - all.getBeginTime()).toSec() + 10.0);
  tf_ = std::make_unique<tf2::BufferCore>(ros::Duration(span));
  rosbag::View tf_view(
      bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static", "tf", "tf_static"}));
  for (const rosbag::MessageInstance& m : tf_view) {
    auto msg = checkedInstantiate<tf2_msgs::TFMessage>(m);
    if (!msg) continue;
    const bool is_static = m.getTopic().find("tf_static") != std::string::npos;
    for (const auto& t : msg->transforms) {
      if (tf_->setTransform(t, "bag", is_static)) ++tf_count_;
    }
  }
  if (!odom_topic.empty()) {
    rosbag::View odom_view(bag, rosbag::TopicQuery(odom_topic));
    for (const rosbag::MessageInstance& m : odom_view) {
      auto msg = checkedInstantiate<nav_msgs::Odometry>(m);
      if (msg) odom_.emplace_back(msg->header.stamp, mrpt::ros1bridge::fromROS(msg->pose.pose));
    }
    std::stable_sort(odom_.begin(), odom_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
  }
}

bool BagPoses::tryTf(const std::string& target, const std::string& source, const ros::Time& t,
                     mrpt::poses::CPose3D& out) const {
  if (tf_count_ == 0) return false;
  try {
    out = toPose(tf_->lookupTransform(target, source, t));
    return true;
  } catch (const tf2::TransformException&) {
    return false;
  }
}

bool BagPoses::odomAt(const ros::Time& t, mrpt::poses::CPose3D& out) const {
  if (odom_.empty()) return false;
  out = odometryAt(odom_, t);
  return true;
}

void resolveMount(bool from_tf, const MountTable& mounts, const std::string& topic,
                  const std::string& base_frame, const std::string& sensor_frame,
                  bool warn_unmounted, WarnOnce& warn, mrpt::poses::CPose3D& mount,
                  std::string& base) {
  base = base_frame;
  if (from_tf) return;
  const auto ini = mounts.find(topic);
  if (ini != mounts.end()) {
    mount = ini->second;  // relative to the robot body: the robot pose is still fixed ← base
    return;
  }
  mount = mrpt::poses::CPose3D();
  base = sensor_frame;
  if (warn_unmounted)
    warn("topic '" + topic + "': neither /tf ('" + base_frame + "' to '" + sensor_frame +
         "') nor `mounts` places the sensor on the robot: its mount is taken as the identity");
}

bool BagPoses::lookup(const std::string& sensor_frame, const std::string& topic,
                      const ros::Time& stamp, mrpt::poses::CPose3D& robot,
                      mrpt::poses::CPose3D& mount) {
  // Mounting transforms are static in practice: accept the latest when the stamp misses.
  const bool from_tf =
      tryTf(base_, sensor_frame, stamp, mount) || tryTf(base_, sensor_frame, ros::Time(0), mount);
  std::string base;
  resolveMount(from_tf, mounts_, topic, base_, sensor_frame, warn_unmounted_, warn_, mount, base);
  if (!from_tf && !warn_unmounted_ && base == sensor_frame && tf_count_ > 0 &&
      sensor_frame != base_)
    warn_("no tf from '" + base_ + "' to sensor frame '" + sensor_frame +
          "': the sensor frame is taken as the robot frame");
  if (tryTf(fixed_, base, stamp, robot)) {
    last_robot_ = robot;
    robot_known_ = true;
  } else if (odomAt(stamp, robot)) {
    last_robot_ = robot;
    robot_known_ = true;
  } else {
    robot = last_robot_;
    if (tf_count_ == 0 && odom_.empty())
      warn_("the bag has neither /tf nor odometry: the sensor is taken as static");
    else
      warn_("no tf from '" + fixed_ + "' to '" + base +
            "' at some scans: the last known pose is used");
  }
  return robot_known_;
}

const ParamTable<RobotFrameParams>& robotFrameTable() {
  using P = RobotFrameParams;
  static const auto t =
      ParamTable<P>()
          .text(&P::fixed_frame, "fixed_frame", "tf frame tracking happens in (odom, map, ...)")
          .text(&P::base_frame, "base_frame", "tf frame of the robot body")
          .text(&P::mounts, "mounts",
                "mounting poses on base_frame of topics /tf does not place: 'topic: x y z "
                "yaw_deg [pitch_deg [roll_deg]]' (m, deg), entries separated by ';' written "
                "right after a number (' ;' starts an INI comment)")
          .real(&P::merge_window, "merge_window", "s", 0, 10,
                "several topics: consecutive messages of distinct topics whose stamps span at "
                "most this make one frame (below one scan period: 0.1 for 10 Hz scanners); 0: "
                "one message per frame")
          .text(&P::odom_topic, "odom_topic",
                "nav_msgs/Odometry topic giving the robot's pose where /tf has no fixed_frame→"
                "base_frame link (the last one at or before each scan's stamp; sensors then "
                "placed by `mounts`); empty: none");
  return t;
}

}  // namespace pedtrack::rosbag_source
