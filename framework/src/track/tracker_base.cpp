#include "pedtrack/track/tracker_base.h"

#include <cmath>

namespace pedtrack::track {

double FrameClock::step(double t) {
  const double prev = last_;
  last_ = t;
  if (!std::isfinite(prev) || !(t > prev)) return fallback_;
  return std::min(t - prev, max_dt_);
}

Track trackRow(long id, const Gaussian& g, const MotionModel& model) {
  Track r;
  r.id = id;
  r.x = g.x(0);
  r.y = g.x(1);
  const Eigen::Vector2d v = model.velocity(g.x);
  r.vx = v.x();
  r.vy = v.y();
  r.yaw = std::atan2(v.y(), v.x());
  r.cov_xx = g.P(0, 0);
  r.cov_xy = g.P(0, 1);
  r.cov_yy = g.P(1, 1);
  r.has_cov = true;
  return r;
}

}  // namespace pedtrack::track
