// `rosbag`: replays sensor_msgs/LaserScan (→ CObservation2DRangeScan) and sensor_msgs/PointCloud2
// (→ CObservationPointCloud) from a ROS1 bag through rosbag_storage and mrpt::ros1bridge, with
// robot poses from /tf and odometry. Observation time = message header stamp.
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
#include <memory>

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
  explicit RosbagSource(const PluginContext& ctx) : file_(ctx.params.getString("file")) {
    try {
      bag_.open(file_, rosbag::bagmode::Read);
    } catch (const std::exception& e) {
      throw ConfigError("file: cannot open bag '" + file_ + "': " + oneLine(e.what()));
    }
    const std::vector<std::string> topics = chooseTopics(ctx.params.getList("topic"));
    poses_ = std::make_unique<BagPoses>(bag_, ctx.params.getString("fixed_frame"),
                                        ctx.params.getString("base_frame"),
                                        ctx.params.getString("odom_topic"));
    realtime_ = ctx.params.getString("rate") == "realtime";
    view_ = std::make_unique<rosbag::View>(bag_, rosbag::TopicQuery(topics));
    total_ = view_->size();
    it_ = view_->begin();
  }

  bool next(Frame& frame) override {
    for (; it_ != view_->end(); ++it_) {
      const rosbag::MessageInstance& m = *it_;
      ++consumed_;
      mrpt::obs::CObservation::Ptr obs;
      std::string sensor_frame;
      ros::Time stamp;
      if (auto scan = m.instantiate<sensor_msgs::LaserScan>()) {
        sensor_frame = scan->header.frame_id;
        stamp = scan->header.stamp;
        poses_->lookup(sensor_frame, stamp, frame.robot_pose, mount_);
        auto o = mrpt::obs::CObservation2DRangeScan::Create();
        if (!mrpt::ros1bridge::fromROS(*scan, mount_, *o))
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          m.getTopic() + ": LaserScan could not be converted");
        // mrpt::ros1bridge drops returns beyond 95% of range_max; ROS defines a return as valid
        // anywhere in [range_min, range_max], and a person at 5.4 m of a 5.6 m scanner is real.
        for (std::size_t k = 0; k < scan->ranges.size(); ++k) {
          const float r = scan->ranges[k];
          o->setScanRangeValidity(k,
                                  std::isfinite(r) && r >= scan->range_min && r <= scan->range_max);
        }
        obs = o;
      } else if (auto cloud = m.instantiate<sensor_msgs::PointCloud2>()) {
        sensor_frame = cloud->header.frame_id;
        stamp = cloud->header.stamp;
        poses_->lookup(sensor_frame, stamp, frame.robot_pose, mount_);
        auto o = mrpt::obs::CObservationPointCloud::Create();
        auto pts = mrpt::maps::CSimplePointsMap::Create();
        if (!mrpt::ros1bridge::fromROS(*cloud, *pts))
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          m.getTopic() + ": PointCloud2 has no x,y,z fields");
        o->pointcloud = pts;
        o->sensorPose = mount_;
        obs = o;
      } else {
        continue;
      }
      obs->timestamp = mrpt::ros1bridge::fromROS(stamp);
      obs->sensorLabel = m.getTopic();
      frame.observations.push_back(obs);
      frame.t = stamp.toSec();
      frame.sensor_pose = frame.robot_pose + mount_;
      if (realtime_) pacer_.wait(frame.t);
      ++it_;
      return true;
    }
    return false;
  }

  double progress() const override { return total_ ? static_cast<double>(consumed_) / total_ : -1; }

 private:
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
  rosbag::Bag bag_;
  std::unique_ptr<BagPoses> poses_;
  std::unique_ptr<rosbag::View> view_;
  rosbag::View::iterator it_;
  std::size_t total_ = 0, consumed_ = 0;
  bool realtime_ = false;
  ReplayPacer pacer_;
  mrpt::poses::CPose3D mount_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Replays LaserScan / PointCloud2 topics of a ROS1 bag, robot pose from /tf and odometry";
  d.params = {
      ParamSpec::inputFile("file", "the .bag to replay"),
      ParamSpec::text(
          "topic", std::string(),
          "topics to replay (comma list); empty: the bag's only LaserScan/PointCloud2 topic"),
      ParamSpec::text("fixed_frame", std::string("odom"),
                      "tf frame tracking happens in (odom, map, ...)"),
      ParamSpec::text("base_frame", std::string("base_link"), "tf frame of the robot body"),
      ParamSpec::text(
          "odom_topic", std::string("/odom"),
          "nav_msgs/Odometry topic used when tf has no fixed_frame→base_frame link; empty: none"),
      ParamSpec::choice("rate", "max", {"max", "realtime"},
                        "max: as fast as the pipeline runs; realtime: paced by the header stamps"),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RosbagSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::rosbag_source

PEDTRACK_PLUGIN("rosbag", pedtrack::rosbag_source::describe)
