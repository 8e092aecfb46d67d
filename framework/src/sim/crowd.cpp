#include "pedtrack/sim/crowd.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace pedtrack::sim {
namespace {

// Social force parameters (per unit mass). τ: how fast people reach their preferred velocity;
// A, B: strength and range of the exponential repulsion; λ: people mind what is ahead of them
// more than what is behind (anisotropy of Helbing & Molnár 1995).
constexpr double kTau = 0.5, kA = 4.0, kB = 0.3, kLambda = 0.35;
constexpr double kRobotRadius = 0.4, kGoalReached = 0.5;

struct State {
  double x, y, vx = 0, vy = 0, yaw;
  double gx = 0, gy = 0;  // goal
  double stop_until = -1;
};

}  // namespace

std::vector<Trajectory> simulateCrowd(const std::vector<CrowdAgent>& agents,
                                      const std::vector<CircleObstacle>& obstacles,
                                      const Trajectory* robot, double duration,
                                      const CrowdArea& area, std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0, 1);
  auto newGoal = [&](State& s) {
    s.gx = area.x0 + (area.x1 - area.x0) * u01(rng);
    s.gy = area.y0 + (area.y1 - area.y0) * u01(rng);
  };
  std::vector<State> st;
  for (const auto& a : agents) {
    State s{a.x, a.y, 0, 0, a.yaw};
    newGoal(s);
    st.push_back(s);
  }
  const double dt = Trajectory::kDt;
  const int steps = static_cast<int>(std::ceil(duration / dt));
  std::vector<std::vector<MotionSample>> out(agents.size());
  for (int k = 0; k <= steps; ++k) {
    const double t = k * dt;
    for (std::size_t i = 0; i < st.size(); ++i) {
      MotionSample m;
      m.t = t;
      m.x = st[i].x;
      m.y = st[i].y;
      m.yaw = st[i].yaw;
      m.vx = st[i].vx;
      m.vy = st[i].vy;
      out[i].push_back(m);
    }
    if (k == steps) break;
    MotionSample rs;
    if (robot) rs = robot->at(t);
    std::vector<double> fx(st.size()), fy(st.size());
    for (std::size_t i = 0; i < st.size(); ++i) {
      State& s = st[i];
      double ex = s.gx - s.x, ey = s.gy - s.y;
      const double dg = std::hypot(ex, ey);
      if (dg < kGoalReached && s.stop_until < t) {
        // At the goal: sometimes pause, then head for a new one.
        if (area.max_stop > 0 && u01(rng) < 0.3) s.stop_until = t + area.max_stop * u01(rng);
        newGoal(s);
        ex = s.gx - s.x;
        ey = s.gy - s.y;
      }
      const double n = std::max(std::hypot(ex, ey), 1e-9);
      const double v0 = s.stop_until > t ? 0.0 : agents[i].speed;
      fx[i] = (v0 * ex / n - s.vx) / kTau;
      fy[i] = (v0 * ey / n - s.vy) / kTau;
      auto repel = [&](double ox, double oy, double reach, double strength) {
        const double dx = s.x - ox, dy = s.y - oy, d = std::max(std::hypot(dx, dy), 1e-6);
        if (d - reach > 3.0) return;
        const double nx = dx / d, ny = dy / d;
        // Anisotropy: full weight for what lies along the walking direction.
        const double cosphi = -(nx * ex + ny * ey) / n;
        const double w = kLambda + (1 - kLambda) * 0.5 * (1 + cosphi);
        const double f = strength * w * std::exp((reach - d) / kB);
        fx[i] += f * nx;
        fy[i] += f * ny;
      };
      for (std::size_t j = 0; j < st.size(); ++j)
        if (j != i) repel(st[j].x, st[j].y, agents[i].radius + agents[j].radius, kA);
      for (const auto& o : obstacles) repel(o.x, o.y, agents[i].radius + o.r, 2 * kA);
      if (robot) repel(rs.x, rs.y, agents[i].radius + kRobotRadius, 2 * kA);
    }
    for (std::size_t i = 0; i < st.size(); ++i) {
      State& s = st[i];
      s.vx += fx[i] * dt;
      s.vy += fy[i] * dt;
      const double v = std::hypot(s.vx, s.vy), vmax = 1.3 * agents[i].speed;
      if (v > vmax) {
        s.vx *= vmax / v;
        s.vy *= vmax / v;
      }
      s.x += s.vx * dt;
      s.y += s.vy * dt;
      // The body faces where it walks, turning at a bounded rate; standing, it keeps its facing.
      if (std::hypot(s.vx, s.vy) > 0.15) {
        const double step = area.facing_rate * dt;
        s.yaw = mrpt::math::wrapToPi(
            s.yaw + std::clamp(mrpt::math::wrapToPi(std::atan2(s.vy, s.vx) - s.yaw), -step, step));
      }
    }
  }
  std::vector<Trajectory> trajectories;
  for (auto& samples : out) trajectories.push_back(Trajectory::fromSamples(std::move(samples)));
  return trajectories;
}

}  // namespace pedtrack::sim
