#pragma once
// P3 §2.3's motion-intention zoning: the orientation measurement from the two legs' positions,
// with the previous orientation θ̂ as the baseline. In the body frame of θ̂ (u forward, v left)
// the leg vector d = left − right is ρ (cos β, sin β); walking straight keeps its frontal part
// d_v near the step width W₀ while the sagittal part swings.
//
//  - go-straight (usual): |d_v − W₀| ≤ width_tolerance · W₀. P3: orientation unchanged. With
//    refine_straight (ours), when the legs are also apart along the sagittal axis (|d_u| ≥ W₀,
//    where the construction below is well conditioned) the small turn it gives is measured too:
//    P3's band otherwise hides every heading error up to acos(1 − width_tolerance).
//  - move-sideways (unusual): d_v > W₀ + the band and |d_u| ≤ sideways_tolerance · W₀ (the legs
//    apart side by side). Orientation unchanged.
//  - go-straight-slight-turn (usual): two parallel lines W₀ apart through the legs give the new
//    sagittal direction, ρ sin(β − Δ) = W₀, the solution nearest θ̂ (Fig. 4 right), accepted
//    while |Δ| ≤ slight_turn_max.
//  - turn-in-place (unusual): the sagittal axis perpendicular to the leg vector, Δ = β − 90° (with
//    resolve_swaps, β + 90° and the legs' labels swapped when that is the smaller turn).
// P3 gives the zones as a figure, not numbers: the thresholds are ours (documented parameters
// of leg_pose and leg_people).
#include <Eigen/Core>
#include <cmath>

namespace pedtrack::track {

enum class MotionZone { GoStraight, SlightTurn, Sideways, TurnInPlace };
const char* toString(MotionZone z);  ///< "go_straight", "slight_turn", "sideways", "turn_in_place"
/// Go-straight and slight turn: the gait model predicts the legs (P3 §2.5).
inline bool isUsual(MotionZone z) {
  return z == MotionZone::GoStraight || z == MotionZone::SlightTurn;
}

struct ZoningParams {
  double width_tolerance = 0.15;    ///< go-straight band half-width, fraction of W₀
  double sideways_tolerance = 0.3;  ///< side step: |d_u| within this fraction of W₀
  bool refine_straight = true;      ///< measure small turns inside the go-straight band
  /// rad: larger turns are turns in place (about 0.79 rad, the key's 45.2637°).
  double slight_turn_max = 45.2637 * (M_PI / 180);
  /// A turn in place of over 90° is read as the legs' labels swapped (the nearer perpendicular).
  /// Off for one person, whose legs the estimator labels itself and whose fast turns may leave
  /// θ̂ far behind; on in leg_people, where a crowd's global assignment swaps leg identities
  /// far more often than anyone turns about between two scans.
  bool resolve_swaps = false;
};

struct ZoneResult {
  MotionZone zone = MotionZone::GoStraight;
  double yaw = 0;       ///< the orientation measurement θ_m (rad), θ̂ + Δ wrapped
  double frontal = 0;   ///< d_v in θ̂'s body frame (m): the step width measured
  double sagittal = 0;  ///< d_u in θ̂'s body frame (m): L_p measured
  /// False when the legs are closer than half a step width (crossing, or one leg's return taken
  /// for both): their vector's direction is then noise, and no orientation is measured.
  bool observable = true;
  /// True when the legs are taken the other way round (left is right): a turn in place reads
  /// the perpendicular nearest θ̂, and one more than 90° away means the labels, not the person,
  /// turned (no one turns 180° between two scans).
  bool swap = false;
};

/// The zone of the leg pair (left, right) relative to `prev_yaw`, and the orientation it gives.
ZoneResult zoneOrientation(const Eigen::Vector2d& left, const Eigen::Vector2d& right,
                           double prev_yaw, double w0, const ZoningParams& p);

}  // namespace pedtrack::track
