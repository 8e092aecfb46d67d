#include "pedtrack/track/leg_zoning.h"

#include <cmath>

#include "pedtrack/track/gaussian.h"

namespace pedtrack::track {

const char* toString(MotionZone z) {
  switch (z) {
    case MotionZone::GoStraight:
      return "go_straight";
    case MotionZone::SlightTurn:
      return "slight_turn";
    case MotionZone::Sideways:
      return "sideways";
    case MotionZone::TurnInPlace:
      return "turn_in_place";
  }
  return "go_straight";
}

ZoneResult zoneOrientation(const Eigen::Vector2d& left, const Eigen::Vector2d& right,
                           double prev_yaw, double w0, const ZoningParams& p) {
  const Eigen::Vector2d d = left - right;
  const double c = std::cos(prev_yaw), s = std::sin(prev_yaw);
  ZoneResult out;
  out.sagittal = d.x() * c + d.y() * s;
  out.frontal = -d.x() * s + d.y() * c;
  out.yaw = prev_yaw;
  const double rho = d.norm();
  if (rho < 0.5 * w0) {
    out.observable = false;
    return out;
  }
  const double band = p.width_tolerance * w0;
  const double beta = std::atan2(out.frontal, out.sagittal);  // from the forward axis
  // The two-line construction: ρ sin(β − Δ) = W₀ has Δ = β − asin(W₀/ρ) or β − π + asin(W₀/ρ),
  // the smaller turn is taken; legs closer than W₀: the perpendicular is the nearest fit.
  double delta = wrapAngle(beta - M_PI / 2);
  if (rho > w0) {
    const double a = std::asin(w0 / rho);
    const double d1 = wrapAngle(beta - a), d2 = wrapAngle(beta - M_PI + a);
    delta = std::abs(d1) <= std::abs(d2) ? d1 : d2;
  }
  if (std::abs(out.frontal - w0) <= band) {
    out.zone = MotionZone::GoStraight;
    if (!p.refine_straight || std::abs(out.sagittal) < w0 || std::abs(delta) > p.slight_turn_max)
      return out;
  } else if (out.frontal > w0 + band && std::abs(out.sagittal) <= p.sideways_tolerance * w0) {
    out.zone = MotionZone::Sideways;
    return out;
  } else if (std::abs(delta) <= p.slight_turn_max) {
    out.zone = MotionZone::SlightTurn;
  } else {
    out.zone = MotionZone::TurnInPlace;
    delta = wrapAngle(beta - M_PI / 2);
    // With resolve_swaps, the legs' labels swapped rather than the person turned round when
    // the perpendicular is over 90° away: the other one is then the smaller turn.
    if (p.resolve_swaps && std::abs(delta) > M_PI / 2) {
      delta = wrapAngle(beta + M_PI / 2);
      out.swap = true;
    }
  }
  out.yaw = wrapAngle(prev_yaw + delta);
  return out;
}

}  // namespace pedtrack::track
