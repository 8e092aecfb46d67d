// scan_odometry: the robot's motion from matching its own scans (all scanners of a frame
// together), for data without odometry: a wheelchair bag with 2D scanners and no /tf, a lone live
// scanner. The frame's robot and sensor poses are moved into that odometry frame before any
// segmenter, classifier or tracker uses them, so detections, tracks, outputs and a tracker's
// static-scene grid all live in one frame where walls stand still.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "scan_odometry/scan_matcher.h"

namespace pedtrack::scanodometry {
namespace {

using track::ScanOdometry;
using track::ScanOdometryOptions;

enum class Mode { Auto, On, Off };

struct ScanOdometryParams {
  Mode mode = Mode::Auto;
  ScanOdometryOptions icp;  // its members' comments say why each default is what it is
};

const ParamTable<ScanOdometryParams>& table() {
  using P = ScanOdometryParams;
  using O = ScanOdometryOptions;
  static const auto t =
      ParamTable<P>()
          .choice(&P::mode, "mode", {{"auto", Mode::Auto}, {"on", Mode::On}, {"off", Mode::Off}},
                  "auto: only while the source gives no odometry (a bag without /tf or /odom, "
                  "a lone live scanner), and only once the match has moved 0.1 m or 3 deg from "
                  "the start (a standing scanner stays exact); on: always, replacing the "
                  "source's odometry; off: never")
          .real(path(&P::icp, &O::predict_for), "predict_for", "s", 0, 3600,
                "the constant-velocity prediction stands in for matches that fail this long; "
                "beyond it the pose is held and the robot's motion is unknown (outdoors, the "
                "view hidden): a tracker learns no static scene and judges no motion meanwhile")
          .real(path(&P::icp, &O::keyframe_distance), "keyframe_distance", "m", 0.01, 100,
                "a new keyframe once the robot moved this far from the current one")
          .real(path(&P::icp, &O::keyframe_angle), "keyframe_angle", "deg", 0.1, 180,
                "... or turned this much", kDegree)
          .real(path(&P::icp, &O::max_match_distance), "max_match_distance", "m", 0.01, 100,
                "ICP's initial correspondence distance (must exceed the prediction's error)")
          .integer(path(&P::icp, &O::max_iterations), "max_iterations", "", 1, 10000,
                   "ICP iterations at most")
          .real(path(&P::icp, &O::max_step), "max_step", "m", 0.01, 100,
                "a match farther than this from the constant-velocity prediction is rejected: "
                "0.25 m within a scan is beyond any robot's acceleration, a wrong alignment "
                "(outdoors, where little matches)")
          .real(path(&P::icp, &O::max_turn_step), "max_turn_step", "deg", 0.1, 180,
                "... or turned more than this from it", kDegree)
          .real(path(&P::icp, &O::max_speed), "max_speed", "m/s", 0, 100,
                "... or moving the robot faster than this since the last accepted pose (0: off)")
          .integer(path(&P::icp, &O::min_points), "min_points", "", 1, 1000000,
                   "a scan with fewer points (after thinning) is not matched: the prediction is "
                   "used")
          .real(path(&P::icp, &O::min_points_share), "min_points_share", "", 0, 1,
                "nor one with fewer points than this share of the median of the last "
                "recent_scans (most of the view suddenly hidden); 0: off")
          .integer(path(&P::icp, &O::recent_scans), "recent_scans", "", 1, 10000,
                   "scans whose median point count min_points_share uses")
          .integer(path(&P::icp, &O::sparse_points), "sparse_points", "", 0, 1000000,
                   "a scan with fewer points is sparse: matched against local_keyframes "
                   "keyframes together, every point in every iteration")
          .integer(path(&P::icp, &O::local_keyframes), "local_keyframes", "", 1, 100,
                   "keyframes a sparse scan is matched against together (1: the newest only)")
          .real(path(&P::icp, &O::decimation_cell), "decimation_cell", "m", 0.001, 10,
                "points are thinned to one per cell of this side before matching");
  return t;
}

class ScanOdometryStage : public Odometry {
 public:
  explicit ScanOdometryStage(const PluginContext& ctx) : p_(table().read(ctx.params)) {
    if (p_.mode != Mode::Off) matcher_.emplace(p_.icp);
  }

  void process(Frame& f) override {
    // auto: scan matching only for data without odometry, and for good once odometry appears
    // (mixing the two frames would move every track).
    if (matcher_ && p_.mode == Mode::Auto && f.has_odometry) matcher_.reset();
    if (matcher_) match(f);
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    if (!matcher_ || matcher_->matched() + matcher_->rejected() == 0) return {};
    return {{"scan_matches", matcher_->matched()}, {"scan_matches_rejected", matcher_->rejected()}};
  }

 private:
  void match(Frame& f) {
    const auto& cloud = f.cloud();
    // People walk: their returns would drag the match along with them (on a standing scanner in
    // a room with a few walkers, the estimate wandered 2-4 cm). Points near the people the
    // tracker knew after the last frame, moved into this robot frame by the last pose, are left
    // out of the match.
    std::vector<Eigen::Vector2d> people;
    for (const PlanarPoint& p : f.people) {
      double x, y, z;
      last_robot_.inverseComposePoint(p.x, p.y, 0, x, y, z);
      people.emplace_back(x, y);
    }
    std::vector<Eigen::Vector2d> pts;
    pts.reserve(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      if (!f.isKept(i)) continue;  // e.g. the robot's own footprint (height_band)
      float x, y, z;
      cloud.getPoint(i, x, y, z);
      const Eigen::Vector2d q(x, y);
      if (std::any_of(people.begin(), people.end(),
                      [&](const Eigen::Vector2d& c) { return (q - c).squaredNorm() < kPersonR2; }))
        continue;
      pts.push_back(q);
    }
    const mrpt::poses::CPose2D matched = matcher_->update(pts, f.t);
    // The constant-velocity prediction stands in for a failed match for a moment (a scan mostly
    // hidden by passers-by); matching that keeps failing (outdoors: nothing to match) leaves the
    // motion unknown. With the source's odometry (mode on) it is known whatever the match did.
    // Unknown also on the first frame matched again: the pose it jumps from was a guess.
    const bool guessed = !f.has_odometry && matcher_->guessing(f.t);
    f.motion_unknown = guessed || last_guessed_;
    last_guessed_ = guessed;
    // auto: a scanner that has not moved stays exactly where it started. Scan matching jitters
    // by 2-3 cm on a standing scanner, which blurs a static-scene grid and costs tracks; the
    // matched pose is used from the moment the robot has clearly moved (and from then on).
    if (p_.mode == Mode::On || matched.norm() > kMovedDistance ||
        std::abs(matched.phi()) > kMovedAngle)
      moved_ = true;
    const mrpt::poses::CPose3D ego =
        moved_ ? mrpt::poses::CPose3D(matched) : mrpt::poses::CPose3D();
    // The match starts where the robot was at the first scan it could match (with min_points;
    // before it the frame's own pose stands). With odometry as well (on), the match replaces it
    // from there: composing the two counted every motion twice.
    if (!start_ && matcher_->started()) start_ = f.robot_pose;
    const mrpt::poses::CPose3D robot = start_ ? *start_ + ego : f.robot_pose;
    const mrpt::poses::CPose3D old_inv = -f.robot_pose;  // sensor poses -> their mounts
    f.sensor_pose = robot + (old_inv + f.sensor_pose);
    for (SensorPose& s : f.sensors) s.pose = robot + (old_inv + s.pose);
    f.robot_pose = robot;
    last_robot_ = robot;
  }

  // Beyond the matcher's jitter on a standing scanner (2-3 cm, a fraction of a degree).
  static constexpr double kMovedDistance = 0.1, kMovedAngle = 3.0 * M_PI / 180;
  static constexpr double kPersonR2 = 0.5 * 0.5;  // m², a person's legs and a step around them
  const ScanOdometryParams p_;
  std::optional<ScanOdometry> matcher_;
  mrpt::poses::CPose3D last_robot_;  // the last frame's scan-matched robot pose
  bool moved_ = false;               // scan matching has seen the robot leave where it started
  bool last_guessed_ = false;        // the last frame's pose was a guess (motion unknown)
  std::optional<mrpt::poses::CPose3D> start_;  // the robot pose at the scan odometry's origin
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Odometry;
  d.doc =
      "The robot's motion from matching its scans (MRPT ICP against keyframes), for data "
      "without odometry";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ScanOdometryStage>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::scanodometry

PEDTRACK_PLUGIN("scan_odometry", pedtrack::scanodometry::describe)
