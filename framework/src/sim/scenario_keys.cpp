// The declared keys of every scenario section (validation, `pedtrack sim --keys`,
// docs/scenarios.md), each bound to the member of the section's struct it fills.
#include "scenario_keys.h"

#include <limits>

#include "pedtrack/sim/scenario.h"

namespace pedtrack::sim {
namespace keys {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The keys of MotionKeys, included by [robot] and [person.*] with their own defaults.
const ParamTable<MotionKeys>& motionTable() {
  using P = MotionKeys;
  static const auto t =
      ParamTable<P>()
          .real(&P::speed, "speed", "m/s", 0.01, 20, "walking speed")
          .real(&P::accel, "accel", "m/s²", 0.01, 20, "acceleration when starting and stopping")
          .real(&P::turn_rate, "turn_rate", "deg/s", 1, 1000, "rate of turns in place", kDegree)
          .real(&P::facing_rate, "facing_rate", "deg/s", 1, 2000,
                "how fast the body turns to a new walking direction", kDegree);
  return t;
}

const ParamTable<BodySpec>& bodyTable() {
  using P = BodySpec;
  static const auto t =
      ParamTable<P>()
          .real(&P::alpha, "alpha", "m", 0.05, 0.5, "torso semi-axis across the shoulders")
          .real(&P::beta, "beta", "m", 0.03, 0.5, "torso semi-axis front to back")
          .real(&P::height, "height", "m", 0.5, 2.5, "body height")
          .real(&P::arm_swing, "arm_swing", "deg", 0, 80, "arm swing amplitude at walking speed",
                kDegree)
          .real(&P::step_length, "step_length", "m", 0.1, 1.5,
                "distance between the feet at full stride")
          .real(&P::step_width, "step_width", "m", 0.0, 0.6, "lateral distance between the feet")
          .real(&P::cadence, "cadence", "steps/s", 0, 5,
                "steps per second (0: speed / step_length)")
          .real(&P::leg_radius, "leg_radius", "m", 0.02, 0.15, "leg radius")
          .choice(&P::carry, "carry",
                  {{"none", Carry::None},
                   {"bag", Carry::Bag},
                   {"suitcase", Carry::Suitcase},
                   {"pram", Carry::Pram}},
                  "what they carry: a bag in the right hand, a suitcase pulled behind, a pram "
                  "pushed ahead (its points are the person's)")
          .boolean(&P::sitting, "sitting",
                   "seated 0.45 m up, thighs forward (give a still path: on a bench)");
  return t;
}

}  // namespace

const ParamTable<ScenarioKeys>& scenarioTable() {
  using P = ScenarioKeys;
  static const auto t =
      ParamTable<P>()
          .text(&P::name, "name", "short name (defaults to the file name)")
          .text(&P::description, "description", "what the scene shows")
          .real(&P::duration, "duration", "s", 0.01, 36000, "simulated time")
          .required()
          .integer(&P::seed, "seed", "", 0, 4294967295.0, "random seed (noise, crowd, clutter)")
          .real(&P::start_time, "start_time", "s", 0, 4e9, "UNIX time of the first frame")
          .real(&P::leg_height, "leg_height", "m", -1, 2,
                "height of truth leg positions (-1: a 2D sensor's height up to 0.7 m, else "
                "0.4 m)");
  return t;
}

const ParamTable<SensorKeys>& sensorTable() {
  using P = SensorKeys;
  static const auto t =
      ParamTable<P>()
          .choice(&P::model, "model",
                  {{"utm30lx", "utm30lx"},
                   {"urg04lx", "urg04lx"},
                   {"vlp16", "vlp16"},
                   {"custom2d", "custom2d"}},
                  "sensor model (datasheet defaults below)")
          .real(&P::x, "x", "m", -kInf, kInf, "mounting position on the robot")
          .real(&P::y, "y", "m", -kInf, kInf, "mounting position on the robot")
          .real(&P::z, "z", "m", -kInf, kInf, "mounting height above the ground")
          .real(&P::yaw, "yaw", "deg", -360, 360, "mounting yaw", kDegree)
          .real(&P::pitch, "pitch", "deg", -90, 90, "mounting pitch", kDegree)
          .real(&P::roll, "roll", "deg", -180, 180, "mounting roll", kDegree)
          .real(&P::rate, "rate", "Hz", 0, 1000, "scan rate (0: model default)")
          .real(&P::fov, "fov", "deg", 0, 360, "2D field of view (0: model default)", kDegree)
          .real(&P::resolution, "resolution", "deg", 0, 10,
                "2D angle between beams (0: model default)", kDegree)
          .real(&P::max_range, "max_range", "m", 0, 1000, "maximum range (0: model default)")
          .real(&P::min_range, "min_range", "m", -1, 100, "minimum range (-1: model default)")
          .real(&P::range_noise, "range_noise", "m", -1, 1, "1σ range noise (-1: model default)")
          .real(&P::dropout, "dropout", "", 0, 1, "probability that a return is lost")
          .boolean(&P::dark_dropout, "dark_dropout",
                   "dark surfaces return less far: a surface of reflectivity R (0-100) is seen "
                   "to half max_range x sqrt(R / 10), its returns fading out over the last fifth "
                   "(a VLP-16 sees 10 % reflectivity to ~50 m, black clothing to ~25 m)")
          .real(&P::mixed_pixels, "mixed_pixels", "", 0, 1,
                "probability that a return at a depth edge (its neighbour in the ring 0.3-1.5 m "
                "farther or nearer: surfaces the pulse cannot tell apart) lands between the two "
                "surfaces, as a beam that hits both does")
          .text(&P::label, "label", "MRPT sensorLabel (default LASER / VELODYNE)")
          .boolean(&P::sweep_motion, "sweep_motion",
                   "people move during the sweep: each is seen when the beam passes it");
  return t;
}

const ParamTable<RobotKeys>& robotTable() {
  using P = RobotKeys;
  static const auto t =
      ParamTable<P>()
          .real(&P::x, "x", "m", -kInf, kInf, "start position")
          .real(&P::y, "y", "m", -kInf, kInf, "start position")
          .real(&P::yaw, "yaw", "deg", -360, 360, "start heading", kDegree)
          .text(&P::script, "script", "motion script (empty: the robot stands still)")
          .real(&P::odometry_noise, "odometry_noise", "m/√m", 0, 1,
                "odometry position random walk: 1σ error after 1 m travelled")
          .real(&P::odometry_yaw_noise, "odometry_yaw_noise", "rad/√rad", 0, 1,
                "heading random walk: 1σ error after 1 rad turned")
          .real(&P::odometry_yaw_drift, "odometry_yaw_drift", "rad/√m", 0, 1,
                "heading random walk: 1σ error after 1 m travelled")
          .include(&P::motion, motionTable());
  return t;
}

const ParamTable<GroundKeys>& groundTable() {
  using P = GroundKeys;
  static const auto t =
      ParamTable<P>()
          .real(&P::tilt, "tilt", "deg", 0, 30, "slope of the ground plane", kDegree)
          .real(&P::direction, "direction", "deg", -360, 360, "azimuth the ground rises towards",
                kDegree);
  return t;
}

const ParamTable<PersonKeys>& personTable() {
  using P = PersonKeys;
  static const auto t =
      ParamTable<P>()
          .real(&P::x, "x", "m", -kInf, kInf, "start position")
          .required()
          .real(&P::y, "y", "m", -kInf, kInf, "start position")
          .required()
          .real(&P::yaw, "yaw", "deg", -360, 360, "start heading", kDegree)
          .choice(&P::path, "path",
                  {{"still", "still"},
                   {"straight", "straight"},
                   {"C", "C"},
                   {"circle", "circle"},
                   {"zigzag", "zigzag"},
                   {"turn_in_place", "turn_in_place"},
                   {"sidestep", "sidestep"},
                   {"random", "random"},
                   {"waypoints", "waypoints"},
                   {"script", "script"}},
                  "path shape (script: the `script` key; waypoints: the `waypoints` key)")
          .text(&P::script, "script", "motion script, for path = script")
          .text(&P::waypoints, "waypoints", "x y; x y; ... for path = waypoints")
          .real(&P::length, "length", "m", 0, 1000, "straight/C/zigzag leg/sidestep length")
          .real(&P::radius, "radius", "m", 0.05, 1000, "C and circle radius")
          .real(&P::angle, "angle", "deg", -3600, 3600,
                "zigzag half angle; turn_in_place total turn")
          .integer(&P::repeats, "repeats", "", 1, 1000, "circle laps; zigzag legs")
          .text(&P::area, "area", "x0 y0 x1 y1 box for path = random (default ±3 m)")
          .integer(&P::legs, "legs", "", 1, 10000, "random walk commands")
          .real(&P::appear, "appear", "s", 0, 36000, "time the person enters the scene")
          .include(&P::motion, motionTable())
          .include(&P::body, bodyTable());
  return t;
}

const ParamTable<CrowdKeys>& crowdTable() {
  using P = CrowdKeys;
  static const auto t =
      ParamTable<P>()
          .integer(&P::count, "count", "", 1, 10000, "people walking at random")
          .required()
          .choice(&P::model, "model", {{"social_force", "social_force"}, {"scripted", "scripted"}},
                  "social_force: keep clear of each other, objects and the robot; scripted: "
                  "independent random-walk scripts")
          .text(&P::area, "area", "x0 y0 x1 y1 box they walk in")
          .required()
          .real(&P::speed_min, "speed_min", "m/s", 0.05, 5, "slowest walking speed")
          .real(&P::speed_max, "speed_max", "m/s", 0.05, 5, "fastest walking speed")
          .integer(&P::legs, "legs", "", 1, 10000, "random walk commands per person (scripted)")
          .real(&P::max_stop, "max_stop", "s", 0, 100, "longest random stop")
          .real(&P::facing_rate, "facing_rate", "deg/s", 1, 2000,
                "how fast bodies turn to a new walking direction", kDegree)
          .real(&P::child_share, "child_share", "", 0, 1,
                "share of children (1.0-1.45 m tall, narrower torso, shorter steps)")
          .real(&P::carry_share, "carry_share", "", 0, 1,
                "share of walkers carrying something: a bag (3 in 5), a suitcase or a pram")
          .real(&P::pair_share, "pair_share", "", 0, 1,
                "share of walkers with a companion walking beside them, 0.6-0.75 m to their "
                "left (pairs and, when companions pair again, groups)");
  return t;
}

const ParamTable<ObjectKeys>& objectTable() {
  using P = ObjectKeys;
  static const auto t =
      ParamTable<P>()
          .choice(&P::type, "type",
                  {{"wall", "wall"},
                   {"pole", "pole"},
                   {"box", "box"},
                   {"bin", "bin"},
                   {"tree", "tree"},
                   {"facade", "facade"},
                   {"hedge", "hedge"},
                   {"bush", "bush"},
                   {"car", "car"},
                   {"van", "van"},
                   {"bicycle", "bicycle"},
                   {"bench", "bench"},
                   {"signpost", "signpost"}},
                  "object kind (docs/scenarios.md: what each is made of)")
          .real(&P::x, "x", "m", -kInf, kInf, "position (a wall's first end)")
          .required()
          .real(&P::y, "y", "m", -kInf, kInf, "position (a wall's first end)")
          .required()
          .real(&P::x2, "x2", "m", -kInf, kInf, "a wall's, facade's or hedge's second end")
          .real(&P::y2, "y2", "m", -kInf, kInf, "a wall's, facade's or hedge's second end")
          .real(&P::thickness, "thickness", "m", 0.01, 10, "wall thickness")
          .real(&P::radius, "radius", "m", 0, 50, "pole/bin/trunk radius (0: 0.05 / 0.25 / 0.15)")
          .real(&P::crown, "crown", "m", 0, 50, "tree crown radius")
          .real(&P::width, "width", "m", 0.01, 100, "box size along its yaw")
          .real(&P::depth, "depth", "m", 0.01, 100, "box size across its yaw")
          .real(&P::height, "height", "m", 0, 100, "height (0: type default)")
          .real(&P::yaw, "yaw", "deg", -360, 360,
                "orientation of a box, car, van, bicycle, bench or sign", kDegree)
          .real(&P::foliage, "foliage", "m", -1, 100,
                "mean free path of a ray in foliage (tree crown, bush, hedge): returns come from "
                "inside the volume, some rays pass through; 0: solid; -1: the type's (trees "
                "solid, bushes and hedges 0.3)");
  return t;
}

const ParamTable<ClutterKeys>& clutterTable() {
  using P = ClutterKeys;
  static const auto t =
      ParamTable<P>()
          .integer(&P::count, "count", "", 1, 100000, "random static objects")
          .required()
          .text(&P::area, "area", "x0 y0 x1 y1 box they stand in")
          .required()
          .text(&P::types, "types", "kinds to draw from")
          .text(&P::heights, "heights",
                "min max: object heights drawn uniformly from this range (m; empty: each type's "
                "default height)")
          .real(&P::robot_clearance, "robot_clearance", "m", 0, 100,
                "an object drawn closer than this (its surface at leg height) to the [robot]'s "
                "path is drawn again elsewhere, from a stream of its own (the crowd and the other "
                "objects stay as without it): a robot does not drive through furniture; 0: off")
          .real(&P::foliage, "foliage", "m", -1, 100,
                "the objects' foliage (as [object.NAME] foliage): -1 trees solid, bushes and "
                "hedges 0.3 m");
  return t;
}

}  // namespace keys

const std::vector<std::pair<std::string, std::vector<ParamSpec>>>& scenarioKeys() {
  using namespace keys;
  static const std::vector<std::pair<std::string, std::vector<ParamSpec>>> all = {
      {"scenario", scenarioTable().specs()},  {"sensor", sensorTable().specs()},
      {"robot", robotTable().specs()},        {"ground", groundTable().specs()},
      {"person.NAME", personTable().specs()}, {"crowd", crowdTable().specs()},
      {"object.NAME", objectTable().specs()}, {"clutter", clutterTable().specs()},
  };
  return all;
}

}  // namespace pedtrack::sim
