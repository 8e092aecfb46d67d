// leg_people: multi-person tracking from leg-height 2D scans (leg_tracker's scheme, P3's pose
// per person). Legs come from leg_circles (and, when a classifier ran, carry its score); every
// leg or clutter cluster is tracked, leg-like pairs become people, confirmed once they move.
// A local occupancy grid of the static scene (and an optional prior map) keeps people from
// starting on walls and furniture. With `follow`, one person is picked and marked "following".
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "leg_people/leg_people_tracker.h"
#include "pedtrack/errors.h"
#include "pedtrack/ipopt/gait_fit.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/track/leg_pose_params.h"
#include "pedtrack/track/static_scene.h"

namespace pedtrack::legpeople {
namespace {

using namespace pedtrack::track;

struct LegPeopleStageParams {
  LegPeopleParams tracker;  // legs, pairs, confirmation, re-identification, pose
  bool report_tentative = false;
  std::string follow = "off";                      // off, nearest or a track id
  std::vector<double> follow_zone{0.3, 3.0, 1.0};  // x_min x_max half_width, robot frame (m)
  double static_radius = 0.07;  // m: a leg's circle centre lies a leg radius behind its points
  double report_coast = 0.5;    // s unseen before a person is no longer written
  double follow_coast = 2.0;    // s unseen before the followed person is no longer written
  bool static_scene = true;
  bool out_of_view = true;  // a place no scanner looks at counts as hidden (max_coast_occluded)
  // Cells occupied for a second (not by a confirmed person) are static scene here, not the
  // grid's general 3 s: a new person must walk to be confirmed anyway, and a moving robot sees
  // furniture only for seconds.
  StaticScene::Options scene = [] {
    StaticScene::Options o;
    o.persist = 1.0;
    return o;
  }();
};

// The tracker's own keys (leg_people_tracker.h's LegPeopleParams; its pose estimator's keys are
// P3's, legPoseTable, with leg_people's defaults).
const ParamTable<LegPeopleParams>& trackerTable() {
  using T = LegPeopleParams;
  static const auto t =
      ParamTable<T>()
          .real(&T::object_q, "object_q", "m2/s3", 1e-6, 1e6,
                "constant-velocity noise of a leg or clutter track")
          .real(&T::object_sigma, "object_sigma", "m", 1e-4, 10, "leg centre noise")
          .real(&T::gate, "gate", "m", 0.01, 10,
                "largest distance from a predicted leg to the leg it is associated with")
          .real(&T::standing_gate, "standing_gate", "m", 0, 10,
                "the gate of a standing confirmed person's legs (centre moved < 0.2 m in the "
                "last second), and of a tentative person's standing 0.3 s in follow_zone while "
                "nobody is followed: a leg at rest does not jump, its detection dropped while "
                "clutter beside them was seen; 0: gate for everyone")
          .real(&T::unknown_motion_tau, "unknown_motion_tau", "s", 0, 3600,
                "where the robot's motion is unknown (Frame::motion_unknown), a person's "
                "velocity decays with this time constant before each prediction: in the "
                "tracking frame it is theirs less the robot's, which turns; 0: off")
          .real(&T::object_max_coast, "object_max_coast", "s", 0, 3600,
                "a leg or clutter track unseen this long is dropped")
          .real(&T::leg_score, "leg_score", "", 0, 1,
                "tracks whose mean classifier score reaches this are legs")
          .real(&T::moving_leg_score, "moving_leg_score", "", 0, 1,
                "a track moving at init_speed or more is leg-like from this mean score on "
                "(far legs score low but walk), and so is one where a confirmed person's "
                "missing leg is predicted")
          .real(&T::moving_confirm_travel, "moving_confirm_travel", "m", 0, 100,
                "a person whose legs' mean score is below leg_score is confirmed once it "
                "moved this far")
          .real(&T::sure_leg_score, "sure_leg_score", "", 0, 1,
                "a person whose legs' mean classifier score reaches this is confirmed after "
                "sure_confirm_travel (at most confirm_travel; a person standing by the "
                "robot, shifting their weight); only where a classifier scored the "
                "legs; 1: off")
          .real(&T::sure_confirm_travel, "sure_confirm_travel", "m", 0, 100,
                "see sure_leg_score (legs must still have scissored: confirm_stride)")
          .real(&T::max_confirm_speed, "max_confirm_speed", "m/s", 0, 100,
                "no person is confirmed while estimated faster than this (a brisk walk): "
                "such speeds are mostly a leg jumping to a neighbouring object")
          .real(&T::pair_distance, "pair_distance", "m", 0, 5,
                "two legs at most this far apart form a person")
          .real(&T::confirm_travel, "confirm_travel", "m", 0, 100,
                "a new person is confirmed (reported) once it moved this far")
          .real(&T::confirm_stride, "confirm_stride", "m", 0, 10,
                "... and once its legs scissored: their separation along its motion swung "
                "over this range (two objects slid together by the robot's motion never "
                "do); 0: off")
          .real(&T::max_travel_turn_rate, "max_travel_turn_rate", "deg/s", 0, 3600,
                "the way a tentative person goes while the robot turns faster than this does "
                "not count towards confirm_travel (skewed scans and scan matching err most in "
                "turns: furniture slides at a walker's pace); 0: off",
                kDegree)
          .real(
              &T::lost_velocity_window, "lost_velocity_window", "s", 0, 60,
              "a confirmed person lost from sight coasts at their centre's mean velocity over the "
              "last this long they were seen, when slower than their filter's (the last "
              "leg fits before an occlusion often read a jump); 0: off")
          .real(&T::max_coast, "max_coast", "s", 0, 3600,
                "a tentative person with neither leg seen this long is deleted, and a "
                "confirmed one at the earliest")
          .real(&T::max_coast_confirmed, "max_coast_confirmed", "s", 0, 3600,
                "a confirmed person with neither leg seen is deleted after as long as they "
                "had been seen while confirmed, at most this (at least max_coast): "
                "a person back from behind others or from outside the view is "
                "re-identified (reidentify_speed) without a second confirmation")
          .real(&T::reacquire_spread, "reacquire_spread", "m/s", 0, 100,
                "while a confirmed person is unseen (occluded in a crowd), the gate in which "
                "a free leg becomes theirs widens this fast (not where the robot's motion is "
                "unknown)")
          .real(&T::reacquire_max, "reacquire_max", "m", 0, 10,
                "... by at most this much beyond leg_gate")
          .real(
              &T::reidentify_speed, "reidentify_speed", "m/s", 0, 100,
              "a confirmed person lost from sight takes back a new leg pair within "
              "leg_gate plus this speed times their time unseen of where they were "
              "predicted (keeps their id through occlusions), or a lone leg "
              "(reidentify_leg_scans); where the robot's motion is unknown, within leg_gate only; "
              "0: off, both")
          .real(&T::reidentify_max, "reidentify_max", "m", 0, 100,
                "... that radius grows by at most this much beyond leg_gate")
          .integer(&T::reidentify_leg_scans, "reidentify_leg_scans", "scans", 0, 1000,
                   "a confirmed person with no leg left takes back a lone walking leg "
                   "(off the static scene, no free leg-like object, furniture included, within "
                   "pair_distance) within that radius once it has been tracked this many "
                   "scans; 0: off (pairs only)")
          .real(&T::merge_distance, "merge_distance", "m", 0, 10,
                "two people closer than this are one (bodies do not interpenetrate): the "
                "tentative, else the one seen less recently, else the newer goes; two "
                "confirmed people only when both are seen; 0: off")
          .real(&T::max_leg_spread, "max_leg_spread", "m", 0.1, 10,
                "a person's legs farther apart than this: the outer one is dropped")
          .real(&T::flip_speed, "flip_speed", "m/s", 0, 100,
                "walking backwards faster than this for flip_time turns the facing round")
          .real(&T::flip_time, "flip_time", "s", 0, 3600, "see flip_speed")
          .real(&T::init_speed, "init_speed", "m/s", 0, 100,
                "a new person faces their legs' motion above this speed, else the scanner")
          .real(&T::tentative_accel_var, "tentative_accel_var", "(m/s2)2", 1e-9, 1e9,
                "variance of a tentative person's X and Y acceleration noise (P3: 100); "
                "accel_var applies once confirmed. Close to the legs, the filter shows a leg "
                "jumping to a neighbouring object as a speed no walker has")
          .real(&T::tentative_sigma_xy, "tentative_sigma_xy", "m", 1e-6, 10,
                "std. dev. of a tentative person's legs' midpoint measurement (P3: 0.03); "
                "sigma_xy applies once confirmed")
          .real(&T::report_heading_speed, "report_heading_speed", "m/s", 0, 100,
                "the written yaw is the person's direction of motion (the way they moved "
                "over report_heading_window) whenever that is at least this fast, else the "
                "last such direction (the pose estimator's orientation until they first "
                "move; it still predicts the legs). Crowds: heading MAE 49 -> 28 deg. 0: "
                "the pose estimator's orientation")
          .real(&T::report_heading_window, "report_heading_window", "s", 0.01, 60,
                "see report_heading_speed")
          .real(
              &T::support_gate, "support_gate", "m", 0, 10,
              "a confirmed person's leg no leg circle shows is still seen where scan "
              "returns of no leg circle (one or two beams: far, or all but hidden; many "
              "that fit no circle: wide trousers) lie within this of where the gait "
              "predicts it, off the static scene (not where the robot's motion is unknown); 0: off")
          .real(&T::one_leg_stand, "one_leg_stand", "s", 0, 3600,
                "a confirmed person held up this long by one leg track alone, standing "
                "(within 0.1 m) on the static scene, or (within 0.25 m) while the scanner "
                "moved 45 deg or more round it, is a track left on a pole or a table leg: "
                "that leg track is let go and never a person's leg again (one seen only in "
                "returns of no circle, support_gate, no longer holds the person up); 0: off")
          .real(&T::follow_confirm_time, "follow_confirm_time", "s", 0, 3600,
                "with follow on and nobody followed, a tentative person inside follow_zone "
                "whose legs look like legs (leg_score) and were both seen over this long is "
                "confirmed without walking (the person to follow stands in front of the "
                "robot); 0: off")
          .real(&T::max_coast_occluded, "max_coast_occluded", "s", 0, 3600,
                "a confirmed person unseen while something nearer the scanner hides where "
                "they are predicted (a pillar, a passer-by) is kept up to this long, however "
                "briefly tracked (time unseen in plain view still counts towards max_coast "
                "and max_coast_confirmed); 0: off")
          .real(&T::max_one_leg, "max_one_leg", "s", 0, 3600,
                "a confirmed person not seen by both legs this long is deleted, counting only "
                "time nothing nearer explains (one leg seen, the other's place in view; gaps "
                "between sightings in view, each up to max_coast): a track that slid onto "
                "clutter lives on single sightings; 0: off")
          .boolean(path(&T::pose, &LegPoseParams::zoning, &ZoningParams::resolve_swaps),
                   "resolve_swaps",
                   "a turn in place of over 90° between two scans is read as the person's "
                   "legs swapped by the assignment (the nearer perpendicular), not a turn")
          .include(&T::pose, legPoseTable());
  return t;
}

const ParamTable<LegPeopleStageParams>& table() {
  using P = LegPeopleStageParams;
  static const auto t =
      ParamTable<P>()
          .include(&P::tracker, trackerTable())
          .real(&P::report_coast, "report_coast", "s", 0, 3600,
                "a person unseen longer than this is no longer written (kept until "
                "deleted, max_coast / max_coast_confirmed, so their legs can be "
                "re-acquired behind an occlusion)")
          .real(&P::follow_coast, "follow_coast", "s", 0, 3600,
                "the followed person is written, and stays the one followed, while unseen up "
                "to this long (at most max_coast): a person walking ahead of a following robot "
                "is lost for a second when their legs merge or turn edge-on, and does not "
                "stop existing then")
          .boolean(&P::report_tentative, "report_tentative", "also write tracks not yet confirmed")
          .boolean(&P::out_of_view, "out_of_view",
                   "a person's place outside every scanner's aperture or range counts as hidden "
                   "(max_coast_occluded), as one behind a nearer return does")
          .boolean(&P::static_scene, "static_scene",
                   "no person starts in a cell the local occupancy grid (or the prior map) "
                   "has seen occupied for static_persist seconds")
          .real(path(&P::scene, &StaticScene::Options::persist), "static_persist", "s", 0, 3600,
                "a cell occupied this long (not by a confirmed person) is static scene; "
                "short, as a new person must walk to be confirmed anyway, and a moving "
                "robot sees furniture only for seconds")
          .real(path(&P::scene, &StaticScene::Options::cell), "static_cell", "m", 0.01, 1,
                "cell size of the static-scene grid")
          .real(&P::static_radius, "static_radius", "m", 0, 1,
                "a leg whose circle centre has a static cell this close is on the static "
                "scene (the centre lies a leg radius behind the points it was fitted to)")
          .text(path(&P::scene, &StaticScene::Options::prior_map), "prior_map",
                "optional map of the fixed frame: ROS map.yaml or MRPT .gridmap; its "
                "occupied cells are static scene")
          .text(&P::follow, "follow",
                "person following: off, nearest (the nearest confirmed person in "
                "follow_zone, re-chosen when lost or out of the zone for longer than "
                "follow_coast) or a track id; marked `following`")
          .vector(&P::follow_zone, "follow_zone", "m", 3, -100, 100,
                  "x_min x_max half_width of the zone in front of the robot (robot frame)");
  return t;
}

// The tracker's parameters with the gait solver the `gait_solver` key chose plugged in.
LegPeopleParams withGaitSolver(LegPeopleParams p) {
  gait::useChosenGaitSolver(p.pose);
  return p;
}

class LegPeople : public Tracker {
 public:
  explicit LegPeople(const PluginContext& ctx) : LegPeople(ctx, table().read(ctx.params)) {}

  LegPeople(const PluginContext& ctx, LegPeopleStageParams p)
      : tracker_(withGaitSolver(p.tracker)),
        report_tentative_(p.report_tentative),
        follow_(p.follow),
        follow_zone_(p.follow_zone),
        static_radius_(p.static_radius),
        report_coast_(p.report_coast),
        follow_coast_(p.follow_coast),
        support_(p.tracker.support_gate > 0),
        out_of_view_(p.out_of_view) {
    if (p.static_scene) scene_.emplace(p.scene);
    if (follow_ != "off" && follow_ != "nearest") {
      char* end = nullptr;
      follow_id_ = std::strtol(follow_.c_str(), &end, 10);
      if (!end || *end || follow_id_ <= 0)
        throw ConfigError(table().where(ctx.params, &LegPeopleStageParams::follow) + ": '" +
                          follow_ + "' is not off, nearest or a track id");
    }
  }

  void process(Frame& f) override {
    std::vector<LegDetection> legs = detections(f);
    // The robot may have moved by an unknown amount (scan matching found nothing to match): what
    // the grid learned may now lie anywhere, and a person who keeps pace with the robot would
    // stand still in this frame. The grid forgets and learns nothing until the motion is known.
    if (scene_ && f.motion_unknown) scene_->forget();
    std::function<bool(double, double)> is_static;
    if (scene_)
      is_static = [&](double x, double y) { return scene_->isStatic(x, y, f.t, static_radius_); };
    // With follow on and nobody followed, the zone in front of the robot is where the person to
    // follow is expected.
    std::function<bool(double, double)> expected;
    if (follow_ == "nearest" && followed_ == 0) {
      const mrpt::poses::CPose3D inv = -f.robot_pose;
      expected = [this, inv](double x, double y) {
        return inFollowZone(inRobotFrame(inv, {x, y}));
      };
    }
    // Whether a place is hidden behind a nearer return (max_coast_occluded): every kept point,
    // in the fixed frame, built on first use.
    std::vector<Eigen::Vector2d> points;
    auto occluded = [&](double x, double y, double half_width) {
      if (out_of_view_ && outOfView(f, {x, y})) return true;
      if (points.empty()) points = keptPoints(f);
      return hiddenBehind(f, {x, y}, half_width, points);
    };
    tracker_.setFollowed(followed_);
    tracker_.step(f.t, legs, is_static, returnsOutsideLegs(f), !f.motion_unknown, expected,
                  occluded, turnRate(f));
    if (scene_ && !f.motion_unknown) scene_->update(f, tracker_.occupiedByPeople());
    const auto people = tracker_.people();
    // For the next frame's stages (scan matching leaves people's returns out): everyone but
    // those kept only for re-identification.
    f.people.clear();
    for (const PersonState& s : people)
      if (!s.lost) f.people.push_back({s.p.x(), s.p.y()});
    chooseFollowed(f, people);
    for (const PersonState& s : people) {
      if (!s.confirmed && !report_tentative_) continue;
      // Kept for re-acquisition, not reported.
      if (s.unseen > (s.id == followed_ ? follow_coast_ : report_coast_)) continue;
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
    return {{"objects", long(tracker_.objectCount())}};
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
    std::vector<LegReturn> out;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] != run_label::kUnclustered) continue;  // a leg's, the ground's, removed
      LegReturn r;
      r.p = fixedPoint(f, i);
      r.sensor = nearestSensor(f, r.p);
      out.push_back(r);
    }
    return out;
  }

  // Cloud point i of the frame in the fixed frame (x, y).
  static Eigen::Vector2d fixedPoint(const Frame& f, std::size_t i) {
    float x, y, z;
    f.cloud().getPoint(i, x, y, z);
    double gx, gy, gz;
    f.robot_pose.composePoint(x, y, z, gx, gy, gz);
    return {gx, gy};
  }

  // The frame's kept returns in the fixed frame.
  static std::vector<Eigen::Vector2d> keptPoints(const Frame& f) {
    std::vector<Eigen::Vector2d> out;
    out.reserve(f.cloud().size());
    for (std::size_t i = 0; i < f.cloud().size(); ++i)
      if (f.isKept(i)) out.push_back(fixedPoint(f, i));
    return out;
  }

  // Whether a return nearer the scanner than p by a body's depth lies within a body's half-width
  // of the ray to p: something hides a person standing there.
  static bool hiddenBehind(const Frame& f, const Eigen::Vector2d& p, double half_width,
                           const std::vector<Eigen::Vector2d>& points) {
    constexpr double kDepth = 0.3;  // m, a person's
    const Eigen::Vector2d s = nearestSensor(f, p);
    const Eigen::Vector2d ray = p - s;
    const double range = ray.norm();
    if (range <= kDepth) return false;
    const Eigen::Vector2d u = ray / range;
    for (const Eigen::Vector2d& q : points) {
      const Eigen::Vector2d d = q - s;
      const double along = d.dot(u);
      if (along <= 0 || along >= range - kDepth) continue;
      if (std::abs(u.x() * d.y() - u.y() * d.x()) * range / along <= half_width) return true;
    }
    return false;
  }

  // How fast the robot turned since the last frame (rad/s, absolute), by the frames' poses.
  double turnRate(const Frame& f) {
    const double yaw = f.robot_pose.yaw();
    double rate = 0;
    if (!std::isnan(last_yaw_t_) && f.t > last_yaw_t_)
      rate = std::abs(mrpt::math::wrapToPi(yaw - last_yaw_)) / (f.t - last_yaw_t_);
    last_yaw_ = yaw, last_yaw_t_ = f.t;
    return rate;
  }

  // Whether no 2D scanner of the frame looks at p: outside every scan's aperture or beyond its
  // maximum range. A person there is unseen for want of a view, not because they left.
  static bool outOfView(const Frame& f, const Eigen::Vector2d& p) {
    std::size_t k = 0;
    bool any = false;
    for (const auto& o : f.observations) {
      const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(o.get());
      if (!scan) continue;
      any = true;
      const mrpt::poses::CPose3D& pose = k < f.sensors.size() ? f.sensors[k].pose : f.sensor_pose;
      ++k;
      double lx, ly, lz;
      pose.inverseComposePoint(p.x(), p.y(), pose.z(), lx, ly, lz);
      if (std::hypot(lx, ly) <= scan->maxRange &&
          std::abs(std::atan2(ly, lx)) <= 0.5 * scan->aperture + 1e-6)
        return false;
    }
    return any;
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
    const mrpt::poses::CPose3D inv = -f.robot_pose;
    auto inZone = [&](const PersonState& s) { return inFollowZone(inRobotFrame(inv, s.p)); };
    for (const auto& s : people) {
      if (s.id != followed_ || !s.confirmed || s.lost || s.unseen > follow_coast_) continue;
      alive = true;
      // Following the nearest: one out of follow_zone for longer than follow_coast is let go
      // (most often a track that slid off its person onto something beyond), and whoever is
      // in the zone is chosen (or confirmed there, follow_confirm_time).
      if (follow_id_ > 0 || inZone(s))
        out_of_zone_since_ = NAN;
      else if (std::isnan(out_of_zone_since_))
        out_of_zone_since_ = f.t;
      else if (f.t - out_of_zone_since_ > follow_coast_)
        alive = false;
    }
    if (alive) return;
    followed_ = 0;
    out_of_zone_since_ = NAN;
    if (follow_id_ > 0) {
      for (const auto& s : people)
        if (s.id == follow_id_ && followable(s)) followed_ = s.id;
      return;
    }
    double best = INFINITY;
    for (const auto& s : people) {
      if (!followable(s)) continue;
      const Eigen::Vector2d r = inRobotFrame(inv, s.p);
      if (inFollowZone(r) && r.norm() < best) best = r.norm(), followed_ = s.id;
    }
  }

  // A fixed-frame point in the robot frame, given the inverse of the robot's pose.
  static Eigen::Vector2d inRobotFrame(const mrpt::poses::CPose3D& inv, const Eigen::Vector2d& p) {
    double x, y, z;
    inv.composePoint(p.x(), p.y(), 0, x, y, z);
    return {x, y};
  }

  bool inFollowZone(const Eigen::Vector2d& r) const {  // robot frame
    return r.x() >= follow_zone_[0] && r.x() <= follow_zone_[1] &&
           std::abs(r.y()) <= follow_zone_[2];
  }

  LegPeopleTracker tracker_;
  std::optional<StaticScene> scene_;
  bool report_tentative_;
  std::string follow_;
  long follow_id_ = 0, followed_ = 0;
  double out_of_zone_since_ = NAN;          // since when the person followed is out of follow_zone
  double last_yaw_ = 0, last_yaw_t_ = NAN;  // the robot's yaw at the last frame (turnRate)
  std::vector<double> follow_zone_;
  double static_radius_;
  double report_coast_, follow_coast_;
  bool support_;      // support_gate > 0: the tracker is given the returns of no leg circle
  bool out_of_view_;  // see LegPeopleStageParams::out_of_view
  mutable bool classifier_seen_ = false;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "People from leg-height scans: leg and clutter tracks, leg pairs, P3 pose per person";
  d.params = table().specs();
  d.moved_keys = {{"scan_odometry",
                   "scan matching is a stage of its own: add [odometry] plugin = scan_odometry "
                   "(mode = auto|on|off) to [pipeline] stages, before the classifier"}};
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<LegPeople>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::legpeople

PEDTRACK_PLUGIN("leg_people", pedtrack::legpeople::describe)
