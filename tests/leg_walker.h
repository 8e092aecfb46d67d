#pragma once
// Shared by the leg tests (test_legs.cpp, test_leg_pose_parts.cpp, test_leg_pose_estimator.cpp): a
// synthetic walker's legs and the angle between two headings.
#include <Eigen/Core>
#include <cmath>
#include <utility>

namespace pedtrack::test {

inline double angleDiff(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * M_PI));
}

// A person facing `facing` walks forward along it at `speed` from the origin, legs scissoring
// (0.9 Hz, L0 0.3 m) W = 0.18 m apart; returns (left, right) at t.
inline std::pair<Eigen::Vector2d, Eigen::Vector2d> walkerLegs(double t, double facing,
                                                              double speed) {
  const Eigen::Vector2d fwd(std::cos(facing), std::sin(facing)), left(-fwd.y(), fwd.x());
  const Eigen::Vector2d c = speed * t * fwd;
  const double lp = 0.3 * std::sin(2 * M_PI * 0.9 * t);
  const Eigen::Vector2d half = 0.5 * (lp * fwd + 0.18 * left);
  return {Eigen::Vector2d(c + half), Eigen::Vector2d(c - half)};
}

}  // namespace pedtrack::test
