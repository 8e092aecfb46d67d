// `ros_topic`: a live ROS1 source. Subscribes to sensor_msgs/LaserScan or sensor_msgs/PointCloud2
// topics (whichever each publisher sends), places the robot and each sensor with /tf, and hands
// the pipeline one frame per scan, or per group of scans of distinct topics within
// `merge_window` (several scanners on one robot), like the rosbag source does with a bag. With
// `detections`, the topics carry a detector's geometry_msgs/PoseArray instead: one frame of
// detections a message.
// Messages wait in a bounded queue filled by a roscpp spinner thread; the oldest is dropped
// when the pipeline falls behind (the pipeline's own live queue drops frames after that).
#include <mrpt/ros1bridge/time.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <iostream>
#include <memory>
#include <mutex>

#include "any_message.h"
#include "bag_poses.h"
#include "live_poses.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/stop_request.h"
#include "pedtrack/text.h"
#include "ros_frames.h"
#include "ros_node.h"

namespace pedtrack::ros_plugins {
namespace {

using Clock = std::chrono::steady_clock;

// tf2 refuses frame ids with tf1's leading '/', which older drivers and bags still send.
std::string tfFrame(const std::string& id) {
  return !id.empty() && id[0] == '/' ? id.substr(1) : id;
}

struct RosTopicParams {
  std::string topic = "/scan";  // comma list
  rosbag_source::RobotFrameParams frames;
  double tf_timeout = 0.1;    // s a scan waits for /tf to reach its stamp
  double idle_timeout = 0.0;  // s; 0: wait until SIGINT/SIGTERM
  bool end_on_idle = false;
  bool detections = false;
  long queue_size = 20;
  NodeParams node;
};

const ParamTable<RosTopicParams>& table() {
  using P = RosTopicParams;
  static const auto t =
      ParamTable<P>()
          .text(&P::topic, "topic",
                "topics to subscribe to (comma list; LaserScan or PointCloud2, several are "
                "merged, see merge_window); '~name' is private to the node")
          .include(&P::frames, rosbag_source::robotFrameTable())
          .real(&P::tf_timeout, "tf_timeout", "s", 0, 10,
                "how long a scan waits for /tf (or odometry) to reach its stamp (only when /tf "
                "links fixed_frame and base_frame at all, or odometry is published)")
          .real(&P::idle_timeout, "idle_timeout", "s", 0, 1e6,
                "fail (or end, see end_on_idle) after this long without a message, counted once "
                "a message came or a publisher is connected; 0: wait until SIGINT/SIGTERM")
          .boolean(&P::end_on_idle, "end_on_idle",
                   "treat idle_timeout as the end of the stream (a bag played into the node)")
          .boolean(&P::detections, "detections",
                   "the topics carry a detector's geometry_msgs/PoseArray (people or legs in the "
                   "sensor's frame, placed by /tf): one frame of detections a message, score 1")
          .integer(&P::queue_size, "queue_size", "", 1, 100000,
                   "messages waiting for the pipeline; beyond it the oldest is dropped "
                   "(queue_drops in run.json)")
          .include(&P::node, nodeTable());
  return t;
}

class RosTopicSource : public Sensor {
 public:
  explicit RosTopicSource(const PluginContext& ctx)
      : RosTopicSource(ctx, table().read(ctx.params)) {}
  RosTopicSource(const PluginContext& ctx, const RosTopicParams& p)
      : topics_(splitList(p.topic)),
        merge_window_(p.frames.merge_window),
        idle_timeout_(p.idle_timeout),
        end_on_idle_(p.end_on_idle),
        detections_(p.detections),
        queue_size_(static_cast<std::size_t>(p.queue_size)) {
    if (topics_.empty()) throw ConfigError("topic: no topic given");
    const std::string mounts_key = table().where(
        ctx.params, path(&RosTopicParams::frames, &rosbag_source::RobotFrameParams::mounts));
    rosbag_source::MountTable mounts = rosbag_source::parseMounts(p.frames.mounts, mounts_key);
    rosbag_source::checkMountTopics(mounts, topics_, mounts_key, "one of `topic`");
    ensureNode(p.node.node, p.node.master_timeout);
    poses_ =
        std::make_unique<LivePoses>(p.frames.fixed_frame, p.frames.base_frame, std::move(mounts),
                                    topics_.size() > 1, p.tf_timeout, p.frames.odom_topic);
    for (std::size_t i = 0; i < topics_.size(); ++i) {
      ResolvedTopic r;
      try {
        r = resolveTopic(topics_[i]);
      } catch (const ConfigError& e) {
        throw ConfigError(table().where(ctx.params, &RosTopicParams::topic) + ": " + e.what());
      }
      ros::SubscribeOptions ops;
      ops.template init<AnyMessage>(
          r.name, static_cast<std::uint32_t>(queue_size_),
          [this, i](const boost::shared_ptr<const AnyMessage>& m) { received(i, *m); });
      ops.callback_queue = &callbacks_;
      ops.transport_hints = ros::TransportHints().tcpNoDelay();
      subs_.push_back(r.nh.subscribe(ops));
    }
    spinner_ = std::make_unique<ros::AsyncSpinner>(1, &callbacks_);
    spinner_->start();
  }

  ~RosTopicSource() override {
    spinner_->stop();  // no callback may run into a half-destroyed source
    subs_.clear();
  }

  bool live() const override { return true; }
  bool detectionsOnly() const override { return detections_; }

  bool next(Frame& frame) override {
    // Idle time runs from this call, but only once the topics are in use (a message came, or a
    // publisher is connected): a node started before its driver or bag waits for it.
    auto idle_from = Clock::now();
    bool counting = false;
    for (;;) {
      std::vector<Incoming> group;
      {
        std::unique_lock<std::mutex> lk(m_);
        // Short waits: a stop request, or the end of ROS, is seen while the topics are quiet.
        while (pending_.empty()) {
          if (stopRequested() || !ros::ok()) return false;
          if (!counting) {
            // Asked without m_ held: roscpp takes its own locks for the publisher links.
            const bool had_messages = messages_ > 0;
            lk.unlock();
            const bool linked = had_messages || connected();
            lk.lock();
            if (linked) {
              counting = true;
              if (!had_messages) idle_from = Clock::now();
            }
            if (!pending_.empty()) break;
          }
          const double idle = std::chrono::duration<double>(Clock::now() - idle_from).count();
          if (counting && idle_timeout_ > 0 && idle > idle_timeout_) {
            if (end_on_idle_) return false;
            throw DataError("ros_topic: no message for " + std::to_string(idle_timeout_) + " s");
          }
          cv_.wait_for(lk, std::chrono::milliseconds(100));
        }
        group = takeGroup(lk);
      }
      if (makeFrame(group, frame)) return true;
    }
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    std::lock_guard<std::mutex> lk(m_);
    return {{"messages", messages_},
            {"queue_drops", queue_drops_},
            {"wrong_type", wrong_type_},
            {"bad_messages", bad_},
            {"tf_waits", poses_->waits()},
            {"tf_misses", poses_->misses()},
            {"odom_poses", poses_->odomPoses()},
            {"odom_waits", poses_->odomWaits()},
            {"poses_skipped", poses_skipped_}};
  }

 private:
  // A message as received, decoded, its poses not looked up yet.
  struct Incoming {
    std::size_t topic = 0;  // index into topics_
    sensor_msgs::LaserScan::ConstPtr scan;
    sensor_msgs::PointCloud2::ConstPtr cloud;
    geometry_msgs::PoseArray::ConstPtr poses;
    ros::Time stamp;
    std::string frame_id;
    Clock::time_point arrival;
  };

  bool connected() const {
    return std::any_of(subs_.begin(), subs_.end(),
                       [](const ros::Subscriber& s) { return s.getNumPublishers() > 0; });
  }

  // The spinner thread: decode and queue, nothing slow.
  void received(std::size_t topic, const AnyMessage& m) {
    Incoming in;
    in.topic = topic;
    in.arrival = Clock::now();
    try {
      if (detections_) {
        if (auto p = m.instantiate<geometry_msgs::PoseArray>()) {
          // No header stamp (some detectors leave it 0): the time it arrived.
          in.stamp = p->header.stamp.isZero() ? ros::Time::now() : p->header.stamp;
          in.frame_id = tfFrame(p->header.frame_id);
          in.poses = p;
        }
      } else if (auto s = m.instantiate<sensor_msgs::LaserScan>()) {
        in.stamp = s->header.stamp;
        in.frame_id = tfFrame(s->header.frame_id);
        in.scan = s;
      } else if (auto c = m.instantiate<sensor_msgs::PointCloud2>()) {
        in.stamp = c->header.stamp;
        in.frame_id = tfFrame(c->header.frame_id);
        in.cloud = c;
      }
    } catch (const std::exception& e) {  // a truncated or corrupt message
      std::lock_guard<std::mutex> lk(m_);
      ++bad_;
      warn_(topics_[topic] + ": a message could not be decoded: " + oneLine(e.what()));
      return;
    }
    std::lock_guard<std::mutex> lk(m_);
    ++messages_;
    if (!in.scan && !in.cloud && !in.poses) {
      ++wrong_type_;
      warn_(topics_[topic] + " carries " + m.datatype +
            (detections_ ? ", not geometry_msgs/PoseArray (detections = true): ignored"
                         : ", not sensor_msgs/LaserScan or sensor_msgs/PointCloud2: ignored"));
      return;
    }
    if (pending_.size() >= queue_size_) {
      pending_.pop_front();
      ++queue_drops_;
    }
    pending_.push_back(std::move(in));
    cv_.notify_one();
  }

  // The next frame's messages (m_ held, pending_ not empty): the oldest, then messages of the
  // other topics while no topic repeats and the stamps span at most merge_window. A partner
  // still on its way gets merge_window of wall time to arrive.
  std::vector<Incoming> takeGroup(std::unique_lock<std::mutex>& lk) {
    std::vector<Incoming> group;
    group.push_back(std::move(pending_.front()));
    pending_.pop_front();
    // A detector's message is a frame of its own.
    if (detections_ || topics_.size() < 2 || merge_window_ <= 0) return group;
    const auto deadline = group.front().arrival + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(merge_window_));
    double lo = group.front().stamp.toSec(), hi = lo;
    while (group.size() < topics_.size()) {
      if (pending_.empty()) {
        if (stopRequested()) break;
        cv_.wait_until(lk, deadline);
        if (pending_.empty() && Clock::now() >= deadline) break;
        continue;
      }
      const Incoming& m = pending_.front();
      const bool repeats = std::any_of(group.begin(), group.end(),
                                       [&](const Incoming& g) { return g.topic == m.topic; });
      const double t = m.stamp.toSec();
      if (repeats || std::max(hi, t) - std::min(lo, t) > merge_window_) break;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
      group.push_back(std::move(pending_.front()));
      pending_.pop_front();
    }
    return group;
  }

  // Converts a group into a frame, as the rosbag source does (ros_frames.h). False when no
  // message of it could be converted.
  bool makeFrame(const std::vector<Incoming>& group, Frame& frame) {
    if (detections_) {
      const Incoming& in = group.front();
      mrpt::poses::CPose3D robot, mount;
      const bool known = poses_->lookup(in.frame_id, topics_[in.topic], in.stamp, robot, mount);
      long skipped = 0;
      rosbag_source::poseArrayToFrame(*in.poses, robot, mount, known, frame, skipped);
      {
        std::lock_guard<std::mutex> lk(m_);
        poses_skipped_ += skipped;
      }
      bool went_back = false;
      frame.t = clock_.next(in.stamp.toSec(), went_back);
      if (went_back)
        std::cerr << "warning: ros_topic: header stamps go back; frame times are held at the "
                     "newest so far\n";
      return true;
    }
    std::vector<rosbag_source::MountedObservation> done;
    for (const Incoming& in : group) {
      rosbag_source::MountedObservation c;
      c.topic = topics_[in.topic];
      c.stamp = in.stamp.toSec();
      c.robot_known = poses_->lookup(in.frame_id, c.topic, in.stamp, c.robot, c.mount);
      c.obs =
          in.scan
              ? mrpt::obs::CObservation::Ptr(rosbag_source::scanToObservation(*in.scan, c.mount))
              : rosbag_source::cloudToObservation(*in.cloud, c.mount);
      if (!c.obs) {
        std::lock_guard<std::mutex> lk(m_);
        ++bad_;
        warn_(c.topic + ": a " + (in.scan ? "LaserScan" : "PointCloud2 without x,y,z") +
              " could not be converted: skipped");
        continue;
      }
      c.obs->timestamp = mrpt::ros1bridge::fromROS(in.stamp);
      c.obs->sensorLabel = c.topic;
      done.push_back(std::move(c));
    }
    if (done.empty()) return false;
    bool went_back = false;
    frame.t = clock_.next(rosbag_source::assembleFrame(done, frame), went_back);
    if (went_back)
      std::cerr << "warning: ros_topic: header stamps go back; frame times are held at the "
                   "newest so far\n";
    return true;
  }

  std::vector<std::string> topics_;
  double merge_window_, idle_timeout_;
  bool end_on_idle_, detections_;
  std::size_t queue_size_;
  std::unique_ptr<LivePoses> poses_;
  ros::CallbackQueue callbacks_;
  std::vector<ros::Subscriber> subs_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  mutable std::mutex m_;  // guards pending_, the counts and warn_
  std::condition_variable cv_;
  std::deque<Incoming> pending_;
  long messages_ = 0, queue_drops_ = 0, wrong_type_ = 0, bad_ = 0, poses_skipped_ = 0;
  WarnOnce warn_{"ros_topic: "};  // one line per distinct problem; counts go to run.json
  rosbag_source::FrameClock clock_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc =
      "Live ROS1 LaserScan / PointCloud2 (or PoseArray detection) topics, robot and sensor poses "
      "from /tf (or odometry)";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<RosTopicSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::ros_plugins

PEDTRACK_PLUGIN("ros_topic", pedtrack::ros_plugins::describe)
