// leg_pose (P3 §2.2–2.5): one person tracked from the two legs a knee-height 2D scanner sees.
// The target is the leg pair nearest the robot when tracking starts (P3 §2.2); from then on its
// legs are picked, left from right, among the scan's legs by nearest neighbour to the legs the
// gait model predicts. The pose [X, Y, θ] comes from P3's constant-acceleration filter with the
// motion-intention zoning's orientation; a leg hidden by the other is placed by eq. 6–7.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "pedtrack/ipopt/gait_fit.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/leg_pose_params.h"
#include "pedtrack/track/tracker_base.h"

namespace pedtrack::legpose {
namespace {

using namespace pedtrack::track;

struct LegPoseStageParams {
  LegPoseParams pose;            // P3's estimator (leg_pose_params.h)
  bool from_detections = false;  // a classifier's legs instead of the leg segmenter's circles
  bool facing_sensor = true;     // the person faces the robot when tracking starts
  double max_range = 3;          // m, the target is the nearest leg pair within it (P3 §2.2)
  double lost_time = 1.0;        // s without a leg: the track ends, the nearest pair is taken
  double occluded_width = 0.07;  // m, narrower leg circles beside a nearer return: partly hidden
};

const ParamTable<LegPoseStageParams>& table() {
  using P = LegPoseStageParams;
  static const auto t =
      ParamTable<P>()
          .include(&P::pose, legPoseTable())
          .choice(&P::from_detections, "legs", {{"clusters", false}, {"detections", true}},
                  "leg positions: the leg segmenter's circles (P3) or a classifier's legs")
          .choice(&P::facing_sensor, "initial_facing", {{"sensor", true}, {"away", false}},
                  "the person faces the robot when tracking starts (P3's frontal following) or "
                  "faces away (the robot follows behind)")
          .real(&P::max_range, "max_range", "m", 0.1, 100,
                "the target is the nearest leg pair within this distance (P3 §2.2)")
          .real(&P::lost_time, "lost_time", "s", 0, 3600,
                "no leg of the person for this long: the track ends and the nearest pair is "
                "acquired again (new id)")
          .real(&P::occluded_width, "occluded_width", "m", 0, 1,
                "a leg circle seen narrower than this with something nearer beside it in the "
                "scan is partly hidden: its heading readings take heading_occluded_sigma_leg as "
                "its position error (from the segmenter's jump_prev, jump_next and width "
                "features: scan_segments, leg_circles; without them no leg is marked); 0: off");
  return t;
}

class LegPose : public Tracker {
 public:
  explicit LegPose(const PluginContext& ctx) : LegPose(table().read(ctx.params)) {}
  explicit LegPose(const LegPoseStageParams& p)
      : params_(p.pose),
        from_detections_(p.from_detections),
        facing_sensor_(p.facing_sensor),
        max_range_(p.max_range),
        lost_time_(p.lost_time),
        occluded_width_(p.occluded_width) {
    gait::useChosenGaitSolver(params_);
  }

  void process(Frame& f) override {
    const std::vector<Eigen::Vector2d> legs = candidates(f);
    const Eigen::Vector2d sensor(f.sensor_pose.x(), f.sensor_pose.y());
    if (est_ && f.t - last_seen_ > lost_time_) est_.reset();  // lost: acquire again
    if (!est_) {
      if (!acquire(f, legs, sensor)) return;
    } else {
      est_->predict(f.t);
      const auto [li, ri] = est_->associate(legs);
      LegSeen l, r;
      if (li >= 0) l = {true, legs[std::size_t(li)], occluded_[std::size_t(li)]};
      if (ri >= 0) r = {true, legs[std::size_t(ri)], occluded_[std::size_t(ri)]};
      est_->update(l, r, sensor);
      if (l.seen || r.seen) last_seen_ = f.t;
    }
    f.tracks.push_back(row(f));
  }

 private:
  // Leg positions in the fixed frame: the leg segmenter's circles, or a classifier's legs. Each
  // circle is also marked partly hidden (occluded_) when something nearer lies beside it in the
  // scan (a jump to a nearer return, jump_prev or jump_next, of more than kOccluderJump) and the
  // part of it seen is narrower than occluded_width: a circle fitted to such a sliver sits
  // centimetres off the leg's centre, sideways (P3 scenario 3's side view: 7 cm, a 20° error in
  // the heading read from the pair).
  std::vector<Eigen::Vector2d> candidates(const Frame& f) {
    std::vector<Eigen::Vector2d> out;
    occluded_.clear();
    if (from_detections_) {
      for (const Detection& d : f.detections) out.emplace_back(d.x, d.y);
      occluded_.assign(out.size(), false);
      return out;
    }
    const int jump_prev = f.clusterFeatureIndex("jump_prev"),
              jump_next = f.clusterFeatureIndex("jump_next"),
              width = f.clusterFeatureIndex("width");
    for (const Cluster& c : f.clusters) {
      double x, y, z;
      f.robot_pose.composePoint(c.cx, c.cy, c.cz, x, y, z);
      out.emplace_back(x, y);
      auto feature = [&](int k) {
        return k >= 0 && std::size_t(k) < c.features.size() ? c.features[std::size_t(k)] : NAN;
      };
      const bool beside_nearer =
          feature(jump_prev) < -kOccluderJump || feature(jump_next) < -kOccluderJump;
      occluded_.push_back(occluded_width_ > 0 && beside_nearer && feature(width) < occluded_width_);
    }
    return out;
  }

  // m: a neighbouring return this much nearer than the segment's end is something in front of
  // it (the scan segmenter splits segments at jumps of 0.1 m and more by default).
  static constexpr double kOccluderJump = 0.05;
  std::vector<bool> occluded_;  // candidates(): this scan's circles partly hidden

  // P3 §2.2: the candidate pair (two legs close enough to be one person's) nearest the robot.
  bool acquire(const Frame& f, const std::vector<Eigen::Vector2d>& legs,
               const Eigen::Vector2d& sensor) {
    double best = max_range_;
    int bi = -1, bj = -1;
    for (std::size_t i = 0; i < legs.size(); ++i)
      for (std::size_t j = i + 1; j < legs.size(); ++j) {
        if ((legs[i] - legs[j]).norm() > 2 * params_.leg_gate) continue;
        const double d = (0.5 * (legs[i] + legs[j]) - sensor).norm();
        if (d < best) best = d, bi = int(i), bj = int(j);
      }
    if (bi < 0) return false;
    const Eigen::Vector2d a = legs[std::size_t(bi)], b = legs[std::size_t(bj)];
    // Facing: perpendicular to the leg vector, towards (or away from) the sensor.
    const Eigen::Vector2d d = a - b, mid = 0.5 * (a + b);
    Eigen::Vector2d fwd(d.y(), -d.x());
    if ((fwd.dot(sensor - mid) < 0) == facing_sensor_) fwd = -fwd;
    est_.emplace(params_);
    est_->start(f.t, a, b, std::atan2(fwd.y(), fwd.x()));
    id_ = ids_.next();
    last_seen_ = f.t;
    return true;
  }

  Track row(const Frame& f) const {
    Track t;
    t.id = id_;
    t.x = est_->x();
    t.y = est_->y();
    t.yaw = est_->yaw();
    const Eigen::Vector2d v = est_->velocity();
    t.vx = v.x();
    t.vy = v.y();
    const Eigen::MatrixXd& P = est_->state().P;
    t.cov_xx = P(0, 0), t.cov_xy = P(0, 1), t.cov_yy = P(1, 1);
    t.has_cov = true;
    t.score = 1;
    t.status = f.t == last_seen_ ? toString(est_->zone()) : "coasting";
    return t;
  }

  LegPoseParams params_;
  bool from_detections_, facing_sensor_;
  double max_range_, lost_time_, occluded_width_;
  std::optional<LegPoseEstimator> est_;
  TrackIds ids_;
  long id_ = 0;
  double last_seen_ = 0;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P3: one person's pose [X, Y, theta] from two legs (zoning, gait model, CA KF, eq. 6-7)";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<LegPose>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::legpose

PEDTRACK_PLUGIN("leg_pose", pedtrack::legpose::describe)
