// `rosbag`: replays sensor_msgs/LaserScan (→ CObservation2DRangeScan) and sensor_msgs/PointCloud2
// (→ CObservationPointCloud) from a ROS1 bag through rosbag_storage and mrpt::ros1bridge, with
// robot poses from /tf and odometry. Observation time = message header stamp. Several topics
// (scanners on one robot) are merged: consecutive messages of distinct topics within
// `merge_window` make one frame, each observation with its own mounting pose.
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/point_cloud2.h>
#include <mrpt/ros1bridge/time.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

#include "bag_poses.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"
#include "pedtrack/text.h"

namespace pedtrack::rosbag_source {
namespace {

const std::string kLaserScan = "sensor_msgs/LaserScan";
const std::string kPointCloud2 = "sensor_msgs/PointCloud2";

class RosbagSource : public Sensor {
 public:
  explicit RosbagSource(const PluginContext& ctx)
      : file_(ctx.params.getString("file")), merge_window_(ctx.params.getDouble("merge_window")) {
    try {
      bag_.open(file_, rosbag::bagmode::Read);
    } catch (const std::exception& e) {
      throw ConfigError("file: cannot open bag '" + file_ + "': " + oneLine(e.what()));
    }
    const std::vector<std::string> topics = chooseTopics(ctx.params.getList("topic"));
    MountTable mounts = parseMounts(ctx.params.getString("mounts"), ctx.params.where("mounts"));
    for (const auto& [topic, pose] : mounts) {
      if (std::find(usable_.begin(), usable_.end(), topic) != usable_.end()) continue;
      const std::string hint = closestMatch(topic, usable_);
      throw ConfigError(ctx.params.where("mounts") + ": topic '" + topic +
                        "' is not a scan topic of bag '" + file_ + "'" +
                        (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    // One scanner's own frame is a fine robot frame; several need their mounts to line up.
    poses_ = std::make_unique<BagPoses>(
        bag_, ctx.params.getString("fixed_frame"), ctx.params.getString("base_frame"),
        ctx.params.getString("odom_topic"), std::move(mounts), topics.size() > 1);
    realtime_ = ctx.params.getString("rate") == "realtime";
    view_ = std::make_unique<rosbag::View>(bag_, rosbag::TopicQuery(topics));
    total_ = view_->size();
    it_ = view_->begin();
  }

  bool next(Frame& frame) override {
    // A group: consecutive messages (bag order) while no topic repeats and their stamps span at
    // most merge_window; the first message that does not fit waits for the next frame.
    std::vector<Message> group;
    double lo = 0, hi = 0;
    for (;;) {
      if (!pending_) pending_ = read();
      if (!pending_) break;
      const Message& m = *pending_;
      if (!group.empty()) {
        const bool repeats = std::any_of(group.begin(), group.end(),
                                         [&](const Message& g) { return g.topic == m.topic; });
        if (merge_window_ <= 0 || repeats ||
            std::max(hi, m.stamp) - std::min(lo, m.stamp) > merge_window_)
          break;
      }
      lo = group.empty() ? m.stamp : std::min(lo, m.stamp);
      hi = group.empty() ? m.stamp : std::max(hi, m.stamp);
      group.push_back(std::move(*pending_));
      pending_.reset();
    }
    if (group.empty()) return false;
    // The frame is the robot at the newest stamp. Each observation's sensorPose places its
    // scanner relative to that robot pose (its mount, composed with the robot's motion since its
    // own stamp when the bag has poses), so the merged cloud is one consistent robot frame.
    const Message& newest =
        *std::max_element(group.begin(), group.end(),
                          [](const Message& a, const Message& b) { return a.stamp < b.stamp; });
    frame.robot_pose = newest.robot;
    frame.has_odometry = newest.robot_known;
    for (const Message& m : group) {
      const mrpt::poses::CPose3D in_fixed = m.robot + m.mount;
      m.obs->setSensorPose(&m == &newest ? m.mount : in_fixed - frame.robot_pose);
      frame.observations.push_back(m.obs);
      frame.sensors.push_back({m.topic, in_fixed});
    }
    frame.sensor_pose = frame.sensors.front().pose;
    // Stages divide by the time step: frame times never go back, even where stamps do.
    if (newest.stamp < last_t_ && !warned_back_) {
      warned_back_ = true;
      std::cerr << "warning: " << file_ << ": header stamps go back in bag order (message "
                << consumed_ << "); frame times are held at the newest so far\n";
    }
    last_t_ = std::max(last_t_, newest.stamp);
    frame.t = last_t_;
    if (realtime_) pacer_.wait(frame.t);
    return true;
  }

  double progress() const override { return total_ ? static_cast<double>(consumed_) / total_ : -1; }

 private:
  // One scan or cloud message, converted, with the poses it was taken at.
  struct Message {
    mrpt::obs::CObservation::Ptr obs;
    std::string topic;
    double stamp = 0;
    mrpt::poses::CPose3D robot, mount;
    bool robot_known = false;  // robot from tf or odometry, not the identity by default
  };

  // The next scan or cloud message of the view, or nothing at its end.
  std::optional<Message> read() {
    for (; it_ != view_->end(); ++it_) {
      const rosbag::MessageInstance& m = *it_;
      ++consumed_;
      Message out;
      out.topic = m.getTopic();
      std::string sensor_frame;
      ros::Time stamp;
      if (auto scan = m.instantiate<sensor_msgs::LaserScan>()) {
        sensor_frame = scan->header.frame_id;
        stamp = scan->header.stamp;
        out.robot_known = poses_->lookup(sensor_frame, out.topic, stamp, out.robot, out.mount);
        auto o = mrpt::obs::CObservation2DRangeScan::Create();
        if (!mrpt::ros1bridge::fromROS(*scan, out.mount, *o))
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          out.topic + ": LaserScan could not be converted");
        // mrpt::ros1bridge drops returns beyond 95% of range_max; ROS defines a return as valid
        // anywhere in [range_min, range_max], and a person at 5.4 m of a 5.6 m scanner is real.
        for (std::size_t k = 0; k < scan->ranges.size(); ++k) {
          const float r = scan->ranges[k];
          o->setScanRangeValidity(k,
                                  std::isfinite(r) && r >= scan->range_min && r <= scan->range_max);
        }
        out.obs = o;
      } else if (auto cloud = m.instantiate<sensor_msgs::PointCloud2>()) {
        sensor_frame = cloud->header.frame_id;
        stamp = cloud->header.stamp;
        out.robot_known = poses_->lookup(sensor_frame, out.topic, stamp, out.robot, out.mount);
        auto o = mrpt::obs::CObservationPointCloud::Create();
        auto pts = mrpt::maps::CSimplePointsMap::Create();
        if (!mrpt::ros1bridge::fromROS(*cloud, *pts))
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          out.topic + ": PointCloud2 has no x,y,z fields");
        o->pointcloud = pts;
        o->sensorPose = out.mount;
        out.obs = o;
      } else {
        continue;
      }
      out.obs->timestamp = mrpt::ros1bridge::fromROS(stamp);
      out.obs->sensorLabel = out.topic;
      out.stamp = stamp.toSec();
      ++it_;
      return out;
    }
    return std::nullopt;
  }

  // The requested topics, checked against the bag; or the bag's only scan/cloud topic.
  std::vector<std::string> chooseTopics(const std::vector<std::string>& requested) {
    rosbag::View all(bag_);
    std::vector<std::string> usable, every;
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      if (std::find(every.begin(), every.end(), c->topic) == every.end()) every.push_back(c->topic);
      if ((c->datatype == kLaserScan || c->datatype == kPointCloud2) &&
          std::find(usable.begin(), usable.end(), c->topic) == usable.end())
        usable.push_back(c->topic);
    }
    usable_ = usable;
    std::string listing;
    for (const auto& t : usable) listing += (listing.empty() ? "" : ", ") + t;
    if (requested.empty()) {
      if (usable.size() == 1) return usable;
      if (usable.empty())
        throw ConfigError("topic: bag '" + file_ + "' has no LaserScan or PointCloud2 topic");
      throw ConfigError("topic: bag '" + file_ +
                        "' has several scan topics, choose from: " + listing);
    }
    for (const auto& t : requested) {
      if (std::find(usable.begin(), usable.end(), t) != usable.end()) continue;
      const bool exists = std::find(every.begin(), every.end(), t) != every.end();
      const std::string hint = closestMatch(t, usable);
      throw ConfigError(
          "topic: '" + t + "' " +
          (exists ? "is not a LaserScan or PointCloud2 topic" : "is not in bag '" + file_ + "'") +
          (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
          (listing.empty() ? "" : "; scan topics: " + listing));
    }
    return requested;
  }

  std::string file_;
  double merge_window_;
  std::vector<std::string> usable_;  // the bag's LaserScan / PointCloud2 topics
  rosbag::Bag bag_;
  std::unique_ptr<BagPoses> poses_;
  std::unique_ptr<rosbag::View> view_;
  rosbag::View::iterator it_;
  std::size_t total_ = 0, consumed_ = 0;
  bool realtime_ = false;
  ReplayPacer pacer_;
  std::optional<Message> pending_;  // read, but did not fit the last frame
  double last_t_ = -std::numeric_limits<double>::infinity();
  bool warned_back_ = false;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Replays LaserScan / PointCloud2 topics of a ROS1 bag, robot pose from /tf and odometry";
  d.params = {
      ParamSpec::inputFile("file", "the .bag to replay"),
      ParamSpec::text(
          "topic", std::string(),
          "topics to replay (comma list; several are merged, see merge_window); empty: the "
          "bag's only LaserScan/PointCloud2 topic"),
      ParamSpec::text("fixed_frame", std::string("odom"),
                      "tf frame tracking happens in (odom, map, ...)"),
      ParamSpec::text("base_frame", std::string("base_link"), "tf frame of the robot body"),
      ParamSpec::text(
          "odom_topic", std::string("/odom"),
          "nav_msgs/Odometry topic used when tf has no fixed_frame→base_frame link; empty: none"),
      ParamSpec::choice("rate", "max", {"max", "realtime"},
                        "max: as fast as the pipeline runs; realtime: paced by the header stamps"),
      ParamSpec::real("merge_window", 0.1, "s", 0, 10,
                      "several topics: consecutive messages of distinct topics whose stamps span "
                      "at most this make one frame (below one scan period: 0.1 for 10 Hz "
                      "scanners); 0: one message per frame"),
      ParamSpec::text("mounts", std::string(),
                      "mounting poses on base_frame of topics /tf does not place: 'topic: x y z "
                      "yaw_deg [pitch_deg [roll_deg]]' (m, deg), entries separated by ';' written "
                      "right after a number (' ;' starts an INI comment)"),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RosbagSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::rosbag_source

PEDTRACK_PLUGIN("rosbag", pedtrack::rosbag_source::describe)
