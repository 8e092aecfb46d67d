#pragma once
// The articulated pedestrian: torso (elliptic cylinder), head (sphere), two arms and two legs
// (capsules) posed by a gait phase that advances with the distance walked.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/motion.h"

namespace pedtrack::sim {

/// What a person carries: a bag in the right hand, a suitcase pulled behind, a pram pushed ahead.
enum class Carry { None, Bag, Suitcase, Pram };

struct BodySpec {
  double alpha = 0.20;        ///< torso semi-axis across the shoulders (m)
  double beta = 0.12;         ///< torso semi-axis front to back (m)
  double height = 1.70;       ///< m
  double arm_swing = 0.35;    ///< rad, amplitude of the arm swing at full walking speed
  double step_length = 0.65;  ///< m, distance between the feet at the widest stride
  double step_width = 0.18;   ///< m, lateral distance between the feet
  double cadence = 0;         ///< steps/s while walking; 0: speed / step_length
  double leg_radius = 0.055;  ///< m
  double arm_radius = 0.045;  ///< m
  Carry carry = Carry::None;  ///< carried items count as the person (their points are theirs)
  bool sitting = false;       ///< seated 0.45 m up, thighs forward (a person on a bench)
};

/// A posed body: its primitives and where its legs cross a reference height.
struct BodyPose {
  std::vector<Primitive> parts;
  Eigen::Vector2d left_leg, right_leg;  ///< leg axes at the reference height (world, m)
};

/// Gait phase bookkeeping: integrate over time with the trajectory's speeds.
class GaitClock {
 public:
  /// Advances the phase by the motion between the previous call and `s` (dt = s.t - last t).
  void advance(const MotionSample& s, const BodySpec& b);
  double phase() const { return phase_; }
  double amplitude() const { return amplitude_; }

 private:
  double phase_ = 0, amplitude_ = 0, last_t_ = 0;
  bool started_ = false;
};

/// Poses `body` at trajectory state `s` with gait `gait`, standing on the ground at height
/// `ground_z`. `leg_ref_height` is the height (above the ground) at which leg positions are
/// reported.
BodyPose poseBody(const BodySpec& body, const MotionSample& s, const GaitClock& gait,
                  double ground_z, double leg_ref_height, int owner);

}  // namespace pedtrack::sim
