#pragma once
// The bookkeeping every tracker plugin repeats otherwise: the time step between frames, stable
// track ids, and a tracks.csv row from a filter's estimate.
#include <cmath>
#include <limits>

#include "pedtrack/frame.h"
#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {

/// Δt between consecutive frames, guarded against a first frame, clock jumps and replays that
/// go backwards (both give `fallback`), and capped at `max_dt` so a pause in the log does not
/// inflate every covariance.
class FrameClock {
 public:
  explicit FrameClock(double fallback = 0.1, double max_dt = 1.0)
      : fallback_(fallback), max_dt_(max_dt) {}
  double step(double t);
  bool first() const { return !std::isfinite(last_); }

 private:
  double fallback_, max_dt_;
  double last_ = std::numeric_limits<double>::quiet_NaN();
};

/// Ids 1, 2, 3, … never reused within a run.
class TrackIds {
 public:
  long next() { return ++last_; }

 private:
  long last_ = 0;
};

/// A tracks.csv row of an estimate: position, velocity and heading from `model`'s state layout,
/// and the position covariance.
Track trackRow(long id, const Gaussian& g, const MotionModel& model);

}  // namespace pedtrack::track
