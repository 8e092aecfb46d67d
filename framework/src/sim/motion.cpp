#include "pedtrack/sim/motion.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/text.h"

namespace pedtrack::sim {
namespace {

// A script's bounds: its samples (a path point every 2 cm, a pose every kDt) stay countable and
// fit in memory. 10 km a command, 100 km in all (10 h of walking is ~50 km), 10 turns, and no
// longer than the longest scenario ([scenario] duration).
constexpr double kMaxDistance = 10000;       // m
constexpr double kMaxAngle = 3600;           // deg
constexpr double kMaxDuration = 36000;       // s
constexpr std::size_t kMaxPathPoints = 5e6;  // 100 km

double deg(double d) {
  return mrpt::DEG2RAD(d);
}

// A piece of motion before time-parameterisation: a translation along a densely sampled
// polyline with a facing per point, or a stand (turning in place or still) of known duration.
struct Piece {
  bool translate = false;
  bool smooth = false;  // facing changes gradually along it (arcs, turns), not at its start
  std::vector<double> px, py, facing;  // translation: points (first is the start)
  double speed = 0;
  double yaw0 = 0, yaw1 = 0, duration = 0;  // stand
};

struct Builder {
  double x, y, yaw;
  MotionLimits lim;
  std::vector<Piece> pieces;

  void translate(double dist, double offset) {  // offset: motion direction relative to facing
    const double dir = yaw + offset;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(dist) / 0.02)));
    Piece p;
    p.translate = true;
    p.speed = lim.speed;
    for (int i = 0; i <= n; ++i) {
      p.px.push_back(x + std::cos(dir) * dist * i / n);
      p.py.push_back(y + std::sin(dir) * dist * i / n);
      p.facing.push_back(yaw);
    }
    x = p.px.back();
    y = p.py.back();
    pieces.push_back(std::move(p));
  }
  void arc(double r, double ang) {
    const double sgn = ang >= 0 ? 1 : -1;
    const double cx = x - sgn * r * std::sin(yaw), cy = y + sgn * r * std::cos(yaw);
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(ang) * r / 0.02)));
    Piece p;
    p.translate = true;
    p.speed = lim.speed;
    p.smooth = true;
    const double a0 = std::atan2(y - cy, x - cx);
    for (int i = 0; i <= n; ++i) {
      const double a = a0 + ang * i / n;
      p.px.push_back(cx + r * std::cos(a));
      p.py.push_back(cy + r * std::sin(a));
      p.facing.push_back(yaw + ang * i / n);
    }
    x = p.px.back();
    y = p.py.back();
    yaw += ang;
    pieces.push_back(std::move(p));
  }
  void gotoPoint(double tx, double ty) {
    const double dist = std::hypot(tx - x, ty - y);
    if (dist < 1e-6) return;
    // Facing smoothing does the turning.
    yaw = yaw + mrpt::math::wrapToPi(std::atan2(ty - y, tx - x) - yaw);
    translate(dist, 0);
  }
  void stand(double new_yaw, double duration) {
    Piece p;
    p.smooth = true;
    p.yaw0 = yaw;
    p.yaw1 = new_yaw;
    p.duration = duration;
    yaw = new_yaw;
    pieces.push_back(std::move(p));
  }
};

// Speeds along a polyline under per-point caps: accelerate from rest, brake to rest, never
// faster than a cap or than `accel` allows (forward and backward passes).
std::vector<double> speedProfile(const std::vector<double>& px, const std::vector<double>& py,
                                 std::vector<double> v, double accel) {
  const std::size_t n = px.size();
  v.front() = v.back() = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double ds = std::hypot(px[i] - px[i - 1], py[i] - py[i - 1]);
    v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * accel * ds));
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    const double ds = std::hypot(px[i + 1] - px[i], py[i + 1] - py[i]);
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * accel * ds));
  }
  return v;
}

}  // namespace

Trajectory Trajectory::fromScript(const std::string& script, double x, double y, double yaw,
                                  const MotionLimits& lim, const std::string& where) {
  Builder b{x, y, yaw, lim, {}};
  std::stringstream all(script);
  std::string cmdtext;
  std::size_t path_points = 0;  // of every translation so far (a point every 2 cm)
  while (std::getline(all, cmdtext, ';')) {
    std::istringstream cs(cmdtext);
    std::string cmd;
    if (!(cs >> cmd)) continue;
    std::vector<double> args;
    std::string tok;
    while (cs >> tok) {
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end || !std::isfinite(v))
        throw ConfigError(where + ": '" + trim(cmdtext) + "': '" + tok + "' is not a number");
      args.push_back(v);
    }
    // Bounds that keep a script's sampling finite (a path point every 2 cm, a sample every
    // kDt): a walk of 1e50 m or a stop of 1e50 s overflowed the sample counts (fuzz_scenario).
    auto within = [&](double v, double max, const char* what) {
      if (std::abs(v) > max)
        throw ConfigError(where + ": '" + trim(cmdtext) + "': " + what + " beyond " +
                          std::to_string(static_cast<long>(max)));
    };
    if (cmd == "walk" || cmd == "back" || cmd == "left" || cmd == "right")
      for (double a : args) within(a, kMaxDistance, "distance (m)");
    if (cmd == "goto")
      for (double a : args) within(a, kMaxDistance, "coordinate (m)");
    if (cmd == "turn" || cmd == "face")
      for (double a : args) within(a, kMaxAngle, "angle (deg)");
    if (cmd == "arc" && args.size() == 2) {
      within(args[0], kMaxDistance, "radius (m)");
      within(args[1], kMaxAngle, "angle (deg)");
    }
    if (cmd == "stop")
      for (double a : args) within(a, kMaxDuration, "duration (s)");
    auto need = [&](std::size_t n) {
      if (args.size() != n)
        throw ConfigError(where + ": '" + trim(cmdtext) + "': '" + cmd + "' takes " +
                          std::to_string(n) + " number" + (n == 1 ? "" : "s"));
    };
    const std::size_t pieces_before = b.pieces.size();
    if (cmd == "walk" || cmd == "back" || cmd == "left" || cmd == "right") {
      need(1);
      const double off = cmd == "walk"   ? 0
                         : cmd == "back" ? M_PI
                         : cmd == "left" ? M_PI / 2
                                         : -M_PI / 2;
      b.translate(args[0], off);
    } else if (cmd == "turn") {
      need(1);
      b.stand(b.yaw + deg(args[0]), std::abs(deg(args[0])) / lim.turn_rate);
    } else if (cmd == "face") {
      need(1);
      const double target = b.yaw + mrpt::math::wrapToPi(deg(args[0]) - b.yaw);
      b.stand(target, std::abs(target - b.yaw) / lim.turn_rate);
    } else if (cmd == "arc") {
      need(2);
      if (args[0] <= 0) throw ConfigError(where + ": '" + trim(cmdtext) + "': radius must be > 0");
      b.arc(args[0], deg(args[1]));
    } else if (cmd == "goto") {
      need(2);
      b.gotoPoint(args[0], args[1]);
    } else if (cmd == "stop") {
      need(1);
      if (args[0] < 0) throw ConfigError(where + ": '" + trim(cmdtext) + "': negative duration");
      b.stand(b.yaw, args[0]);
    } else if (cmd == "speed") {
      need(1);
      if (args[0] <= 0) throw ConfigError(where + ": '" + trim(cmdtext) + "': speed must be > 0");
      b.lim.speed = args[0];
    } else {
      throw ConfigError(where + ": unknown motion command '" + cmd +
                        "' (walk, back, left, right, turn, arc, goto, face, stop, speed)");
    }
    if (b.pieces.size() > pieces_before) path_points += b.pieces.back().px.size();
    if (path_points > kMaxPathPoints)
      throw ConfigError(where + ": the script walks farther than " +
                        std::to_string(static_cast<long>(kMaxPathPoints * 0.02 / 1000)) + " km");
  }

  // Time-parameterise: consecutive translations form one run without stopping in between;
  // walkers slow down for corners between them ((1 + cos turn) / 2 of the speed, at least 10 %).
  struct Raw {
    double t, x, y, facing;
    bool smooth;   // reached by a gradual facing change (arc, turn) rather than a corner
    double v = 0;  // path speed at this point
  };
  std::vector<Raw> raw{{0, x, y, yaw, false, 0}};
  double t = 0;
  for (std::size_t i = 0; i < b.pieces.size();) {
    if (!b.pieces[i].translate) {
      const Piece& p = b.pieces[i++];
      const int n = std::max(1, static_cast<int>(std::ceil(p.duration / kDt)));
      for (int k = 1; k <= n; ++k)
        raw.push_back({t + p.duration * k / n, raw.back().x, raw.back().y,
                       p.yaw0 + (p.yaw1 - p.yaw0) * k / n, true});
      t += p.duration;
      continue;
    }
    std::vector<double> px{b.pieces[i].px.front()}, py{b.pieces[i].py.front()},
        facing{b.pieces[i].facing.front()}, caps{b.pieces[i].speed};
    std::vector<bool> smooth{false};
    for (; i < b.pieces.size() && b.pieces[i].translate; ++i) {
      const Piece& p = b.pieces[i];
      if (px.size() > 1 && p.px.size() > 1) {
        const double a0 = std::atan2(py.back() - py[py.size() - 2], px.back() - px[px.size() - 2]);
        const double a1 = std::atan2(p.py[1] - p.py[0], p.px[1] - p.px[0]);
        const double slow = std::max(0.1, 0.5 * (1 + std::cos(mrpt::math::wrapToPi(a1 - a0))));
        caps.back() = std::min(caps.back(), slow * std::min(caps.back(), p.speed));
      }
      for (std::size_t k = 1; k < p.px.size(); ++k) {
        px.push_back(p.px[k]);
        py.push_back(p.py[k]);
        facing.push_back(p.facing[k]);
        caps.push_back(p.speed);
        smooth.push_back(p.smooth);
      }
    }
    const std::vector<double> v = speedProfile(px, py, caps, lim.accel);
    for (std::size_t k = 1; k < px.size(); ++k) {
      const double ds = std::hypot(px[k] - px[k - 1], py[k] - py[k - 1]);
      const double vm = std::max(0.5 * (v[k] + v[k - 1]), 0.02);
      t += ds / vm;
      raw.push_back({t, px[k], py[k], facing[k], smooth[k], v[k]});
    }
  }

  if (t > kMaxDuration)
    throw ConfigError(where + ": the script lasts longer than " +
                      std::to_string(static_cast<long>(kMaxDuration)) +
                      " s (the longest scenario)");
  // Resample at kDt; the body turns towards the commanded facing at a bounded rate.
  Trajectory tr;
  std::size_t j = 0;
  double facing = yaw;
  const int n = static_cast<int>(std::ceil(t / kDt));
  for (int k = 0; k <= n; ++k) {
    const double tk = std::min(k * kDt, t);
    while (j + 1 < raw.size() && raw[j + 1].t < tk) ++j;
    MotionSample s;
    s.t = tk;
    if (j + 1 < raw.size()) {
      const Raw &r0 = raw[j], &r1 = raw[j + 1];
      const double dt = r1.t - r0.t, tau = std::clamp(tk - r0.t, 0.0, std::max(dt, 0.0));
      const double u = dt > 0 ? tau / dt : 1.0;
      // Along a path segment the speed changes uniformly from v0 to v1 (the profile's constant
      // acceleration), so the distance covered grows quadratically, not linearly, with time.
      double w = u;
      if (dt > 0 && r0.v + r1.v > 1e-9)
        w = std::clamp(
            (r0.v * tau + 0.5 * (r1.v - r0.v) / dt * tau * tau) / (0.5 * (r0.v + r1.v) * dt), 0.0,
            1.0);
      s.x = r0.x + w * (r1.x - r0.x);
      s.y = r0.y + w * (r1.y - r0.y);
      const double target = r0.facing + u * (r1.facing - r0.facing);
      // Along arcs and turns the commanded facing itself moves smoothly: follow it; after a
      // corner or a new walking direction it jumps: turn at facing_rate.
      const double follow =
          r1.smooth ? std::abs(r1.facing - r0.facing) * kDt / std::max(r1.t - r0.t, kDt) : 0.0;
      const double step = lim.facing_rate * kDt + follow;
      facing += std::clamp(mrpt::math::wrapToPi(target - facing), -step, step);
    } else {
      s.x = raw.back().x;
      s.y = raw.back().y;
      facing += std::clamp(mrpt::math::wrapToPi(raw.back().facing - facing), -lim.facing_rate * kDt,
                           lim.facing_rate * kDt);
    }
    s.yaw = mrpt::math::wrapToPi(facing);
    tr.samples_.push_back(s);
  }
  // Velocities by central differences (what a perfect observer of the path would report).
  auto& S = tr.samples_;
  for (std::size_t k = 0; k < S.size(); ++k) {
    const std::size_t a = k ? k - 1 : k, c = k + 1 < S.size() ? k + 1 : k;
    const double dt = S[c].t - S[a].t;
    if (dt <= 0) continue;
    S[k].vx = (S[c].x - S[a].x) / dt;
    S[k].vy = (S[c].y - S[a].y) / dt;
    S[k].omega = mrpt::math::wrapToPi(S[c].yaw - S[a].yaw) / dt;
  }
  return tr;
}

Trajectory Trajectory::fromSamples(std::vector<MotionSample> samples) {
  Trajectory tr;
  tr.samples_ = std::move(samples);
  auto& S = tr.samples_;
  for (std::size_t k = 0; k < S.size(); ++k) {
    const std::size_t a = k ? k - 1 : k, c = k + 1 < S.size() ? k + 1 : k;
    if (S[c].t > S[a].t) S[k].omega = mrpt::math::wrapToPi(S[c].yaw - S[a].yaw) / (S[c].t - S[a].t);
  }
  return tr;
}

MotionSample Trajectory::at(double t) const {
  if (samples_.empty()) return {};
  if (t <= 0) {
    MotionSample s = samples_.front();
    s.t = t;
    return s;
  }
  const std::size_t k = static_cast<std::size_t>(t / kDt);
  if (k + 1 >= samples_.size()) {
    MotionSample s = samples_.back();
    s.t = t;
    s.vx = s.vy = s.omega = 0;
    return s;
  }
  const MotionSample &a = samples_[k], &b = samples_[k + 1];
  const double u = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
  MotionSample s;
  s.t = t;
  s.x = a.x + u * (b.x - a.x);
  s.y = a.y + u * (b.y - a.y);
  s.yaw = a.yaw + u * mrpt::math::wrapToPi(b.yaw - a.yaw);
  s.vx = a.vx + u * (b.vx - a.vx);
  s.vy = a.vy + u * (b.vy - a.vy);
  s.omega = a.omega + u * (b.omega - a.omega);
  return s;
}

std::string shapeScript(const std::string& shape, double length, double radius, double angle_deg,
                        int repeats) {
  std::ostringstream os;
  if (shape == "straight") {
    os << "walk " << length;
  } else if (shape == "C") {
    // Out along the top, a half circle turning right, back along the bottom (P0 §VI).
    os << "walk " << length << "; arc " << radius << " -180; walk " << length;
  } else if (shape == "circle") {
    os << "arc " << radius << " " << 360 * repeats;
  } else if (shape == "zigzag") {
    // Legs of `length` m alternating ±angle about the initial heading.
    os << "turn " << angle_deg << "; walk " << length;
    for (int i = 1; i < repeats; ++i)
      os << "; turn " << (i % 2 ? -2 : 2) * angle_deg << "; walk " << length;
  } else if (shape == "turn_in_place") {
    os << "turn " << angle_deg;
  } else if (shape == "sidestep") {
    os << "right " << length << "; stop 0.5; left " << length;
  } else {
    throw ConfigError("unknown path shape '" + shape + "'");
  }
  return os.str();
}

std::string randomWalkScript(unsigned seed, int legs, double x0, double y0, double x1, double y1,
                             double max_stop) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1), u01(0, 1);
  std::ostringstream os;
  os.precision(10);
  for (int i = 0; i < legs; ++i) {
    if (i) os << "; ";
    const double r = u01(rng);
    if (r < 0.15 && max_stop > 0)
      os << "stop " << u01(rng) * max_stop;
    else if (r < 0.25)
      os << "turn " << (u01(rng) - 0.5) * 360;
    else if (r < 0.32)
      os << (u01(rng) < 0.5 ? "left " : "right ") << 0.3 + 0.7 * u01(rng);
    else
      os << "goto " << ux(rng) << " " << uy(rng);
  }
  return os.str();
}

}  // namespace pedtrack::sim
