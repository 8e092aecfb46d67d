#include "pedtrack/sim/body.h"

#include <algorithm>
#include <cmath>
#include <functional>

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

namespace {

// Body frame (u forward, v left, z up above the ground) to world.
using ToWorld = std::function<Eigen::Vector3d(double, double, double)>;

// A box in the body frame: centre (u, v), half sizes along / across the body, z0..z1.
Primitive bodyBox(const ToWorld& world, double yaw, double u, double v, double hu, double hv,
                  double z0, double z1, int owner) {
  const Eigen::Vector3d c = world(u, v, 0);
  return Primitive::box(c.x(), c.y(), yaw, hu, hv, c.z() + z0, c.z() + z1, owner);
}

// The carried item: a bag hanging from the right hand, a suitcase pulled behind on the right by
// a handle from that hand, a pram pushed ahead (its handle at the hands' height).
void addCarried(BodyPose& out, const BodySpec& b, const ToWorld& world, double yaw,
                const Eigen::Vector3d& right_hand, int owner) {
  const double ground = world(0, 0, 0).z();
  switch (b.carry) {
    case Carry::None:
      return;
    case Carry::Bag: {
      const double top = right_hand.z() - ground;
      out.parts.push_back(Primitive::box(right_hand.x(), right_hand.y(), yaw, 0.17, 0.06,
                                         ground + top - 0.38, ground + top - 0.03, owner));
      return;
    }
    case Carry::Suitcase: {
      out.parts.push_back(bodyBox(world, yaw, -0.55, -0.3, 0.22, 0.12, 0.05, 0.65, owner));
      out.parts.push_back(Primitive::capsule(right_hand, world(-0.4, -0.3, 0.65), 0.015, owner));
      return;
    }
    case Carry::Pram: {
      const double z_hand = 0.45 * b.height;
      out.parts.push_back(bodyBox(world, yaw, 0.85, 0, 0.4, 0.28, 0.3, 0.95, owner));
      for (const double u : {0.55, 1.15})
        for (const double v : {-0.25, 0.25})
          out.parts.push_back(bodyBox(world, yaw, u, v, 0.1, 0.02, 0, 0.25, owner));
      out.parts.push_back(
          Primitive::capsule(world(0.4, -0.25, z_hand), world(0.4, 0.25, z_hand), 0.015, owner));
      out.parts.push_back(
          Primitive::capsule(world(0.4, 0, z_hand), world(0.5, 0, 0.95), 0.015, owner));
      return;
    }
  }
}

// Seated 0.45 m up: torso and head above the seat, thighs forward, shins down, hands on the
// thighs. Truth legs at the shins (where a leg-height scanner meets them).
BodyPose sittingBody(const BodySpec& b, const ToWorld& world, const MotionSample& s,
                     double ground_z, double leg_ref_height, int owner) {
  BodyPose out;
  const double H = b.height, seat = 0.45, z_torso1 = seat + 0.31 * H;
  out.parts.push_back(Primitive::ellipticCylinder(
      s.x, s.y, s.yaw, b.beta, b.alpha, ground_z + seat + 0.02, ground_z + z_torso1, owner));
  out.parts.push_back(Primitive::sphere(world(0, 0, z_torso1 + 0.11 * H), 0.065 * H, owner));
  const double half_w = 0.5 * b.step_width, thigh = 0.24 * H;
  for (int side : {+1, -1}) {
    const Eigen::Vector3d hip = world(0, side * half_w, seat),
                          knee = world(thigh, side * half_w, seat + 0.02);
    const Eigen::Vector3d foot = world(thigh + 0.05, side * half_w, 0.08);
    out.parts.push_back(Primitive::capsule(hip, knee, b.leg_radius * 1.2, owner));
    out.parts.push_back(Primitive::capsule(knee, foot, b.leg_radius, owner));
    const double u = std::clamp((leg_ref_height - 0.08) / (seat - 0.06), 0.0, 1.0);
    (side > 0 ? out.left_leg : out.right_leg) = (foot + u * (knee - foot)).head<2>();
    const double off = b.alpha + b.arm_radius;
    out.parts.push_back(Primitive::capsule(world(0, side * off, z_torso1 - 0.03 * H),
                                           world(0.7 * thigh, side * (off - 0.05), seat + 0.12),
                                           b.arm_radius, owner));
  }
  if (b.carry == Carry::Bag)  // beside them on the seat
    out.parts.push_back(bodyBox(world, s.yaw, 0, -0.5, 0.17, 0.06, seat, seat + 0.35, owner));
  return out;
}

}  // namespace

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
  if (b.sitting) return sittingBody(b, world, s, ground_z, leg_ref_height, owner);
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
    if (side < 0) addCarried(out, b, world, s.yaw, hand, owner);
  }
  return out;
}

}  // namespace pedtrack::sim
