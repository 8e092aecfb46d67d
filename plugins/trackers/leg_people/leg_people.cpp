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
#include "pedtrack/track/gait_fit_ipopt.h"
#include "pedtrack/track/leg_people_tracker.h"
#include "pedtrack/track/leg_pose_params.h"
#include "pedtrack/track/static_scene.h"

namespace pedtrack::legpeople {
namespace {

using namespace pedtrack::track;

LegPeopleParams readParams(const ParamSet& s) {
  LegPeopleParams p;
  p.pose = readLegPoseParams(s);
  if (s.getString("gait_solver") == "ipopt") p.pose.gait_solver = &gait::fitIpopt;
  p.object_q = s.getDouble("object_q");
  p.object_sigma = s.getDouble("object_sigma");
  p.gate = s.getDouble("gate");
  p.object_max_coast = s.getDouble("object_max_coast");
  p.leg_score = s.getDouble("leg_score");
  p.pair_distance = s.getDouble("pair_distance");
  p.confirm_travel = s.getDouble("confirm_travel");
  p.max_coast = s.getDouble("max_coast");
  p.max_leg_spread = s.getDouble("max_leg_spread");
  p.flip_speed = s.getDouble("flip_speed");
  p.flip_time = s.getDouble("flip_time");
  p.init_speed = s.getDouble("init_speed");
  return p;
}

class LegPeople : public Tracker {
 public:
  explicit LegPeople(const PluginContext& ctx)
      : tracker_(readParams(ctx.params)),
        report_tentative_(ctx.params.getBool("report_tentative")),
        follow_(ctx.params.getString("follow")),
        follow_zone_(ctx.params.getVector("follow_zone")) {
    if (ctx.params.getBool("static_scene")) {
      StaticScene::Options o;
      o.persist = ctx.params.getDouble("static_persist");
      o.prior_map = ctx.params.getString("prior_map");
      o.cell = ctx.params.getDouble("static_cell");
      scene_.emplace(o);
    }
    if (follow_ != "off" && follow_ != "nearest") {
      char* end = nullptr;
      follow_id_ = std::strtol(follow_.c_str(), &end, 10);
      if (!end || *end || follow_id_ <= 0)
        throw ConfigError(ctx.params.where("follow") + ": '" + follow_ +
                          "' is not off, nearest or a track id");
    }
  }

  void process(Frame& f) override {
    std::vector<LegDetection> legs = detections(f);
    std::function<bool(double, double)> is_static;
    if (scene_) is_static = [&](double x, double y) { return scene_->isStatic(x, y, f.t); };
    tracker_.step(f.t, legs, is_static);
    if (scene_) scene_->update(f, tracker_.occupiedByPeople());
    const auto people = tracker_.people();
    chooseFollowed(f, people);
    for (const PersonState& s : people) {
      if (!s.confirmed && !report_tentative_) continue;
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
      d.sensor = {f.sensor_pose.x(), f.sensor_pose.y()};
      d.cluster = int(i);
      out.push_back(d);
    }
    return out;
  }

  // Person following: the given track, or the nearest confirmed person inside the zone in front
  // of the robot [x_min, x_max] × [−half_width, half_width] (robot frame), kept while it lives.
  void chooseFollowed(const Frame& f, const std::vector<PersonState>& people) {
    if (follow_ == "off") return;
    bool alive = false;
    for (const auto& s : people) alive |= s.id == followed_ && s.confirmed;
    if (alive) return;
    followed_ = 0;
    if (follow_id_ > 0) {
      for (const auto& s : people)
        if (s.id == follow_id_ && s.confirmed) followed_ = s.id;
      return;
    }
    double best = INFINITY;
    const mrpt::poses::CPose3D inv = -f.robot_pose;
    for (const auto& s : people) {
      if (!s.confirmed) continue;
      double x, y, z;
      inv.composePoint(s.p.x(), s.p.y(), 0, x, y, z);
      if (x < follow_zone_[0] || x > follow_zone_[1] || std::abs(y) > follow_zone_[2]) continue;
      const double d = std::hypot(x, y);
      if (d < best) best = d, followed_ = s.id;
    }
  }

  LegPeopleTracker tracker_;
  std::optional<StaticScene> scene_;
  bool report_tentative_;
  std::string follow_;
  long follow_id_ = 0, followed_ = 0;
  std::vector<double> follow_zone_;
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
      ParamSpec::real("pair_distance", def.pair_distance, "m", 0, 5,
                      "two legs at most this far apart form a person"),
      ParamSpec::real("confirm_travel", def.confirm_travel, "m", 0, 100,
                      "a new person is confirmed (reported) once it moved this far"),
      ParamSpec::real("max_coast", def.max_coast, "s", 0, 3600,
                      "a person with neither leg seen this long is deleted"),
      ParamSpec::real("max_leg_spread", def.max_leg_spread, "m", 0.1, 10,
                      "a person's legs farther apart than this: the outer one is dropped"),
      ParamSpec::real("flip_speed", def.flip_speed, "m/s", 0, 100,
                      "walking backwards faster than this for flip_time turns the facing round"),
      ParamSpec::real("flip_time", def.flip_time, "s", 0, 3600, "see flip_speed"),
      ParamSpec::real("init_speed", def.init_speed, "m/s", 0, 100,
                      "a new person faces their legs' motion above this speed, else the scanner"),
      ParamSpec::boolean("report_tentative", false, "also write tracks not yet confirmed"),
      ParamSpec::boolean("static_scene", true,
                         "no person starts in a cell the local occupancy grid (or the prior map) "
                         "has seen occupied for static_persist seconds"),
      ParamSpec::real("static_persist", so.persist, "s", 0, 3600,
                      "a cell occupied this long (not by a tracked person) is static scene"),
      ParamSpec::real("static_cell", so.cell, "m", 0.01, 1, "cell size of the static-scene grid"),
      ParamSpec::text("prior_map", std::string(),
                      "optional map of the fixed frame: ROS map.yaml or MRPT .gridmap; its "
                      "occupied cells are static scene"),
      ParamSpec::text("follow", std::string("off"),
                      "person following: off, nearest (the nearest confirmed person in "
                      "follow_zone, re-chosen when lost) or a track id; marked `following`"),
      ParamSpec::vector("follow_zone", std::vector<double>{0.3, 3.0, 1.0}, "m", 3, -100, 100,
                        "x_min x_max half_width of the zone in front of the robot (robot frame)"),
  };
  const auto pose = legPoseParamSpecs();
  d.params.insert(d.params.end(), pose.begin(), pose.end());
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<LegPeople>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::legpeople

PEDTRACK_PLUGIN("leg_people", pedtrack::legpeople::describe)
