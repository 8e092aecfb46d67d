#pragma once
// The keys of every scenario section, each section a struct whose member initialisers are the
// defaults, bound to its INI keys by one table (scenario_keys.cpp): validation, `pedtrack sim
// --keys`, docs/scenarios.md and the reading of a section all come from it. Angles the INI gives
// in degrees are kept in radians (the tables' scale), except a person's `angle`, a path shape's
// turn, which shapeScript takes in degrees.
#include <string>

#include "pedtrack/param_table.h"
#include "pedtrack/sim/body.h"

namespace pedtrack::sim::keys {

struct ScenarioKeys {
  std::string name, description;
  double duration = 0;  ///< s (required)
  long seed = 1;
  double start_time = 1700000000.0;  ///< UNIX s of frame 0
  double leg_height = -1;            ///< m; -1: a 2D sensor's height up to 0.7 m, else 0.4 m
};

struct SensorKeys {
  std::string model = "vlp16";
  double x = 0, y = 0, z = 1.0;                             ///< m, mount on the robot
  double yaw = 0, pitch = 0, roll = 0;                      ///< rad
  double rate = 0, fov = 0, resolution = 0, max_range = 0;  ///< Hz, rad, rad, m; 0: the model's
  double min_range = -1, range_noise = -1;                  ///< m; -1: the model's
  double dropout = 0;
  bool dark_dropout = false;
  double mixed_pixels = 0;
  std::string label;  ///< empty: LASER / VELODYNE
  bool sweep_motion = false;
};

/// How a robot or a person moves (MotionLimits' keys; the defaults are each section's).
struct MotionKeys {
  double speed = 1.2;                  ///< m/s
  double accel = 0.8;                  ///< m/s²
  double turn_rate = 90 * kDegree;     ///< rad/s, turns in place
  double facing_rate = 150 * kDegree;  ///< rad/s, the body following a new walking direction
};

struct RobotKeys {
  double x = 0, y = 0, yaw = 0;  ///< m, m, rad
  std::string script;            ///< empty: the robot stands still
  double odometry_noise = 0, odometry_yaw_noise = 0, odometry_yaw_drift = 0;
  MotionKeys motion{0.6, 0.8, 45 * kDegree, 150 * kDegree};  ///< a robot drives slower
};

struct GroundKeys {
  double tilt = 0, direction = 0;  ///< rad
};

struct PersonKeys {
  double x = 0, y = 0;  ///< m (required)
  double yaw = 0;       ///< rad
  std::string path = "still", script, waypoints;
  double length = 3, radius = 1;
  double angle = 45;  ///< deg: the path shape's (shapeScript takes degrees)
  long repeats = 1;
  std::string area;  ///< x0 y0 x1 y1; empty: ±3 m around the start
  long legs = 20;
  double appear = 0;  ///< s
  MotionKeys motion;
  /// A [person.*]'s body; a [crowd]'s random people draw theirs (crowd.cpp), keeping BodySpec's
  /// own arm swing of 0.35 rad.
  BodySpec body = [] {
    BodySpec b;
    b.arm_swing = 20 * kDegree;
    return b;
  }();
};

struct CrowdKeys {
  long count = 0;  ///< required
  std::string model = "social_force";
  std::string area;  ///< required: x0 y0 x1 y1
  double speed_min = 0.8, speed_max = 1.5;
  long legs = 30;
  double max_stop = 3;
  double facing_rate = 150 * kDegree;  ///< rad/s
  double child_share = 0;
  double carry_share = 0, pair_share = 0;
};

struct ObjectKeys {
  std::string type = "pole";
  double x = 0, y = 0;  ///< m (required)
  double x2 = 0, y2 = 0, thickness = 0.15;
  double radius = 0;  ///< 0: the type's (roundRadius)
  double crown = 1.5, width = 0.6, depth = 0.4;
  double height = 0;    ///< 0: the type's
  double yaw = 0;       ///< rad
  double foliage = -1;  ///< m, see ObjectRequest::foliage
};

struct ClutterKeys {
  long count = 0;    ///< required
  std::string area;  ///< required: x0 y0 x1 y1
  std::string types = "pole box bin tree";
  std::string heights;         ///< min max; empty: each type's height
  double robot_clearance = 0;  ///< m
  double foliage = -1;         ///< m, see ObjectRequest::foliage
};

const ParamTable<ScenarioKeys>& scenarioTable();
const ParamTable<SensorKeys>& sensorTable();
const ParamTable<RobotKeys>& robotTable();
const ParamTable<GroundKeys>& groundTable();
const ParamTable<PersonKeys>& personTable();
const ParamTable<CrowdKeys>& crowdTable();
const ParamTable<ObjectKeys>& objectTable();
const ParamTable<ClutterKeys>& clutterTable();

}  // namespace pedtrack::sim::keys
