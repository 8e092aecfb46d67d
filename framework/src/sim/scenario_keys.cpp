// The declared keys of every scenario section (validation, `pedtrack sim --keys`, README).
#include "pedtrack/sim/scenario.h"

namespace pedtrack::sim {
namespace {

using P = ParamSpec;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<ParamSpec> motionKeys(double speed, double turn_rate) {
  return {
      P::real("speed", speed, "m/s", 0.01, 20, "walking speed"),
      P::real("accel", 0.8, "m/s²", 0.01, 20, "acceleration when starting and stopping"),
      P::real("turn_rate", turn_rate, "deg/s", 1, 1000, "rate of turns in place"),
      P::real("facing_rate", 150, "deg/s", 1, 2000,
              "how fast the body turns to a new walking direction"),
  };
}

std::vector<ParamSpec> bodyKeys() {
  return {
      P::real("alpha", 0.20, "m", 0.05, 0.5, "torso semi-axis across the shoulders"),
      P::real("beta", 0.12, "m", 0.03, 0.5, "torso semi-axis front to back"),
      P::real("height", 1.70, "m", 0.5, 2.5, "body height"),
      P::real("arm_swing", 20, "deg", 0, 80, "arm swing amplitude at walking speed"),
      P::real("step_length", 0.65, "m", 0.1, 1.5, "distance between the feet at full stride"),
      P::real("step_width", 0.18, "m", 0.0, 0.6, "lateral distance between the feet"),
      P::real("cadence", 0, "steps/s", 0, 5, "steps per second (0: speed / step_length)"),
      P::real("leg_radius", 0.055, "m", 0.02, 0.15, "leg radius"),
  };
}

template <class... Vs>
std::vector<ParamSpec> cat(std::vector<ParamSpec> a, const Vs&... more) {
  (a.insert(a.end(), more.begin(), more.end()), ...);
  return a;
}

}  // namespace

const std::vector<std::pair<std::string, std::vector<ParamSpec>>>& scenarioKeys() {
  static const std::vector<std::pair<std::string, std::vector<ParamSpec>>> keys = {
      {"scenario",
       {
           P::text("name", std::string(""), "short name (defaults to the file name)"),
           P::text("description", std::string(""), "what the scene shows"),
           P::real("duration", std::nullopt, "s", 0.01, 36000, "simulated time"),
           P::integer("seed", 1, "", 0, 4294967295.0, "random seed (noise, crowd, clutter)"),
           P::real("start_time", 1700000000.0, "s", 0, 4e9, "UNIX time of the first frame"),
           P::real(
               "leg_height", -1, "m", -1, 2,
               "height of truth leg positions (-1: a 2D sensor's height up to 0.7 m, else 0.4 m)"),
       }},
      {"sensor",
       {
           P::choice("model", "vlp16", {"utm30lx", "urg04lx", "vlp16", "custom2d"},
                     "sensor model (datasheet defaults below)"),
           P::real("x", 0, "m", -kInf, kInf, "mounting position on the robot"),
           P::real("y", 0, "m", -kInf, kInf, "mounting position on the robot"),
           P::real("z", 1.0, "m", -kInf, kInf, "mounting height above the ground"),
           P::real("yaw", 0, "deg", -360, 360, "mounting yaw"),
           P::real("pitch", 0, "deg", -90, 90, "mounting pitch"),
           P::real("roll", 0, "deg", -180, 180, "mounting roll"),
           P::real("rate", 0, "Hz", 0, 1000, "scan rate (0: model default)"),
           P::real("fov", 0, "deg", 0, 360, "2D field of view (0: model default)"),
           P::real("resolution", 0, "deg", 0, 10, "2D angle between beams (0: model default)"),
           P::real("max_range", 0, "m", 0, 1000, "maximum range (0: model default)"),
           P::real("min_range", -1, "m", -1, 100, "minimum range (-1: model default)"),
           P::real("range_noise", -1, "m", -1, 1, "1σ range noise (-1: model default)"),
           P::real("dropout", 0, "", 0, 1, "probability that a return is lost"),
           P::text("label", std::string(""), "MRPT sensorLabel (default LASER / VELODYNE)"),
           P::boolean("sweep_motion", false,
                      "people move during the sweep: each is seen when the beam passes it"),
       }},
      {"robot",
       cat({P::real("x", 0, "m", -kInf, kInf, "start position"),
            P::real("y", 0, "m", -kInf, kInf, "start position"),
            P::real("yaw", 0, "deg", -360, 360, "start heading"),
            P::text("script", std::string(""), "motion script (empty: the robot stands still)"),
            P::real("odometry_noise", 0, "m/√m", 0, 1,
                    "odometry position random walk: 1σ error after 1 m travelled"),
            P::real("odometry_yaw_noise", 0, "rad/√rad", 0, 1,
                    "heading random walk: 1σ error after 1 rad turned"),
            P::real("odometry_yaw_drift", 0, "rad/√m", 0, 1,
                    "heading random walk: 1σ error after 1 m travelled")},
           motionKeys(0.6, 45))},
      {"ground",
       {
           P::real("tilt", 0, "deg", 0, 30, "slope of the ground plane"),
           P::real("direction", 0, "deg", -360, 360, "azimuth the ground rises towards"),
       }},
      {"person.NAME",
       cat({P::real("x", std::nullopt, "m", -kInf, kInf, "start position"),
            P::real("y", std::nullopt, "m", -kInf, kInf, "start position"),
            P::real("yaw", 0, "deg", -360, 360, "start heading"),
            P::choice("path", "still",
                      {"still", "straight", "C", "circle", "zigzag", "turn_in_place", "sidestep",
                       "random", "waypoints", "script"},
                      "path shape (script: the `script` key; waypoints: the `waypoints` key)"),
            P::text("script", std::string(""), "motion script, for path = script"),
            P::text("waypoints", std::string(""), "x y; x y; ... for path = waypoints"),
            P::real("length", 3, "m", 0, 1000, "straight/C/zigzag leg/sidestep length"),
            P::real("radius", 1, "m", 0.05, 1000, "C and circle radius"),
            P::real("angle", 45, "deg", -3600, 3600, "zigzag half angle; turn_in_place total turn"),
            P::integer("repeats", 1, "", 1, 1000, "circle laps; zigzag legs"),
            P::text("area", std::string(""), "x0 y0 x1 y1 box for path = random (default ±3 m)"),
            P::integer("legs", 20, "", 1, 10000, "random walk commands"),
            P::real("appear", 0, "s", 0, 36000, "time the person enters the scene")},
           motionKeys(1.2, 90), bodyKeys())},
      {"crowd",
       {
           P::integer("count", std::nullopt, "", 1, 10000, "people walking at random"),
           P::choice("model", "social_force", {"social_force", "scripted"},
                     "social_force: keep clear of each other, objects and the robot; scripted: "
                     "independent random-walk scripts"),
           P::text("area", std::nullopt, "x0 y0 x1 y1 box they walk in"),
           P::real("speed_min", 0.8, "m/s", 0.05, 5, "slowest walking speed"),
           P::real("speed_max", 1.5, "m/s", 0.05, 5, "fastest walking speed"),
           P::integer("legs", 30, "", 1, 10000, "random walk commands per person (scripted)"),
           P::real("max_stop", 3, "s", 0, 100, "longest random stop"),
           P::real("facing_rate", 150, "deg/s", 1, 2000,
                   "how fast bodies turn to a new walking direction"),
           P::real("child_share", 0, "", 0, 1,
                   "share of children (1.0-1.45 m tall, narrower torso, shorter steps)"),
       }},
      {"object.NAME",
       {
           P::choice("type", "pole", {"wall", "pole", "box", "bin", "tree"}, "object kind"),
           P::real("x", std::nullopt, "m", -kInf, kInf, "position (a wall's first end)"),
           P::real("y", std::nullopt, "m", -kInf, kInf, "position (a wall's first end)"),
           P::real("x2", 0, "m", -kInf, kInf, "a wall's second end"),
           P::real("y2", 0, "m", -kInf, kInf, "a wall's second end"),
           P::real("thickness", 0.15, "m", 0.01, 10, "wall thickness"),
           P::real("radius", 0, "m", 0, 50, "pole/bin/trunk radius (0: 0.05 / 0.25 / 0.15)"),
           P::real("crown", 1.5, "m", 0, 50, "tree crown radius"),
           P::real("width", 0.6, "m", 0.01, 100, "box size along its yaw"),
           P::real("depth", 0.4, "m", 0.01, 100, "box size across its yaw"),
           P::real("height", 0, "m", 0, 100, "height (0: type default)"),
           P::real("yaw", 0, "deg", -360, 360, "box orientation"),
       }},
      {"clutter",
       {
           P::integer("count", std::nullopt, "", 1, 100000, "random static objects"),
           P::text("area", std::nullopt, "x0 y0 x1 y1 box they stand in"),
           P::text("types", std::string("pole box bin tree"), "kinds to draw from"),
           P::text("heights", std::string(""),
                   "min max: object heights drawn uniformly from this range (m; empty: each "
                   "type's default height)"),
           P::real("robot_clearance", 0, "m", 0, 100,
                   "an object drawn closer than this (its surface at leg height) to the "
                   "[robot]'s path is drawn again elsewhere, from a stream of its own (the crowd "
                   "and the other objects stay as without it): a robot does not drive through "
                   "furniture; 0: off"),
       }},
  };
  return keys;
}

}  // namespace pedtrack::sim
