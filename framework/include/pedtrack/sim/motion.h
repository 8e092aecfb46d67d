#pragma once
// How a person (or the robot) moves: a motion script of body-frame commands, turned into a
// trajectory sampled at 100 Hz with bounded acceleration and a rate-limited facing direction.
//
// Script commands (separated by ';'):
//   walk D        forward D m            back D       backwards D m
//   left D        sidestep left D m      right D      sidestep right D m
//   turn DEG      turn in place (+ = counter-clockwise)
//   arc R DEG     walk forward on a circle of radius R m while turning DEG (+ = left)
//   goto X Y      walk to the point (X, Y), turning towards it on the way
//   face DEG      turn in place to the absolute heading DEG
//   stop S        stand still S s
//   speed V       walking speed for the following commands (m/s)
#include <string>
#include <vector>

namespace pedtrack::sim {

struct MotionLimits {
  double speed = 1.2;         ///< m/s, walking speed
  double accel = 0.8;         ///< m/s², speeding up and slowing down
  double turn_rate = 1.5708;  ///< rad/s, turning in place
  double facing_rate = 2.5;   ///< rad/s, how fast the body follows a new walking direction
};

/// One sample of a trajectory, in the world frame.
struct MotionSample {
  double t = 0;         ///< s since the trajectory's start
  double x = 0, y = 0;  ///< m
  double yaw = 0;       ///< facing (rad)
  double vx = 0, vy = 0;
  double omega = 0;  ///< rad/s
};

class Trajectory {
 public:
  static constexpr double kDt = 0.01;  ///< sampling period (s)

  /// Builds the trajectory of `script` from the pose (x, y, yaw). Throws ConfigError prefixed
  /// with `where` for a malformed command.
  static Trajectory fromScript(const std::string& script, double x, double y, double yaw,
                               const MotionLimits& limits, const std::string& where);

  /// A trajectory already sampled every kDt from t = 0 (with velocities), e.g. by a crowd model.
  static Trajectory fromSamples(std::vector<MotionSample> samples);

  /// State at time t (s since start), linearly interpolated; before the start the first sample,
  /// after the end the last one standing still.
  MotionSample at(double t) const;
  double duration() const { return samples_.empty() ? 0 : samples_.back().t; }
  const std::vector<MotionSample>& samples() const { return samples_; }

 private:
  std::vector<MotionSample> samples_;
};

/// Motion scripts of the named path shapes (see the scenario documentation).
std::string shapeScript(const std::string& shape, double length, double radius, double angle_deg,
                        int repeats);

/// A random walk: `legs` goto/stop/turn commands inside the box [x0,x1]×[y0,y1], from `seed`.
std::string randomWalkScript(unsigned seed, int legs, double x0, double y0, double x1, double y1,
                             double max_stop);

}  // namespace pedtrack::sim
