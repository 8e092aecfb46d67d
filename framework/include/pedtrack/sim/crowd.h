#pragma once
// A crowd that walks like one: the social force model (Helbing & Molnár 1995) moves every person
// towards random goals while they keep clear of each other, of static objects and of the robot,
// so simulated people do not walk through one another as independent scripts would.
#include <random>
#include <vector>

#include "pedtrack/sim/motion.h"

namespace pedtrack::sim {

struct CrowdAgent {
  double x = 0, y = 0, yaw = 0;  ///< start pose
  double speed = 1.2;            ///< preferred walking speed (m/s)
  double radius = 0.25;          ///< body radius for keeping clear (m)
};

struct CircleObstacle {
  double x = 0, y = 0, r = 0;
};

/// Where and how the crowd walks.
struct CrowdArea {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< box goals are drawn from
  double max_stop = 0;                    ///< longest pause at a goal (s)
  double facing_rate = 2.6;               ///< rad/s, how fast bodies turn to the walking direction
};

/// Trajectories of `agents` over `duration` s. `robot` (may be null) is avoided like a person of
/// radius 0.4 m.
std::vector<Trajectory> simulateCrowd(const std::vector<CrowdAgent>& agents,
                                      const std::vector<CircleObstacle>& obstacles,
                                      const Trajectory* robot, double duration,
                                      const CrowdArea& area, std::mt19937& rng);

}  // namespace pedtrack::sim
