// leg_people: multi-person tracking from leg-height 2D scans (leg_tracker's scheme, P3's pose
// per person). Legs come from leg_circles (and, when a classifier ran, carry its score); every
// leg or clutter cluster is tracked, leg-like pairs become people, confirmed once they move.
// A local occupancy grid of the static scene (and an optional prior map) keeps people from
// starting on walls and furniture. With `follow`, one person is picked and marked "following".
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/track/gait_fit_ipopt.h"
#include "pedtrack/track/leg_people_tracker.h"
#include "pedtrack/track/leg_pose_params.h"
#include "pedtrack/track/scan_odometry.h"
#include "pedtrack/track/static_scene.h"

namespace pedtrack::legpeople {
namespace {

using namespace pedtrack::track;

LegPeopleParams readParams(const ParamSet& s) {
  LegPeopleParams p;
  p.pose = readLegPoseParams(s);
  p.pose.zoning.resolve_swaps = s.getBool("resolve_swaps");
  if (s.getString("gait_solver") == "ipopt") p.pose.gait_solver = &gait::fitIpopt;
  p.object_q = s.getDouble("object_q");
  p.object_sigma = s.getDouble("object_sigma");
  p.gate = s.getDouble("gate");
  p.object_max_coast = s.getDouble("object_max_coast");
  p.leg_score = s.getDouble("leg_score");
  p.moving_leg_score = s.getDouble("moving_leg_score");
  p.moving_confirm_travel = s.getDouble("moving_confirm_travel");
  p.max_confirm_speed = s.getDouble("max_confirm_speed");
  p.sure_leg_score = s.getDouble("sure_leg_score");
  p.sure_confirm_travel = s.getDouble("sure_confirm_travel");
  p.pair_distance = s.getDouble("pair_distance");
  p.confirm_travel = s.getDouble("confirm_travel");
  p.confirm_stride = s.getDouble("confirm_stride");
  p.max_coast = s.getDouble("max_coast");
  p.lost_velocity_window = s.getDouble("lost_velocity_window");
  p.max_coast_confirmed = s.getDouble("max_coast_confirmed");
  p.reacquire_spread = s.getDouble("reacquire_spread");
  p.reacquire_max = s.getDouble("reacquire_max");
  p.merge_distance = s.getDouble("merge_distance");
  p.reidentify_speed = s.getDouble("reidentify_speed");
  p.reidentify_max = s.getDouble("reidentify_max");
  p.reidentify_leg_scans = int(s.getInt("reidentify_leg_scans"));
  p.max_leg_spread = s.getDouble("max_leg_spread");
  p.flip_speed = s.getDouble("flip_speed");
  p.flip_time = s.getDouble("flip_time");
  p.init_speed = s.getDouble("init_speed");
  p.tentative_accel_var = s.getDouble("tentative_accel_var");
  p.tentative_sigma_xy = s.getDouble("tentative_sigma_xy");
  p.report_heading_speed = s.getDouble("report_heading_speed");
  p.report_heading_window = s.getDouble("report_heading_window");
  p.support_gate = s.getDouble("support_gate");
  p.one_leg_stand = s.getDouble("one_leg_stand");
  return p;
}

class LegPeople : public Tracker {
 public:
  explicit LegPeople(const PluginContext& ctx)
      : tracker_(readParams(ctx.params)),
        report_tentative_(ctx.params.getBool("report_tentative")),
        follow_(ctx.params.getString("follow")),
        follow_zone_(ctx.params.getVector("follow_zone")),
        static_radius_(ctx.params.getDouble("static_radius")),
        report_coast_(ctx.params.getDouble("report_coast")),
        support_(ctx.params.getDouble("support_gate") > 0) {
    if (ctx.params.getBool("static_scene")) {
      StaticScene::Options o;
      o.persist = ctx.params.getDouble("static_persist");
      o.prior_map = ctx.params.getString("prior_map");
      o.cell = ctx.params.getDouble("static_cell");
      scene_.emplace(o);
    }
    scan_odometry_ = ctx.params.getString("scan_odometry");
    if (scan_odometry_ != "off") odometry_.emplace();
    if (follow_ != "off" && follow_ != "nearest") {
      char* end = nullptr;
      follow_id_ = std::strtol(follow_.c_str(), &end, 10);
      if (!end || *end || follow_id_ <= 0)
        throw ConfigError(ctx.params.where("follow") + ": '" + follow_ +
                          "' is not off, nearest or a track id");
    }
  }

  void process(Frame& f) override {
    // auto: scan matching only for data without odometry, and for good once odometry appears
    // (mixing the two frames would move every track).
    if (odometry_ && scan_odometry_ == "auto" && f.has_odometry) odometry_.reset();
    if (odometry_) useScanOdometry(f);
    std::vector<LegDetection> legs = detections(f);
    std::function<bool(double, double)> is_static;
    if (scene_)
      is_static = [&](double x, double y) { return scene_->isStatic(x, y, f.t, static_radius_); };
    tracker_.step(f.t, legs, is_static, returnsOutsideLegs(f));
    if (scene_) scene_->update(f, tracker_.occupiedByPeople());
    const auto people = tracker_.people();
    chooseFollowed(f, people);
    for (const PersonState& s : people) {
      if (!s.confirmed && !report_tentative_) continue;
      if (s.unseen > report_coast_) continue;  // kept for re-acquisition, not reported
      Track t;
      t.id = s.id;
      t.x = s.p.x(), t.y = s.p.y();
      t.vx = s.v.x(), t.vy = s.v.y();
      t.yaw = s.yaw;
      t.cov_xx = s.cov(0, 0), t.cov_xy = s.cov(0, 1), t.cov_yy = s.cov(1, 1);
      t.has_cov = true;
      t.score = s.score;
      t.cluster = s.cluster;
      t.status = s.id == followed_ ? "following"
                 : s.confirmed     ? (s.seen ? "confirmed" : "coasting")
                                   : "tentative";
      f.tracks.push_back(t);
    }
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    std::vector<std::pair<std::string, long>> c{{"objects", long(tracker_.objectCount())}};
    if (odometry_ && odometry_->matched() + odometry_->rejected() > 0) {
      c.emplace_back("scan_matches", odometry_->matched());
      c.emplace_back("scan_matches_rejected", odometry_->rejected());
    }
    return c;
  }

 private:
  // Leg circles in the fixed frame with the classifier's score (1 when no classifier ran), each
  // with the position of the scanner that saw it (the nearest one, with several scanners).
  std::vector<LegDetection> detections(const Frame& f) const {
    std::map<int, double> score;
    for (const Detection& d : f.detections)
      if (d.cluster >= 0) score[d.cluster] = d.score;
    const bool classified = !score.empty() || classifier_seen_;
    classifier_seen_ = classified;
    std::vector<LegDetection> out;
    out.reserve(f.clusters.size());
    for (std::size_t i = 0; i < f.clusters.size(); ++i) {
      const Cluster& c = f.clusters[i];
      LegDetection d;
      double x, y, z;
      f.robot_pose.composePoint(c.cx, c.cy, c.cz, x, y, z);
      d.p = {x, y};
      auto it = score.find(int(i));
      d.score = it != score.end() ? it->second : (classified ? 0.0 : 1.0);
      d.scored = classified;
      d.sensor = nearestSensor(f, d.p);
      d.cluster = int(i);
      out.push_back(d);
    }
    return out;
  }

  // The scan's returns in the fixed frame that are part of no leg circle (support_gate): a leg
  // seen by one or two beams, or by many that fit no circle. None when support_gate is off.
  std::vector<LegReturn> returnsOutsideLegs(const Frame& f) const {
    if (!support_) return {};
    const std::vector<std::int32_t> labels = runLabels(f).labels;
    const auto& cloud = f.cloud();
    std::vector<LegReturn> out;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] != run_label::kUnclustered) continue;  // a leg's, the ground's, removed
      float x, y, z;
      cloud.getPoint(i, x, y, z);
      LegReturn r;
      double gx, gy, gz;
      f.robot_pose.composePoint(x, y, z, gx, gy, gz);
      r.p = {gx, gy};
      r.sensor = nearestSensor(f, r.p);
      out.push_back(r);
    }
    return out;
  }

  // Data without odometry: the robot's motion from matching its scans (all scanners together);
  // the frame's robot and sensor poses are moved into that odometry frame, so tracks, outputs
  // and the static scene all live in a frame where walls stand still.
  void useScanOdometry(Frame& f) {
    const auto& cloud = f.cloud();
    // People walk: their returns would drag the match along with them (on a standing scanner in
    // a room with a few walkers, the estimate wandered 2-4 cm). Points near the people of the
    // last scan, moved into this robot frame by the last pose, are left out of the match.
    std::vector<Eigen::Vector2d> people;
    for (const PersonState& s : tracker_.people()) {
      if (s.lost) continue;  // kept only for re-identification
      double x, y, z;
      last_robot_.inverseComposePoint(s.p.x(), s.p.y(), 0, x, y, z);
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
    const mrpt::poses::CPose2D matched = odometry_->update(pts, f.t);
    // auto: a scanner that has not moved stays exactly where it started. Scan matching jitters
    // by 2-3 cm on a standing scanner, which blurs the static scene and costs tracks; the
    // matched pose is used from the moment the robot has clearly moved (and from then on).
    if (scan_odometry_ == "on" || matched.norm() > kMovedDistance ||
        std::abs(matched.phi()) > kMovedAngle)
      moved_ = true;
    const mrpt::poses::CPose3D ego =
        moved_ ? mrpt::poses::CPose3D(matched) : mrpt::poses::CPose3D();
    // The match starts where the robot was at the first scan it could match (with min_points;
    // before it the frame's own pose stands). With odometry as well (on), the match replaces it
    // from there: composing the two counted every motion twice.
    if (!start_ && odometry_->started()) start_ = f.robot_pose;
    const mrpt::poses::CPose3D robot = start_ ? *start_ + ego : f.robot_pose;
    const mrpt::poses::CPose3D old_inv = -f.robot_pose;  // sensor poses -> their mounts
    f.sensor_pose = robot + (old_inv + f.sensor_pose);
    for (SensorPose& s : f.sensors) s.pose = robot + (old_inv + s.pose);
    f.robot_pose = robot;
    last_robot_ = robot;
  }

  // The scanner nearest to a fixed-frame point: with several scanners merged, the one that saw it
  // (the apex of P3 eq. 6's hidden area).
  static Eigen::Vector2d nearestSensor(const Frame& f, const Eigen::Vector2d& p) {
    Eigen::Vector2d best(f.sensor_pose.x(), f.sensor_pose.y());
    double bd = INFINITY;
    for (const SensorPose& s : f.sensors) {
      const Eigen::Vector2d q(s.pose.x(), s.pose.y());
      if ((q - p).norm() < bd) bd = (q - p).norm(), best = q;
    }
    return best;
  }

  // Person following: the given track, or the nearest confirmed person inside the zone in front
  // of the robot [x_min, x_max] × [−half_width, half_width] (robot frame), kept while it lives.
  void chooseFollowed(const Frame& f, const std::vector<PersonState>& people) {
    if (follow_ == "off") return;
    bool alive = false;
    // Only people still written count: one lost from sight is kept (max_coast_confirmed) for
    // re-identification, not followed.
    auto followable = [&](const PersonState& s) {
      return s.confirmed && s.unseen <= report_coast_;
    };
    for (const auto& s : people) alive |= s.id == followed_ && followable(s);
    if (alive) return;
    followed_ = 0;
    if (follow_id_ > 0) {
      for (const auto& s : people)
        if (s.id == follow_id_ && followable(s)) followed_ = s.id;
      return;
    }
    double best = INFINITY;
    const mrpt::poses::CPose3D inv = -f.robot_pose;
    for (const auto& s : people) {
      if (!followable(s)) continue;
      double x, y, z;
      inv.composePoint(s.p.x(), s.p.y(), 0, x, y, z);
      if (x < follow_zone_[0] || x > follow_zone_[1] || std::abs(y) > follow_zone_[2]) continue;
      const double d = std::hypot(x, y);
      if (d < best) best = d, followed_ = s.id;
    }
  }

  LegPeopleTracker tracker_;
  std::optional<StaticScene> scene_;
  std::optional<ScanOdometry> odometry_;
  mrpt::poses::CPose3D last_robot_;  // the last frame's scan-matched robot pose
  bool moved_ = false;               // scan matching has seen the robot leave where it started
  std::optional<mrpt::poses::CPose3D> start_;  // the robot pose at the scan odometry's origin
  // Beyond the matcher's jitter on a standing scanner (2-3 cm, a fraction of a degree).
  static constexpr double kMovedDistance = 0.1, kMovedAngle = 3.0 * M_PI / 180;
  static constexpr double kPersonR2 = 0.5 * 0.5;  // m², a person's legs and a step around them
  std::string scan_odometry_;                     // auto, on or off
  bool report_tentative_;
  std::string follow_;
  long follow_id_ = 0, followed_ = 0;
  std::vector<double> follow_zone_;
  double static_radius_;
  double report_coast_;
  bool support_;  // support_gate > 0: the tracker is given the returns of no leg circle
  mutable bool classifier_seen_ = false;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "People from leg-height scans: leg and clutter tracks, leg pairs, P3 pose per person";
  const LegPeopleParams def;
  const StaticScene::Options so;
  d.params = {
      ParamSpec::real("object_q", def.object_q, "m2/s3", 1e-6, 1e6,
                      "constant-velocity noise of a leg or clutter track"),
      ParamSpec::real("object_sigma", def.object_sigma, "m", 1e-4, 10, "leg centre noise"),
      ParamSpec::real("gate", def.gate, "m", 0.01, 10,
                      "largest distance from a predicted leg to the leg it is associated with"),
      ParamSpec::real("object_max_coast", def.object_max_coast, "s", 0, 3600,
                      "a leg or clutter track unseen this long is dropped"),
      ParamSpec::real("leg_score", def.leg_score, "", 0, 1,
                      "tracks whose mean classifier score reaches this are legs"),
      ParamSpec::real("moving_leg_score", def.moving_leg_score, "", 0, 1,
                      "a track moving at init_speed or more is leg-like from this mean score on "
                      "(far legs score low but walk), and so is one where a confirmed person's "
                      "missing leg is predicted"),
      ParamSpec::real("moving_confirm_travel", def.moving_confirm_travel, "m", 0, 100,
                      "a person whose legs' mean score is below leg_score is confirmed once it "
                      "moved this far"),
      ParamSpec::real("sure_leg_score", def.sure_leg_score, "", 0, 1,
                      "a person whose legs' mean classifier score reaches this is confirmed after "
                      "sure_confirm_travel (at most confirm_travel; a person standing by the "
                      "robot, shifting their weight); only where a classifier scored the "
                      "legs; 1: off"),
      ParamSpec::real("sure_confirm_travel", def.sure_confirm_travel, "m", 0, 100,
                      "see sure_leg_score (legs must still have scissored: confirm_stride)"),
      ParamSpec::real("max_confirm_speed", def.max_confirm_speed, "m/s", 0, 100,
                      "no person is confirmed while estimated faster than this (a brisk walk): "
                      "such speeds are mostly a leg jumping to a neighbouring object"),
      ParamSpec::real("pair_distance", def.pair_distance, "m", 0, 5,
                      "two legs at most this far apart form a person"),
      ParamSpec::real("confirm_travel", def.confirm_travel, "m", 0, 100,
                      "a new person is confirmed (reported) once it moved this far"),
      ParamSpec::real("confirm_stride", def.confirm_stride, "m", 0, 10,
                      "... and once its legs scissored: their separation along its motion swung "
                      "over this range (two objects slid together by the robot's motion never "
                      "do); 0: off"),
      ParamSpec::real(
          "lost_velocity_window", def.lost_velocity_window, "s", 0, 60,
          "a confirmed person lost from sight coasts at their centre's mean velocity over the "
          "last this long they were seen, when slower than their filter's (the last "
          "leg fits before an occlusion often read a jump); 0: off"),
      ParamSpec::real("max_coast", def.max_coast, "s", 0, 3600,
                      "a tentative person with neither leg seen this long is deleted, and a "
                      "confirmed one at the earliest"),
      ParamSpec::real("max_coast_confirmed", def.max_coast_confirmed, "s", 0, 3600,
                      "a confirmed person with neither leg seen is deleted after as long as they "
                      "had been seen while confirmed, at most this (at least max_coast): "
                      "a person back from behind others or from outside the view is "
                      "re-identified (reidentify_speed) without a second confirmation"),
      ParamSpec::real("reacquire_spread", def.reacquire_spread, "m/s", 0, 100,
                      "while a confirmed person is unseen (occluded in a crowd), the gate in which "
                      "a free leg becomes theirs widens this fast"),
      ParamSpec::real("reacquire_max", def.reacquire_max, "m", 0, 10,
                      "... by at most this much beyond leg_gate"),
      ParamSpec::real("reidentify_speed", def.reidentify_speed, "m/s", 0, 100,
                      "a confirmed person lost from sight takes back a new leg pair within "
                      "leg_gate plus this speed times their time unseen of where they were "
                      "predicted (keeps their id through occlusions), or a lone leg "
                      "(reidentify_leg_scans); 0: off, both"),
      ParamSpec::real("reidentify_max", def.reidentify_max, "m", 0, 100,
                      "... that radius grows by at most this much beyond leg_gate"),
      ParamSpec::integer(
          "reidentify_leg_scans", def.reidentify_leg_scans, "scans", 0, 1000,
          "a confirmed person with no leg left takes back a lone walking leg "
          "(off the static scene, no free leg-like object, furniture included, within "
          "pair_distance) within that radius once it has been tracked this many "
          "scans; 0: off (pairs only)"),
      ParamSpec::real("merge_distance", def.merge_distance, "m", 0, 10,
                      "two people closer than this are one (bodies do not interpenetrate): the "
                      "tentative, else the one seen less recently, else the newer goes; two "
                      "confirmed people only when both are seen; 0: off"),
      ParamSpec::real("max_leg_spread", def.max_leg_spread, "m", 0.1, 10,
                      "a person's legs farther apart than this: the outer one is dropped"),
      ParamSpec::real("flip_speed", def.flip_speed, "m/s", 0, 100,
                      "walking backwards faster than this for flip_time turns the facing round"),
      ParamSpec::real("flip_time", def.flip_time, "s", 0, 3600, "see flip_speed"),
      ParamSpec::real("init_speed", def.init_speed, "m/s", 0, 100,
                      "a new person faces their legs' motion above this speed, else the scanner"),
      ParamSpec::real("tentative_accel_var", def.tentative_accel_var, "(m/s2)2", 1e-9, 1e9,
                      "variance of a tentative person's X and Y acceleration noise (P3: 100); "
                      "accel_var applies once confirmed. Close to the legs, the filter shows a leg "
                      "jumping to a neighbouring object as a speed no walker has"),
      ParamSpec::real("tentative_sigma_xy", def.tentative_sigma_xy, "m", 1e-6, 10,
                      "std. dev. of a tentative person's legs' midpoint measurement (P3: 0.03); "
                      "sigma_xy applies once confirmed"),
      ParamSpec::real("report_heading_speed", def.report_heading_speed, "m/s", 0, 100,
                      "the written yaw is the person's direction of motion (the way they moved "
                      "over report_heading_window) whenever that is at least this fast, else the "
                      "last such direction (the pose estimator's orientation until they first "
                      "move; it still predicts the legs). Crowds: heading MAE 49 -> 28 deg. 0: "
                      "the pose estimator's orientation"),
      ParamSpec::real("report_heading_window", def.report_heading_window, "s", 0.01, 60,
                      "see report_heading_speed"),
      ParamSpec::choice("scan_odometry", "auto", {"auto", "on", "off"},
                        "the robot's motion from matching each frame's scans (MRPT ICP against "
                        "keyframes), tracked in that frame so walls stand still on a robot "
                        "without odometry (robot poses in outputs become it). auto: only while "
                        "the source gives no odometry (a bag without /tf or /odom, a lone live "
                        "scanner), and only once the match has moved 0.1 m or 3 deg from the "
                        "start (a standing scanner stays exact); on: always; off: never"),
      ParamSpec::real("report_coast", 0.5, "s", 0, 3600,
                      "a person unseen longer than this is no longer written (kept until "
                      "deleted, max_coast / max_coast_confirmed, so their legs can be "
                      "re-acquired behind an occlusion)"),
      ParamSpec::real("support_gate", def.support_gate, "m", 0, 10,
                      "a confirmed person's leg no leg circle shows is still seen where scan "
                      "returns of no leg circle (one or two beams: far, or all but hidden; many "
                      "that fit no circle: wide trousers) lie within this of where the gait "
                      "predicts it, off the static scene; 0: off"),
      ParamSpec::real("one_leg_stand", def.one_leg_stand, "s", 0, 3600,
                      "a confirmed person held up this long by one leg track alone, standing "
                      "(within 0.1 m) on the static scene, or (within 0.25 m) while the scanner "
                      "moved 45 deg or more round it, is a track left on a pole or a table leg: "
                      "that leg track is let go and never a person's leg again (one seen only in "
                      "returns of no circle, support_gate, no longer holds the person up); 0: off"),
      ParamSpec::boolean("resolve_swaps", true,
                         "a turn in place of over 90° between two scans is read as the person's "
                         "legs swapped by the assignment (the nearer perpendicular), not a turn"),
      ParamSpec::boolean("report_tentative", false, "also write tracks not yet confirmed"),
      ParamSpec::boolean("static_scene", true,
                         "no person starts in a cell the local occupancy grid (or the prior map) "
                         "has seen occupied for static_persist seconds"),
      ParamSpec::real("static_persist", 1.0, "s", 0, 3600,
                      "a cell occupied this long (not by a confirmed person) is static scene; "
                      "short, as a new person must walk to be confirmed anyway, and a moving "
                      "robot sees furniture only for seconds"),
      ParamSpec::real("static_cell", so.cell, "m", 0.01, 1, "cell size of the static-scene grid"),
      ParamSpec::real("static_radius", 0.07, "m", 0, 1,
                      "a leg whose circle centre has a static cell this close is on the static "
                      "scene (the centre lies a leg radius behind the points it was fitted to)"),
      ParamSpec::text("prior_map", std::string(),
                      "optional map of the fixed frame: ROS map.yaml or MRPT .gridmap; its "
                      "occupied cells are static scene"),
      ParamSpec::text("follow", std::string("off"),
                      "person following: off, nearest (the nearest confirmed person in "
                      "follow_zone, re-chosen when lost) or a track id; marked `following`"),
      ParamSpec::vector("follow_zone", std::vector<double>{0.3, 3.0, 1.0}, "m", 3, -100, 100,
                        "x_min x_max half_width of the zone in front of the robot (robot frame)"),
  };
  const auto pose = legPoseParamSpecs(def.pose);
  d.params.insert(d.params.end(), pose.begin(), pose.end());
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<LegPeople>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::legpeople

PEDTRACK_PLUGIN("leg_people", pedtrack::legpeople::describe)
