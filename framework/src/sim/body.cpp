#include "pedtrack/sim/body.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::sim {

void GaitClock::advance(const MotionSample& s, const BodySpec& b) {
  const double dt = started_ ? s.t - last_t_ : 0;
  started_ = true;
  last_t_ = s.t;
  const double v = std::hypot(s.vx, s.vy);
  // One stride (two steps) per 2·step_length walked: dφ/dt = π v / L. Turning in place shuffles
  // the feet as if walking a quarter metre per radian. A set cadence (steps/s) replaces the
  // speed-derived one while moving: dφ/dt = π·cadence.
  const double moving = v + 0.25 * std::abs(s.omega);
  const double rate = b.cadence > 0 ? M_PI * b.cadence * std::clamp(moving / 0.3, 0.0, 1.0)
                                    : M_PI * moving / b.step_length;
  phase_ = std::fmod(phase_ + rate * std::max(0.0, dt), 2 * M_PI);
  // Feet close when standing, open fully from a slow walk on.
  const double target = std::clamp(std::max(v / 0.6, std::abs(s.omega) / 3.0), 0.0, 1.0);
  const double k = std::clamp(dt / 0.3, 0.0, 1.0);
  amplitude_ += k * (target - amplitude_);
}

BodyPose poseBody(const BodySpec& b, const MotionSample& s, const GaitClock& gait, double ground_z,
                  double leg_ref_height, int owner) {
  const double H = b.height, c = std::cos(s.yaw), sn = std::sin(s.yaw);
  // Body frame: u forward, v left, z up; to world.
  auto world = [&](double u, double v, double z) {
    return Eigen::Vector3d(s.x + u * c - v * sn, s.y + u * sn + v * c, ground_z + z);
  };
  // Motion direction in the body frame (forward when standing).
  double mu = 1, mv = 0;
  const double speed = std::hypot(s.vx, s.vy);
  if (speed > 0.05) {
    mu = (s.vx * c + s.vy * sn) / speed;
    mv = (-s.vx * sn + s.vy * c) / speed;
  }
  const double ph = gait.phase(), amp = gait.amplitude(), swing = std::sin(ph);

  BodyPose out;
  const double z_hip = 0.50 * H, z_torso0 = 0.52 * H, z_shoulder = 0.81 * H;
  out.parts.push_back(Primitive::ellipticCylinder(
      s.x, s.y, s.yaw, b.beta, b.alpha, ground_z + z_torso0, ground_z + z_shoulder, owner));
  out.parts.push_back(Primitive::sphere(world(0, 0, 0.92 * H), 0.065 * H, owner));

  // Legs: hip joint above the foot's lateral position, foot displaced along the motion
  // direction (sagittal) or stepping out sideways (lateral).
  const double half_w = 0.5 * b.step_width, ankle = 0.08;
  const double sag = 0.5 * b.step_length * amp * swing * mu;
  const double lat = 0.25 * b.step_length * amp * (1 + swing) * std::abs(mv);
  const double lat_sign = mv >= 0 ? 1 : -1;
  for (int side : {+1, -1}) {  // +1 left, -1 right
    // Sidestepping: the leading leg (towards the motion) opens, the trailing one follows it
    // part of the way; both move in the direction of the motion, so the legs never cross.
    const double dv = side * half_w + lat_sign * (side == lat_sign ? lat : 0.3 * lat);
    const Eigen::Vector3d hip = world(0, side * half_w * 0.9, z_hip);
    const Eigen::Vector3d foot = world(side * sag, dv, ankle);
    out.parts.push_back(Primitive::capsule(foot, hip, b.leg_radius, owner));
    const double u = std::clamp((leg_ref_height - ankle) / (z_hip - ankle), 0.0, 1.0);
    const Eigen::Vector3d at = foot + u * (hip - foot);
    (side > 0 ? out.left_leg : out.right_leg) = at.head<2>();
    // Arm on this side swings against this side's leg.
    const double a = -side * b.arm_swing * amp * swing * mu;
    const double arm_len = 0.40 * H, off = b.alpha + b.arm_radius;
    const Eigen::Vector3d shoulder = world(0, side * off, z_shoulder - 0.03 * H);
    const Eigen::Vector3d hand =
        world(arm_len * std::sin(a), side * off, z_shoulder - 0.03 * H - arm_len * std::cos(a));
    out.parts.push_back(Primitive::capsule(shoulder, hand, b.arm_radius, owner));
  }
  return out;
}

}  // namespace pedtrack::sim
