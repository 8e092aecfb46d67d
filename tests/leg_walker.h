#pragma once
// Shared by the leg tests (test_legs.cpp, test_leg_pose_parts.cpp, test_leg_pose_estimator.cpp,
// test_leg_one_leg_stand.cpp, test_leg_association.cpp, test_leg_unknown_motion.cpp): a synthetic
// walker's legs, the angle between two headings, and a walker who stops and stands in front of
// leg_people's tracker.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "leg_people/leg_people_tracker.h"

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

// `scans` scans from t (advanced) of a walker along +x at 1 m/s from x = -2, legs scissoring,
// seen from (0, -5), who stops at x = -0.5 (legs at y = ±0.09, after 1.5 m: confirmed) and
// stands. Returns the id of the confirmed person, 0 if none.
inline long walkThenStand(track::LegPeopleTracker& tr, double& t, int scans,
                          const std::function<bool(double, double)>& is_static = {}) {
  for (int k = 0; k < scans; ++k, t += 0.1) {
    const double x = std::min(-0.5, -2 + 1.0 * t);
    const double lp = x < -0.5 ? 0.25 * std::sin(2 * M_PI * 0.9 * t) : 0.0;
    tr.step(t, {{{x + lp / 2, 0.09}, 0.9, {0, -5}, -1}, {{x - lp / 2, -0.09}, 0.9, {0, -5}, -1}},
            is_static);
  }
  for (const track::PersonState& s : tr.people())
    if (s.confirmed) return s.id;
  return 0;
}

}  // namespace pedtrack::test
