// `ros_publish`: publishes each frame's tracks to ROS1, stamped with the frame's input time:
// geometry_msgs/PoseArray (`tracks_topic`), the sensor_msgs/PointCloud2 "people" array with ids,
// velocities, shape, covariance and status (`people_topic`), and a visualization_msgs/MarkerArray
// for rviz (`markers_topic`); see track_messages.h. A stage after the tracker: it works with any
// source (`pedtrack ros` pairs it with ros_topic; a bag replay can publish too).
#include <mrpt/config/CConfigFileBase.h>
#include <ros/ros.h>

#include <memory>
#include <optional>

#include "bag_poses.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/text.h"
#include "ros_node.h"
#include "track_messages.h"

namespace pedtrack::ros_plugins {
namespace {

// A key of the pipeline's source section, or `def` (the source's own default) when unset.
std::string sourceKey(const PluginContext& ctx, const std::string& key, const std::string& def) {
  if (!ctx.config) return def;
  const auto stages = splitList(ctx.config->read_string("pipeline", "stages", ""));
  if (stages.empty()) return def;
  const std::string v = trim(ctx.config->read_string(stages.front(), key, ""));
  return v.empty() ? def : v;
}

struct RosPublishParams {
  std::string tracks_topic = "~tracks", people_topic = "~people", markers_topic = "~markers";
  std::string frame = "fixed";  // fixed, robot or sensor
  std::string frame_id;         // empty: the source's fixed_frame or base_frame
  std::string skip_status;      // comma list
  MarkerStyle style;
  NodeParams node;
};

const ParamTable<RosPublishParams>& table() {
  using P = RosPublishParams;
  static const auto t =
      ParamTable<P>()
          .text(&P::tracks_topic, "tracks_topic",
                "geometry_msgs/PoseArray, one pose per track; '~name' is private to the node; "
                "empty: not published")
          .text(&P::people_topic, "people_topic",
                "sensor_msgs/PointCloud2, one point per track in the PoseArray's order: x y z id "
                "vx vy yaw alpha beta cov_xx cov_xy cov_yy score (NaN: unknown) and status (0 "
                "tentative, 1 confirmed, 2 coasting, 3 following, 255 other); empty: not "
                "published")
          .text(&P::markers_topic, "markers_topic",
                "visualization_msgs/MarkerArray for rviz (namespaces torso, id, velocity, "
                "covariance, following); empty: not published")
          .choice(&P::frame, "frame",
                  {{"fixed", "fixed"}, {"robot", "robot"}, {"sensor", "sensor"}},
                  "frame the tracks are expressed in: the source's fixed frame, the robot (base) "
                  "frame or the (first) sensor's frame")
          .text(&P::frame_id, "frame_id",
                "header.frame_id of the messages; empty: the source's fixed_frame (frame = "
                "fixed, default odom) or base_frame (frame = robot, default base_link)")
          .text(&P::skip_status, "skip_status",
                "track statuses not published (comma list, e.g. tentative); empty: every track, "
                "as in tracks.csv")
          .real(path(&P::style, &MarkerStyle::person_height), "person_height", "m", 0.1, 3,
                "height of the rviz torso columns")
          .real(path(&P::style, &MarkerStyle::arrow_seconds), "arrow_seconds", "s", 0, 10,
                "velocity arrows reach where the person will be after this long")
          .include(&P::node, nodeTable());
  return t;
}

class RosPublish : public Tracker {
 public:
  explicit RosPublish(const PluginContext& ctx) : RosPublish(ctx, table().read(ctx.params)) {}
  RosPublish(const PluginContext& ctx, const RosPublishParams& p)
      : skip_(splitList(p.skip_status)), frame_(p.frame), frame_id_(p.frame_id), style_(p.style) {
    // The tracks are in the source's fixed frame; the robot frame is its base frame.
    const rosbag_source::RobotFrameParams frames;  // the source's defaults
    if (frame_id_.empty() && frame_ == "fixed")
      frame_id_ = sourceKey(ctx, "fixed_frame", frames.fixed_frame);
    if (frame_id_.empty() && frame_ == "robot")
      frame_id_ = sourceKey(ctx, "base_frame", frames.base_frame);
    if (frame_id_.empty())
      throw ConfigError(table().where(ctx.params, &RosPublishParams::frame_id) +
                        ": frame = sensor needs the sensor's tf frame name here");
    ensureNode(p.node.node, p.node.master_timeout);
    tracks_ =
        advertise<geometry_msgs::PoseArray>(ctx, p.tracks_topic, &RosPublishParams::tracks_topic);
    people_ =
        advertise<sensor_msgs::PointCloud2>(ctx, p.people_topic, &RosPublishParams::people_topic);
    markers_ = advertise<visualization_msgs::MarkerArray>(ctx, p.markers_topic,
                                                          &RosPublishParams::markers_topic);
  }

  void process(Frame& frame) override {
    if (!ros::ok()) return;  // ROS shut down under a run that is ending
    std::vector<Track> kept;
    kept.reserve(frame.tracks.size());
    for (const Track& t : frame.tracks)
      if (std::find(skip_.begin(), skip_.end(), t.status) == skip_.end()) kept.push_back(t);
    const mrpt::poses::CPose3D at = frame_ == "robot"    ? frame.robot_pose
                                    : frame_ == "sensor" ? frame.sensor_pose
                                                         : mrpt::poses::CPose3D();
    const std::vector<OutTrack> out = expressIn(kept, at);
    const ros::Time stamp(frame.t);
    if (tracks_) tracks_->publish(toPoseArray(out, frame_id_, stamp));
    if (people_) people_->publish(toPeopleCloud(out, frame_id_, stamp));
    if (markers_) markers_->publish(toMarkers(out, frame_id_, stamp, style_));
    ++published_;
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    return {{"published", published_}};
  }

 private:
  template <class M>
  std::optional<ros::Publisher> advertise(const PluginContext& ctx, const std::string& topic,
                                          std::string RosPublishParams::*key_member) {
    const std::string key = table().where(ctx.params, key_member);
    if (trim(topic).empty()) return std::nullopt;  // that output is not wanted
    try {
      ResolvedTopic r = resolveTopic(topic);
      // Deep enough for a subscriber that reads in bursts; a live one reads every message.
      return r.nh.advertise<M>(r.name, 100);
    } catch (const ConfigError& e) {
      throw ConfigError(key + ": " + e.what());
    } catch (const ros::Exception& e) {
      throw ConfigError(key + ": " + oneLine(e.what()));
    }
  }

  std::vector<std::string> skip_;
  std::string frame_, frame_id_;
  MarkerStyle style_;
  std::optional<ros::Publisher> tracks_, people_, markers_;
  long published_ = 0;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "Publishes tracks to ROS1: PoseArray, a people PointCloud2 and rviz markers";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RosPublish>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::ros_plugins

PEDTRACK_PLUGIN("ros_publish", pedtrack::ros_plugins::describe)
