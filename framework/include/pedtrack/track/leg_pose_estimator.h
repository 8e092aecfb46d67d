#pragma once
// One person seen as two legs (P3 §2.3–2.5): a constant-acceleration Kalman filter on the pose
// [X, Y, θ] (eq. 4–5) whose position measurement is the legs' midpoint and whose orientation
// measurement comes from the motion-intention zoning (leg_zoning.h); the step width W₀ learned
// over the first seconds; the gait model (gait_model.h) predicting where each leg will be, so
// the next scan's legs are told left from right by nearest neighbour; a leg hidden behind the
// other placed by the hidden-area attraction of eq. 6–7.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "pedtrack/track/gait_model.h"
#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/heading_hypotheses.h"
#include "pedtrack/track/leg_zoning.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {

struct LegPoseParams {
  double var_ax = 100, var_ay = 100;  ///< (m/s²)², P3 §2.5's σ²_ax, σ²_ay
  double var_atheta = 9.86960440109;  ///< (rad/s²)², P3's σ²_aθ = π² (to the key's 12 digits)
  double sigma_xy = 0.03;             ///< m, P3's σ_X = σ_Y
  double sigma_theta = 12 * (M_PI / 180);  ///< rad, P3's σ_θ = π/15, as the key's 12°
  /// The measurement's standard deviations are multiplied by this when one leg was inferred
  /// (P3: "while increasing the input's variance").
  double inferred_sigma_scale = 3;
  bool occlusion = true;     ///< eq. 6–7; false: a hidden leg is the plain prediction
  double w0_default = 0.18;  ///< m, step width until one is learned
  double w0_time = 3;        ///< s, W₀ is the mean frontal leg distance over this long
  double leg_gate = 0.4;     ///< m, a leg farther from both predicted legs is not this person's
  int gait_frames = 20;      ///< N of eq. 3 (P3: one gait cycle, 20 frames)
  /// s, with neither leg seen the velocity decays with this time constant (0: held). A
  /// pedestrian's velocity is mean-reverting: in company people stop, swerve and turn within a
  /// second, so a lost person is looked for near where they vanished rather than where a
  /// constant velocity would have carried them.
  double coast_tau = 0.5;
  /// rad/s, the turn rate state is held within ±this (ours; 0: unbounded). P3's constant-
  /// acceleration model lets one wrong turn-in-place reading wind the rate up to thousands of
  /// degrees a second, after which every prediction lands on another wrong reading; a quick
  /// pivot is about 180° in 0.6 s.
  double max_turn_rate = 300 * M_PI / 180;
  /// The orientation measurement's normalised innovation is held within this many standard
  /// deviations by inflating its variance (a robust Kalman update; ours; 0: off): a reading far
  /// from the prediction is more often a leg taken for the other than a turn.
  double orientation_gate = 3;
  /// m, the facing check (ours; 0: off). The legs cannot tell a person walking forward from
  /// one walking backward with the estimate turned round (left and right swapped with it): the
  /// two explain every scan alike, and a fast turn can leave the estimate on the wrong one for
  /// good. People walk forward far more than backward, so the distance walked along the
  /// estimated facing minus the distance walked against it is summed, starting at (and capped
  /// at) this; an orientation innovation over 45° shrinks it (by half at 67.5°, to nothing from
  /// 90°: the reading may have been the mirror image), and so does, with the heading hypotheses,
  /// the lead passing to a hypothesis walking the other way (forward or backward), by its jump
  /// from the prediction; once it falls below −mirror_margin the estimate is turned round. A person
  /// who walks backward further than this after a clean track is then read as facing the way they
  /// walk.
  double backward_walk_max = 2.5;
  double mirror_margin = 0.3;     ///< m, see backward_walk_max
  double mirror_min_speed = 0.3;  ///< m/s, slower motion is no evidence of facing
  /// rad, people walk forward: at motion_heading_speed or faster the direction of the estimated
  /// velocity is a second orientation measurement with this standard deviation (ours; 0: off,
  /// P3's model). In a crowd the zoning reads legs that are often hidden, inferred or someone
  /// else's, and the motion tells the heading better; a side step (P3 scenario 2) it misreads.
  /// Not applied when over 90° from the heading (walking backward: the facing rules decide).
  double motion_heading_sigma = 0;
  double motion_heading_speed = 0.5;  ///< m/s, see motion_heading_sigma
  /// Eq. 3's solver: gait::fitVarPro, or Ipopt by gait::fitIpopt (pedtrack_ipopt, so these parts
  /// do not depend on Ipopt), which useChosenGaitSolver() plugs into gait_solver.
  enum class GaitSolver { VarPro, Ipopt } solver = GaitSolver::VarPro;
  /// The solver called: null = gait::fitVarPro.
  gait::Params (*gait_solver)(const std::vector<gait::Sample>&, const gait::Bounds&,
                              const gait::Params& previous) = nullptr;
  ZoningParams zoning;
  gait::Bounds gait;
  /// The heading over several scans (heading_hypotheses.h; ours): with count > 0 it replaces
  /// the zoning's single orientation reading and the gate (the zoning still names the zone;
  /// max_turn_rate and the facing check act on the hypotheses too); 0: P3's zoning.
  HeadingHypothesesParams heading;
};

/// A leg measurement in the fixed frame, or none.
struct LegSeen {
  bool seen = false;
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  /// Partly hidden by something nearer beside it: its position is less sure (heading readings
  /// take HeadingHypothesesParams::occluded_sigma_leg).
  bool occluded = false;
};

class LegPoseEstimator {
 public:
  explicit LegPoseEstimator(const LegPoseParams& p);

  /// Starts at the legs' midpoint facing `yaw`; the leg on the left of `yaw` is the left one.
  void start(double t, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double yaw);
  bool started() const { return started_; }

  /// Predicts the pose to time t and where each leg will be.
  void predict(double t);
  const Eigen::Vector2d& predictedLeft() const { return pred_left_; }
  const Eigen::Vector2d& predictedRight() const { return pred_right_; }

  /// Nearest-neighbour labelling (P3 §2.5) of candidate leg positions to the predicted legs:
  /// the pair (i → left, j → right) with the least summed squared distance, both within
  /// leg_gate; else the single nearest within the gate. Indices into `candidates`, -1 for none.
  /// A leg's distance is to its predicted place or, when nearer, to where it was last seen (in
  /// the last half second; ours): a standing leg stays where it was when the gait model or a
  /// wrong heading sends the prediction ahead, and would otherwise fall out of the gate.
  std::pair<int, int> associate(const std::vector<Eigen::Vector2d>& candidates) const;

  /// The update with this scan's labelled legs (either may be missing); `sensor` is the
  /// scanner's position (fixed frame), the apex of eq. 6's hidden area.
  void update(const LegSeen& left, const LegSeen& right, const Eigen::Vector2d& sensor);

  /// A hidden leg's position by eq. 6–7: `visible` the other leg, `predicted` the hidden leg's
  /// prediction, `hidden_for` the occlusion's duration T_o (s).
  static Eigen::Vector2d hiddenLeg(const Eigen::Vector2d& sensor, const Eigen::Vector2d& visible,
                                   const Eigen::Vector2d& predicted, double w0, double hidden_for);

  const Gaussian& state() const { return g_; }
  double x() const { return g_.x(0); }
  double y() const { return g_.x(1); }
  double yaw() const { return g_.x(2); }
  Eigen::Vector2d velocity() const { return g_.x.segment<2>(3); }
  /// Replaces the parameters from the next prediction on; the state, its covariance, the gait
  /// fit and the step width are kept (leg_people: a person confirmed gets a walker's).
  void retune(const LegPoseParams& p);
  /// Turns the estimate round by π (front and back swapped; left and right with them).
  void turnAround();
  /// Sets the velocity (fixed frame, m/s) and clears the acceleration; the heading is kept.
  void setVelocity(const Eigen::Vector2d& v);
  /// The last update() found the legs the other way round and swapped its left and right (a
  /// caller that keeps its own leg identities swaps them too).
  bool legsSwapped() const { return legs_swapped_; }
  /// The last update() turned the estimate round by the facing check (backward_walk_max); its
  /// left and right were swapped with it (legsSwapped() is true too).
  bool turnedRound() const { return turned_round_; }
  /// m, the facing check's evidence: walked along the facing minus against it, capped.
  double facingWalked() const { return facing_walked_; }
  MotionZone zone() const { return zone_; }
  double stepWidth() const { return w0_; }
  bool stepWidthLearned() const { return w0_learned_; }
  const gait::Params& gait() const { return gait_; }
  const Eigen::Vector2d& left() const { return left_; }    ///< last (measured or inferred) leg
  const Eigen::Vector2d& right() const { return right_; }  ///< last (measured or inferred) leg

 private:
  void learnStepWidth(double distance);
  void recordGait(double t);
  void clampTurnRate();
  void updateFromMotion();
  void checkFacing(double innovation);
  bool multiHeading() const { return p_.heading.count > 0; }
  /// The pose filter's heading block (θ, θ̇, θ̈) set to the best hypothesis's.
  void takeBestHeading();
  /// The hypotheses (one) and the walk filter started from the pose filter's state.
  void startHeadings();
  /// update()'s measurement step, `k` the noise factor (inferred legs), `observable` whether
  /// the legs gave an orientation; returns the heading's innovation (for the facing check).
  double updateWithZoning(double k, bool& observable);  // P3's single reading
  /// The same with the hypotheses (heading_hypotheses.h): `legs_d` the leg vector they read,
  /// `inferred` whether one leg was hidden (a bound, not readings).
  /// `left_is_a`: left_ is the hypotheses' leg A (nameLegs); `names_uncertain`: a leg goes hidden
  /// or comes back (HeadingHypothesesParams::label_swap_hidden).
  double updateWithHypotheses(const Eigen::Vector2d& legs_d, bool inferred, bool left_is_a,
                              bool names_uncertain, bool& observable);
  bool occluded_left_ = false, occluded_right_ = false;  // this scan's legs (LegSeen::occluded)
  /// left_ and right_ (and their hidden times) exchanged.
  void swapNames();
  /// Whether left_ is the hypotheses' leg A, from where A and B were last seen (both legs seen;
  /// else the visible one and eq. 6's point behind it, `sensor` the scanner); updates those.
  bool nameLegs(bool left_seen, bool right_seen, const Eigen::Vector2d& sensor);

  LegPoseParams p_;
  PoseConstantAcceleration model_;
  Gaussian g_;
  bool started_ = false;
  double t_ = 0, t_start_ = 0, prev_yaw_ = 0;
  double measured_yaw_ = 0;  // the last orientation measurement a turning zone gave
  bool have_measured_yaw_ = false;
  double hidden_left_ = 0, hidden_right_ = 0;  // T_o per leg, s
  bool legs_swapped_ = false;
  bool turned_round_ = false;
  // The hypotheses' names for the legs, A and B, and where each was last seen: kept from scan
  // to scan by nearest neighbour to those places, with no use of the heading (which the
  // association to pred_left_ / pred_right_ makes), so that they are evidence for it
  // (HeadingHypothesesParams::label_swap). A hidden leg's place stays where it was last seen.
  Eigen::Vector2d leg_a_ = Eigen::Vector2d::Zero(), leg_b_ = Eigen::Vector2d::Zero();
  double dt_ = 0;             // the last prediction's step, s
  double facing_walked_ = 0;  // m, backward_walk_max's evidence
  double w0_ = 0;
  std::vector<double> w0_samples_;  // leg distances while W₀ is learned
  bool w0_learned_ = false;
  MotionZone zone_ = MotionZone::GoStraight;
  Eigen::Vector2d body_d_ = Eigen::Vector2d::Zero();  // last leg vector in the body frame (u, v)
  std::vector<gait::Sample> samples_;                 // newest first
  gait::Params gait_;
  Eigen::Vector2d pred_left_, pred_right_, left_, right_;
  Eigen::Vector2d seen_left_ = Eigen::Vector2d::Zero(), seen_right_ = Eigen::Vector2d::Zero();
  HeadingHypotheses headings_;
  // The hypotheses' motion evidence: a walker's constant-velocity filter on the legs'
  // midpoint. P3's pose filter (σ_a = 10 m/s²) follows every leg fit, and its velocity reads
  // half a metre per second on someone standing still.
  ConstantVelocity walk_model_{1.0};  // q, m²/s³: a walker's gentle speed changes
  Gaussian walk_;
};

}  // namespace pedtrack::track
