#pragma once
// A simulation scenario (configs/scenarios/*.ini): sensor, robot, ground, people and objects.
// Every section's keys are declared once (scenarioKeys) for validation and documentation.
#include <string>
#include <utility>
#include <vector>

#include "pedtrack/params.h"
#include "pedtrack/sim/body.h"
#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/motion.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {

struct PersonSpec {
  int id = 0;
  BodySpec body;
  Trajectory path;
  double appear = 0;  ///< s after the scenario start when the person enters
};

struct RobotSpec {
  Trajectory path;
  double odometry_noise = 0;      ///< m of 1σ error per m travelled
  double odometry_yaw_noise = 0;  ///< rad of 1σ error per rad turned
  double odometry_yaw_drift = 0;  ///< rad of 1σ error per m travelled
};

struct Scenario {
  std::string file, name, description;
  double duration = 0;    ///< s
  double start_time = 0;  ///< UNIX s of frame 0
  unsigned long seed = 1;
  double leg_height = 0;  ///< m above the ground where truth leg positions are taken
  SensorSpec sensor;
  RobotSpec robot;
  Ground ground;
  std::vector<PersonSpec> people;
  std::vector<Primitive> objects;  ///< static scene
  int object_count = 0;            ///< objects (ids 1..object_count; a wall is one object)
};

/// Loads and validates a scenario. `seed_override` >= 0 replaces [scenario] seed. Throws
/// ConfigError with one line naming file, section and key.
Scenario loadScenario(const std::string& path, long seed_override = -1);
/// Same from text (tests); `file` names it in messages.
Scenario scenarioFromText(const std::string& text, const std::string& file,
                          long seed_override = -1);

/// Every object type with what it is made of (documentation, in declaration order).
const std::vector<std::pair<std::string, std::string>>& objectTypeDocs();

/// Section kinds and their declared keys, in documentation order: "scenario", "sensor",
/// "robot", "ground", "person.NAME", "crowd", "object.NAME", "clutter".
const std::vector<std::pair<std::string, std::vector<ParamSpec>>>& scenarioKeys();

}  // namespace pedtrack::sim
