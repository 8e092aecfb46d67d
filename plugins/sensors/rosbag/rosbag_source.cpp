// `rosbag`: replays sensor_msgs/LaserScan (→ CObservation2DRangeScan) and sensor_msgs/PointCloud2
// (→ CObservationPointCloud) from a ROS1 bag through rosbag_storage and mrpt::ros1bridge, with
// robot poses from /tf and odometry; or a detector's geometry_msgs/PoseArray topics as frames of
// detections. Observation time = message header stamp. Several topics
// (scanners on one robot) are merged: consecutive messages of distinct topics within
// `merge_window` make one frame, each observation with its own mounting pose.
#include <mrpt/ros1bridge/time.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include "bag_poses.h"
#include "pedtrack/bag_open.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"
#include "pedtrack/ros_checked_message.h"
#include "pedtrack/text.h"
#include "ros_frames.h"

namespace pedtrack::rosbag_source {
namespace {

const std::string kLaserScan = "sensor_msgs/LaserScan";
const std::string kPointCloud2 = "sensor_msgs/PointCloud2";
const std::string kPoseArray = "geometry_msgs/PoseArray";

struct RosbagParams {
  std::string file;
  std::string topic;  // comma list; empty: the bag's only scan topic
  RobotFrameParams frames;
  ReplayRateParams rate;
};

const ParamTable<RosbagParams>& table() {
  using P = RosbagParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::file, "file", "the .bag to replay")
          .text(&P::topic, "topic",
                "topics to replay (comma list; several are merged, see merge_window); empty: the "
                "bag's only LaserScan/PointCloud2 topic. geometry_msgs/PoseArray topics (a "
                "detector's people or legs, sensor frame) replay as detections, one frame a "
                "message")
          .include(&P::frames, robotFrameTable())
          .include(&P::rate, replayRateTable());
  return t;
}

class RosbagSource : public Sensor {
 public:
  explicit RosbagSource(const PluginContext& ctx) : RosbagSource(ctx, table().read(ctx.params)) {}
  RosbagSource(const PluginContext& ctx, const RosbagParams& p)
      : file_(p.file), merge_window_(p.frames.merge_window) {
    const std::string mounts_key =
        table().where(ctx.params, path(&RosbagParams::frames, &RobotFrameParams::mounts));
    try {
      recovered_ = openBagForReading(bag_, file_);
      if (recovered_)  // said at once; the run then ends with it as its error (exit 1)
        std::cerr << "warning: " << recoveryWarning(file_, *recovered_) << "\n";
    } catch (const std::exception& e) {
      throw ConfigError("file: cannot open bag '" + file_ + "': " + oneLine(e.what()));
    }
    const std::vector<std::string> topics = chooseTopics(splitList(p.topic));
    MountTable mounts = parseMounts(p.frames.mounts, mounts_key);
    checkMountTopics(mounts, usable_, mounts_key, "a scan topic of bag '" + file_ + "'");
    // One scanner's own frame is a fine robot frame; several need their mounts to line up.
    try {
      poses_ =
          std::make_unique<BagPoses>(bag_, p.frames.fixed_frame, p.frames.base_frame,
                                     p.frames.odom_topic, std::move(mounts), topics.size() > 1);
    } catch (const ConfigError&) {
      throw;
    } catch (const std::exception& e) {  // a /tf or odometry message that cannot be read
      throw DataError(file_ + ": reading /tf and odometry: " + oneLine(e.what()));
    }
    realtime_ = p.rate.realtime;
    view_ = std::make_unique<rosbag::View>(bag_, rosbag::TopicQuery(topics));
    total_ = view_->size();
    it_ = view_->begin();
  }

  bool detectionsOnly() const override { return detections_; }

  std::vector<std::pair<std::string, long>> counters() const override {
    std::vector<std::pair<std::string, long>> out;
    if (detections_) out.emplace_back("poses_skipped", poses_skipped_);
    if (recovered_) {  // a bag cut short: where its data ends and what was read of it
      out.emplace_back("bag_data_end_byte", long(recovered_->data_end));
      out.emplace_back("bag_messages_recovered", long(recovered_->messages));
    }
    return out;
  }

  bool next(Frame& frame) override {
    if (detections_ ? nextPoses(frame) : nextScans(frame)) return true;
    // A bag cut short fails the run once every complete message is replayed: outputs are kept.
    if (recovered_ && !reported_) {
      reported_ = true;
      throw DataError(recoveryWarning(file_, *recovered_));
    }
    return false;
  }

  double progress() const override { return total_ ? static_cast<double>(consumed_) / total_ : -1; }

 private:
  // The next frame of scans or clouds: messages of several topics merged.
  bool nextScans(Frame& frame) {
    // A group: consecutive messages (bag order) while no topic repeats and their stamps span at
    // most merge_window; the first message that does not fit waits for the next frame.
    std::vector<MountedObservation> group;
    double lo = 0, hi = 0;
    for (;;) {
      if (!pending_) pending_ = read();
      if (!pending_) break;
      const MountedObservation& m = *pending_;
      if (!group.empty()) {
        const bool repeats =
            std::any_of(group.begin(), group.end(),
                        [&](const MountedObservation& g) { return g.topic == m.topic; });
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
    bool went_back = false;
    frame.t = clock_.next(assembleFrame(group, frame), went_back);
    if (went_back)
      std::cerr << "warning: " << file_ << ": header stamps go back in bag order (message "
                << consumed_ << "); frame times are held at the newest so far\n";
    if (realtime_) pacer_.wait(frame.t);
    return true;
  }

  // One PoseArray message as a frame of detections.
  bool nextPoses(Frame& frame) {
    for (; it_ != view_->end(); ++it_) {
      const rosbag::MessageInstance& m = *it_;
      ++consumed_;
      boost::shared_ptr<geometry_msgs::PoseArray> poses;
      try {
        poses = checkedInstantiate<geometry_msgs::PoseArray>(m);
      } catch (const std::exception& e) {
        throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                        m.getTopic() + ": " + oneLine(e.what()));
      }
      if (!poses) continue;
      // No header stamp (0, as some extracted bags have): the time the bag recorded it.
      const ros::Time stamp = poses->header.stamp.isZero() ? m.getTime() : poses->header.stamp;
      mrpt::poses::CPose3D robot, mount;
      const bool known = poses_->lookup(poses->header.frame_id, m.getTopic(), stamp, robot, mount);
      poseArrayToFrame(*poses, robot, mount, known, frame, poses_skipped_);
      bool went_back = false;
      frame.t = clock_.next(stamp.toSec(), went_back);
      if (went_back)
        std::cerr << "warning: " << file_ << ": header stamps go back in bag order (message "
                  << consumed_ << "); frame times are held at the newest so far\n";
      ++it_;
      if (realtime_) pacer_.wait(frame.t);
      return true;
    }
    return false;
  }

  // The next scan or cloud message of the view, or nothing at its end.
  std::optional<MountedObservation> read() {
    for (; it_ != view_->end(); ++it_) {
      const rosbag::MessageInstance& m = *it_;
      ++consumed_;
      MountedObservation out;
      out.topic = m.getTopic();
      std::string sensor_frame;
      ros::Time stamp;
      boost::shared_ptr<sensor_msgs::LaserScan> scan;
      boost::shared_ptr<sensor_msgs::PointCloud2> cloud;
      try {
        if (!(scan = checkedInstantiate<sensor_msgs::LaserScan>(m)))
          cloud = checkedInstantiate<sensor_msgs::PointCloud2>(m);
      } catch (const std::exception& e) {
        throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " + out.topic +
                        ": " + oneLine(e.what()));
      }
      if (scan) {
        sensor_frame = scan->header.frame_id;
        stamp = scan->header.stamp;
        out.robot_known = poses_->lookup(sensor_frame, out.topic, stamp, out.robot, out.mount);
        out.obs = scanToObservation(*scan, out.mount);
        if (!out.obs)
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          out.topic + ": LaserScan could not be converted");
      } else if (cloud) {
        sensor_frame = cloud->header.frame_id;
        stamp = cloud->header.stamp;
        out.robot_known = poses_->lookup(sensor_frame, out.topic, stamp, out.robot, out.mount);
        out.obs = cloudToObservation(*cloud, out.mount);
        if (!out.obs)
          throw DataError(file_ + ": message " + std::to_string(consumed_ - 1) + " on " +
                          out.topic + ": PointCloud2 has no x,y,z fields");
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
    std::vector<std::string> usable, every, poses;
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      if (std::find(every.begin(), every.end(), c->topic) == every.end()) every.push_back(c->topic);
      if (c->datatype == kPoseArray &&
          std::find(poses.begin(), poses.end(), c->topic) == poses.end())
        poses.push_back(c->topic);
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
    // A detector's PoseArray topics, asked for by name, replay as detections (not with scans).
    const auto isPoses = [&](const std::string& t) {
      return std::find(poses.begin(), poses.end(), t) != poses.end();
    };
    const long n_poses = std::count_if(requested.begin(), requested.end(), isPoses);
    if (n_poses > 0 && n_poses < long(requested.size()))
      throw ConfigError("topic: give scan topics or geometry_msgs/PoseArray topics, not both");
    if (n_poses > 0) {
      detections_ = true;
      usable_ = requested;
      return requested;
    }
    for (const auto& t : requested) {
      if (std::find(usable.begin(), usable.end(), t) != usable.end()) continue;
      const bool exists = std::find(every.begin(), every.end(), t) != every.end();
      const std::string hint = closestMatch(t, usable);
      throw ConfigError("topic: '" + t + "' " +
                        (exists ? "is not a LaserScan, PointCloud2 or PoseArray topic"
                                : "is not in bag '" + file_ + "'") +
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
  std::optional<MountedObservation> pending_;  // read, but did not fit the last frame
  bool detections_ = false;                    // the topics are PoseArrays: detections
  long poses_skipped_ = 0;
  FrameClock clock_;
  std::optional<BagRecovery> recovered_;  // the bag was cut short and re-indexed
  bool reported_ = false;                 // its DataError was thrown at the end
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc =
      "Replays LaserScan / PointCloud2 (or PoseArray detection) topics of a ROS1 bag, robot pose "
      "from /tf and odometry";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RosbagSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::rosbag_source

PEDTRACK_PLUGIN("rosbag", pedtrack::rosbag_source::describe)
