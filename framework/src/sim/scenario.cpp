#include "pedtrack/sim/scenario.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/ini_text.h"
#include "pedtrack/sim/crowd.h"
#include "pedtrack/text.h"
#include "scenario_keys.h"
#include "scene_objects.h"

namespace pedtrack::sim {
namespace {

using namespace keys;
using KeyValues = std::vector<std::pair<std::string, std::string>>;

// "person.10" after "person.9": compare digit runs by value.
bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) &&
        std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t i2 = i, j2 = j;
      while (i2 < a.size() && std::isdigit(static_cast<unsigned char>(a[i2]))) ++i2;
      while (j2 < b.size() && std::isdigit(static_cast<unsigned char>(b[j2]))) ++j2;
      const long x = std::stol(a.substr(i, i2 - i)), y = std::stol(b.substr(j, j2 - j));
      if (x != y) return x < y;
      i = i2;
      j = j2;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

MotionLimits limits(const MotionKeys& k) {
  MotionLimits l;
  l.speed = k.speed;
  l.accel = k.accel;
  l.turn_rate = k.turn_rate;
  l.facing_rate = k.facing_rate;
  return l;
}

std::string personScript(const PersonKeys& k, const ParamSet& p, unsigned long seed, int id) {
  const auto& t = personTable();
  if (k.path == "still") return "";
  if (k.path == "script") {
    if (k.script.empty())
      throw ConfigError(t.where(p, &PersonKeys::script) + ": path = script needs a motion script");
    return k.script;
  }
  if (k.path == "waypoints") {
    const auto v = parseNumbers(k.waypoints, 0, t.where(p, &PersonKeys::waypoints));
    if (v.empty() || v.size() % 2)
      throw ConfigError(t.where(p, &PersonKeys::waypoints) + ": expected pairs 'x y; x y; ...'");
    std::ostringstream os;
    os.precision(10);
    for (std::size_t i = 0; i < v.size(); i += 2)
      os << (i ? "; " : "") << "goto " << v[i] << " " << v[i + 1];
    return os.str();
  }
  if (k.path == "random") {
    std::vector<double> a{k.x - 3, k.y - 3, k.x + 3, k.y + 3};
    if (!k.area.empty()) a = parseNumbers(k.area, 4, t.where(p, &PersonKeys::area));
    return randomWalkScript(static_cast<unsigned>(seed * 7919 + id), int(k.legs), a[0], a[1], a[2],
                            a[3], 2.0);
  }
  return shapeScript(k.path, k.length, k.radius, k.angle, int(k.repeats));
}

// The [crowd]: random people, placed apart from each other and from the objects, moving by the
// social force model (default) or by independent random-walk scripts.
// Walking beside `leader`, `offset` m to the left of their facing, at their pace (the velocity
// is the offset path's own).
Trajectory companionPath(const Trajectory& leader, double offset) {
  std::vector<MotionSample> out = leader.samples();
  for (auto& m : out) {
    m.x -= offset * std::sin(m.yaw);
    m.y += offset * std::cos(m.yaw);
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::size_t a = k ? k - 1 : k, b = std::min(out.size() - 1, k + 1);
    const double dt = out[b].t - out[a].t;
    if (dt > 0) out[k].vx = (out[b].x - out[a].x) / dt, out[k].vy = (out[b].y - out[a].y) / dt;
  }
  return Trajectory::fromSamples(std::move(out));
}

void addCrowd(Scenario& s, const ParamSet& p, std::mt19937& rng) {
  const CrowdKeys cr = crowdTable().read(p);
  const std::string area_where = crowdTable().where(p, &CrowdKeys::area);
  const auto a = parseNumbers(cr.area, 4, area_where);
  std::uniform_real_distribution<double> u01(0, 1);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * u01(rng); };
  const bool social = cr.model == "social_force";
  std::vector<CircleObstacle> obstacles;
  for (const Primitive& p : s.objects) {
    Eigen::Vector3d c;
    double r = 0;
    p.bound(c, r);
    const double bottom = p.shape == Shape::Sphere ? p.a.z() - p.ru : p.z0;
    if (bottom > 1.8) continue;  // tree crowns: people walk under them
    const double rxy = p.shape == Shape::Box                ? std::hypot(p.ru, p.rv)
                       : p.shape == Shape::EllipticCylinder ? std::max(p.ru, p.rv)
                                                            : p.ru;
    obstacles.push_back({c.x(), c.y(), rxy});
  }
  std::vector<CrowdAgent> agents;
  std::vector<PersonSpec> people;
  for (long i = 0; i < cr.count; ++i) {
    PersonSpec ps;
    ps.id = static_cast<int>(s.people.size() + people.size()) + 1;
    ps.body.alpha = in(0.17, 0.24);
    ps.body.beta = in(0.10, 0.15);
    ps.body.height = in(1.55, 1.92);
    ps.body.step_length = in(0.55, 0.75);
    // Children draw only when the scenario has them: scenarios without keep their numbers.
    if (cr.child_share > 0 && u01(rng) < cr.child_share) {
      ps.body.height = in(1.0, 1.45);
      ps.body.alpha = in(0.13, 0.17);
      ps.body.beta = in(0.08, 0.11);
      ps.body.step_length = in(0.40, 0.55);
    }
    CrowdAgent ag;
    ag.speed = in(cr.speed_min, cr.speed_max);
    ag.radius = ps.body.alpha + 0.05;
    // Start clear of everyone and everything (a few hundred tries, then anywhere).
    for (int tries = 0; tries < 500; ++tries) {
      ag.x = in(a[0], a[2]);
      ag.y = in(a[1], a[3]);  // separate statements: a fixed order of draws
      bool clear = true;
      for (const auto& o : agents) clear = clear && std::hypot(o.x - ag.x, o.y - ag.y) > 0.9;
      for (const auto& o : obstacles)
        clear = clear && std::hypot(o.x - ag.x, o.y - ag.y) > o.r + ag.radius + 0.2;
      if (clear) break;
    }
    ag.yaw = in(-M_PI, M_PI);
    if (!social) {
      MotionLimits lim;
      lim.speed = ag.speed;
      lim.facing_rate = cr.facing_rate;
      const std::string script = randomWalkScript(static_cast<unsigned>(rng()), int(cr.legs), a[0],
                                                  a[1], a[2], a[3], cr.max_stop);
      ps.path = Trajectory::fromScript(script, ag.x, ag.y, ag.yaw, lim, area_where);
    }
    agents.push_back(ag);
    people.push_back(std::move(ps));
  }
  if (social) {
    const CrowdArea area{a[0], a[1], a[2], a[3], cr.max_stop, cr.facing_rate};
    auto paths = simulateCrowd(agents, obstacles, &s.robot.path, s.duration, area, rng);
    for (std::size_t i = 0; i < people.size(); ++i) people[i].path = std::move(paths[i]);
  }
  // Carried items and companions from a stream of their own: a crowd without them draws as
  // before.
  std::mt19937_64 extra(s.seed ^ 0x3c6ef372fe94f82bull);
  std::uniform_real_distribution<double> e01(0, 1);
  const std::size_t walkers = people.size();
  for (std::size_t i = 0; i < walkers; ++i) {
    if (cr.carry_share > 0 && e01(extra) < cr.carry_share) {
      const double k = e01(extra);
      people[i].body.carry = k < 0.6 ? Carry::Bag : k < 0.8 ? Carry::Suitcase : Carry::Pram;
    }
    if (cr.pair_share <= 0 || e01(extra) >= cr.pair_share) continue;
    PersonSpec c;
    c.id = static_cast<int>(s.people.size() + people.size()) + 1;
    c.body = people[i].body;
    c.body.carry = Carry::None;
    c.body.height = std::clamp(c.body.height + 0.15 * (e01(extra) - 0.5), 1.0, 2.0);
    c.path = companionPath(people[i].path, 0.6 + 0.15 * e01(extra));
    people.push_back(std::move(c));
  }
  for (auto& p : people) s.people.push_back(std::move(p));
}

}  // namespace

Scenario scenarioFromText(const std::string& raw_text, const std::string& file,
                          long seed_override) {
  const std::string text = preprocessIniText(raw_text, file);
  mrpt::config::CConfigFileMemory ini(text);
  std::vector<std::string> sections;
  ini.getAllSections(sections);
  std::sort(sections.begin(), sections.end(), naturalLess);

  const auto& declared = scenarioKeys();
  std::map<std::string, ParamSet> single;
  std::vector<std::pair<std::string, ParamSet>> people, objects;
  for (const auto& sec : sections) {
    std::string kind = sec;
    if (sec.rfind("person.", 0) == 0 && sec.size() > 7) kind = "person.NAME";
    if (sec.rfind("object.", 0) == 0 && sec.size() > 7) kind = "object.NAME";
    auto it = std::find_if(declared.begin(), declared.end(),
                           [&](const auto& d) { return d.first == kind; });
    if (it == declared.end()) {
      std::vector<std::string> names;
      for (const auto& d : declared) names.push_back(d.first);
      const std::string hint = closestMatch(sec, names);
      throw ConfigError(file + ": [" + sec +
                        "]: unknown section (scenario, sensor, robot, "
                        "ground, person.NAME, crowd, object.NAME, clutter)" +
                        (hint.empty() ? "" : "; did you mean [" + hint + "]?"));
    }
    KeyValues kv;
    std::vector<std::string> keys;
    ini.getAllKeys(sec, keys);
    for (const auto& k : keys) kv.emplace_back(k, trim(ini.read_string(sec, k, "")));
    ParamSet ps = validateSection(it->second, kv, file, sec, "a [" + kind + "] section");
    if (kind == "person.NAME")
      people.emplace_back(sec, std::move(ps));
    else if (kind == "object.NAME")
      objects.emplace_back(sec, std::move(ps));
    else
      single.emplace(sec, std::move(ps));
  }
  auto section = [&](const std::string& name) -> const ParamSet& {
    if (!single.count(name)) {
      const auto& specs = std::find_if(declared.begin(), declared.end(), [&](const auto& d) {
                            return d.first == name;
                          })->second;
      single.emplace(name, validateSection(specs, {}, file, name, "a [" + name + "] section"));
    }
    return single.at(name);
  };
  if (!single.count("scenario"))
    throw ConfigError(file + ": [scenario] duration: missing required section and key");

  Scenario s;
  s.file = file;
  const ParamSet& sc_set = section("scenario");
  const ScenarioKeys sc = scenarioTable().read(sc_set);
  s.name = sc.name.empty() ? std::filesystem::path(file).stem().string() : sc.name;
  s.description = sc.description;
  s.duration = sc.duration;
  s.start_time = sc.start_time;
  s.seed = seed_override >= 0 ? static_cast<unsigned long>(seed_override)
                              : static_cast<unsigned long>(sc.seed);

  // Sensor: datasheet defaults, then what the file overrides.
  const ParamSet& se_set = section("sensor");
  const SensorKeys se = sensorTable().read(se_set);
  auto sensorWhere = [&](auto member) { return sensorTable().where(se_set, member); };
  s.sensor = sensorDefaults(se.model);
  if (se.fov > 0) s.sensor.fov = se.fov;
  if (se.resolution > 0) s.sensor.resolution = se.resolution;
  if (se.max_range > 0) s.sensor.max_range = se.max_range;
  if (se.min_range >= 0) s.sensor.min_range = se.min_range;
  if (se.rate > 0) s.sensor.rate = se.rate;
  if (se.range_noise >= 0) s.sensor.range_noise = se.range_noise;
  s.sensor.dropout = se.dropout;
  s.sensor.dark_dropout = se.dark_dropout;
  s.sensor.mixed_pixels = se.mixed_pixels;
  if (!se.label.empty()) s.sensor.label = se.label;
  s.sensor.sweep_motion = se.sweep_motion;
  for (double SensorKeys::*k : {&SensorKeys::fov, &SensorKeys::resolution})
    if (s.sensor.is3d && se.*k > 0)
      throw ConfigError(sensorWhere(k) + ": the VLP-16's geometry is fixed (for 2D models only)");
  // The simulated VLP-16 turns at 10 Hz (1800 columns of 0.2°); other rates change its columns.
  if (s.sensor.is3d && std::abs(s.sensor.rate - 10) > 1e-9)
    throw ConfigError(sensorWhere(&SensorKeys::rate) + ": the simulated VLP-16 runs at 10 Hz only");
  for (double SensorKeys::*k :
       {&SensorKeys::fov, &SensorKeys::resolution, &SensorKeys::max_range, &SensorKeys::rate})
    if (s.sensor.model == "custom2d" && se.*k <= 0)
      throw ConfigError(sensorWhere(k) + ": required (> 0) for model custom2d");
  s.sensor.mount = mrpt::poses::CPose3D(se.x, se.y, se.z, se.yaw, se.pitch, se.roll);
  // Truth legs at a leg-height 2D scanner's plane; a torso-height one scans above the hips.
  const bool leg_scanner = !s.sensor.is3d && se.z <= 0.7;
  s.leg_height = sc.leg_height >= 0 ? sc.leg_height : leg_scanner ? se.z : 0.4;

  const ParamSet& ro_set = section("robot");
  const RobotKeys ro = robotTable().read(ro_set);
  s.robot.path = Trajectory::fromScript(ro.script, ro.x, ro.y, ro.yaw, limits(ro.motion),
                                        robotTable().where(ro_set, &RobotKeys::script));
  s.robot.odometry_noise = ro.odometry_noise;
  s.robot.odometry_yaw_noise = ro.odometry_yaw_noise;
  s.robot.odometry_yaw_drift = ro.odometry_yaw_drift;

  const GroundKeys gr = groundTable().read(section("ground"));
  s.ground = Ground(gr.tilt, gr.direction);

  for (const auto& [sec, p] : people) {
    const PersonKeys k = personTable().read(p);
    PersonSpec ps;
    ps.id = static_cast<int>(s.people.size()) + 1;
    ps.body = k.body;
    ps.appear = k.appear;
    ps.path = Trajectory::fromScript(
        personScript(k, p, s.seed, ps.id), k.x, k.y, k.yaw, limits(k.motion),
        personTable().where(p, k.path == "script" ? &PersonKeys::script : &PersonKeys::path));
    s.people.push_back(std::move(ps));
  }

  std::mt19937 rng(static_cast<unsigned>(s.seed));
  std::uniform_real_distribution<double> u01(0, 1);
  // The street objects' sizes and layouts: a stream of their own, so the scene's other draws
  // (clutter places, the crowd) stay as they were.
  std::mt19937_64 details(s.seed ^ 0x2545f4914f6cdd1dull);
  for (const auto& [sec, p] : objects) {
    const ObjectKeys o = objectTable().read(p);
    ObjectRequest r{o.type, o.x,     o.y,     o.x2,        o.y2,    o.radius, o.height,
                    o.yaw,  o.width, o.depth, o.thickness, o.crown, o.foliage};
    addObject(s, r, objectTable().where(p, &ObjectKeys::x2), details);
  }
  if (single.count("clutter")) {
    const ParamSet& cl_set = single.at("clutter");
    const ClutterKeys cl = clutterTable().read(cl_set);
    const std::string types_where = clutterTable().where(cl_set, &ClutterKeys::types);
    const auto a = parseNumbers(cl.area, 4, clutterTable().where(cl_set, &ClutterKeys::area));
    const auto types = splitList(cl.types);
    const auto& known = objectTypes();
    for (const auto& t : types)
      if (std::find(known.begin(), known.end(), t) == known.end())
        throw ConfigError(types_where + ": unknown object type '" + t + "'");
    if (types.empty()) throw ConfigError(types_where + ": empty");
    std::vector<double> heights;
    if (!cl.heights.empty()) {
      const std::string heights_where = clutterTable().where(cl_set, &ClutterKeys::heights);
      heights = parseNumbers(cl.heights, 2, heights_where);
      if (!(0 < heights[0] && heights[0] <= heights[1]))
        throw ConfigError(heights_where + ": need 0 < min <= max");
    }
    const double clearance = cl.robot_clearance;
    // Objects in the robot's way are drawn again from a stream of their own, so the main
    // stream (the other objects, the crowd) is the same as without robot_clearance.
    std::mt19937 redraw(static_cast<unsigned>(s.seed) ^ 0x9e3779b9u);
    for (long i = 0; i < cl.count; ++i) {
      const std::string& t =
          types[static_cast<std::size_t>(u01(rng) * types.size()) % types.size()];
      double x = a[0] + (a[2] - a[0]) * u01(rng);
      double y = a[1] + (a[3] - a[1]) * u01(rng);
      const double yaw = u01(rng) * M_PI;
      // One draw per statement: the order of arguments' evaluation is unspecified.
      const double radius = t == "pole" ? 0.04 + 0.06 * u01(rng) : 0;
      const double width = 0.4 + 0.8 * u01(rng);
      const double depth = 0.3 + 0.5 * u01(rng);
      const double crown = 1.0 + u01(rng);
      const double height = heights.empty() ? 0 : heights[0] + (heights[1] - heights[0]) * u01(rng);
      // A wall is 2 m long; a facade or a hedge as long as real ones (their own stream).
      const double len = t == "facade"  ? std::uniform_real_distribution<double>(6, 15)(details)
                         : t == "hedge" ? std::uniform_real_distribution<double>(2, 6)(details)
                                        : 2.0;
      ObjectRequest r{t, x, y, 0, 0, radius, height, yaw, width, depth, 0.15, crown, cl.foliage};
      auto place = [&] {
        r.x = x, r.y = y, r.x2 = x + len * std::cos(yaw), r.y2 = y + len * std::sin(yaw);
      };
      place();
      for (int tries = 0; clearance > 0 && tries < 1000; ++tries) {
        if (robotPathDistance(s.robot.path, r) >= clearance) break;
        x = a[0] + (a[2] - a[0]) * u01(redraw);
        y = a[1] + (a[3] - a[1]) * u01(redraw);
        place();
      }
      addObject(s, r, types_where, details);
    }
  }
  if (single.count("crowd")) addCrowd(s, single.at("crowd"), rng);
  return s;
}

Scenario loadScenario(const std::string& path, long seed_override) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw ConfigError(path + ": scenario file not found");
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return scenarioFromText(ss.str(), path, seed_override);
}

}  // namespace pedtrack::sim
