#pragma once
// A person's heading from their two legs over several scans (ours, on top of P3 §2.3): a bank of
// hypotheses, each a constant-acceleration Kalman filter on [θ, θ̇, θ̈] (the heading block of
// P3's eq. 4, which the position blocks do not touch), weighed by how well it explains the
// scans so far.
//
// Why several: in the body frame a walker's leg vector d = left − right is (L_p, W₀), the
// sagittal spread L_p swinging with the gait and the frontal one the step width. One scan gives
// |d| and its direction, so L_p = ±√(|d|² − W₀²): two headings explain it, one per leg ahead,
// up to 2·atan(|L_p| / W₀) apart (over 100° at a brisk stride). P3's zoning takes the one
// nearer the previous heading; mid-turn that is often the wrong one (the turn stalls), and the
// zoning's turn-in-place reading, the perpendicular of d, is their mean and lags the body by
// atan(|L_p| / W₀). Only over several scans do the branches part: the right one turns smoothly,
// the wrong one swings with the gait. Each hypothesis takes each reading it can explain as a
// child; children are weighed by the reading's likelihood and by whether the person's motion
// agrees (people walk forward; legs open side by side only in a side step, with the body
// moving sideways), near-duplicates merge and the `count` best survive.
#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace pedtrack::track {

struct HeadingHypothesesParams {
  /// Hypotheses kept (0: off, P3's single zoning reading). 32, not 8: with 8 the bank filled
  /// with near neighbours of the best, and after a quick turn no hypothesis was left near the
  /// true heading or its mirror image (over 170 seeds of P3's scenarios, with the two keys
  /// below: 8.3 / 3.7 / 4.9 / 15.5° with 8, 7.2 / 3.7 / 4.9 / 13.9° with 16, 6.7 / 3.7 / 4.9 /
  /// 13.4° with 32 and 64; the time per scan is the simulator's either way).
  int count = 32;
  /// σ: a reading farther than this from a hypothesis's predicted heading spawns no child.
  double gate = 4;
  /// m, one leg circle's position error (the readings' geometric spread is derived from it).
  double sigma_leg = 0.02;
  /// m, the same for a leg circle partly hidden by something nearer beside it
  /// (LegSeen::occluded): fitted to the sliver seen, its centre sits off the leg's sideways (7 cm
  /// in P3 scenario 3's side view, where such readings set a turn going on past its end). Over
  /// 170 seeds of P3's scenarios the heading MAE went 8.4 / 7.6 / 5.7 / 16.3° -> 7.8 / 7.6 / 5.2
  /// / 15.2° with 0.07; 0.05: 8.2 / 7.5 / 5.1 / 15.6°, 0.1: 7.2 / 7.7 / 5.4 / 15.6°. 0: as
  /// sigma_leg.
  double occluded_sigma_leg = 0.07;
  /// rad, no reading is taken as sharper than this: about 0.05 rad, kept at the 2.86479° its key
  /// has always given (every figure was measured with it).
  double sigma_floor = 2.86479 * (M_PI / 180);
  /// Motion evidence: at motion_speed or faster the velocity's direction ψ is compared with
  /// a child's heading θ. A walking child (legs along the gait) expects ψ − θ ≈ 0, or ≈ π while
  /// it is in its walking-backward mode, in walk_weight of the scans (anything in the rest); a
  /// side-step child (legs opened side by side) expects ψ − θ ≈ ±π/2 in sideways_weight.
  /// Walking backward is a mode a person keeps for a while (P3 scenario 1 backs up 2 m), not a
  /// per-scan chance: entering or leaving it costs mode_switch once, and each metre walked in
  /// it backward_per_metre nats. So a hypothesis cannot swing round to face the way a
  /// backward walker goes, nor settle facing backward on a forward walker. From 0.15 m/s, not
  /// 0.3: side steps start slowly (P3 scenario 2's side step off its turn read as a 38° turn
  /// until it was 0.3 m/s fast; over 170 seeds scenario 2 went 7.6° -> 3.7°, scenario 3 5.2° ->
  /// 5.6°, where the walker sets off and stops).
  double motion_speed = 0.15;  ///< m/s
  /// rad, spread of ψ − θ about each expected direction: about 0.7 rad, the key's 40.107°.
  double motion_sigma = 40.107 * (M_PI / 180);
  double walk_weight = 0.6;      ///< see motion_speed
  double sideways_weight = 0.6;  ///< see motion_speed
  double mode_switch = 0.02;     ///< chance per scan of starting or ending a backward walk
  /// Nats per metre walked backward. 0.3, not 1: a backward walk (P3 scenario 1's 2 m) cost
  /// its true hypothesis more than the mirror image's renamed legs (label_swap) once that
  /// image survived in the larger bank, which then took the lead as the walker stopped
  /// (scenario 1 over 170 seeds 10.0° with 1, 7.2° with 0.5, 6.7° with 0.3 and with 0).
  double backward_per_metre = 0.3;
  double still_sideways_prior = 0.1;  ///< a side step read while slower than motion_speed
  /// Chance per scan that a turning person stops turning: each hypothesis turning faster than
  /// its rate's standard deviation also has a child with the turn rate and acceleration zeroed. A
  /// turn ends within a step; the constant- acceleration model alone would carry the heading on
  /// past it for several scans.
  double stop_turn_prior = 0.05;
  /// Chance per scan that a turn starts: each hypothesis also has a child whose turn-rate
  /// variance is opened by start_turn_rate², so a reading can set the rate at once.
  double start_turn_prior = 0.05;
  double start_turn_rate = 2.6;  ///< rad/s (150°/s: a brisk turn; internal)
  /// s, the turn rate and its change revert to zero with this time constant (0: P3's constant
  /// acceleration): people turn in bursts of a step or two, and with the legs hidden for a
  /// few scans a rate kept would carry the heading on far past where the turn ended. Only the
  /// transition's diagonal decays (the heading takes the undecayed rate over the step: ~10 %
  /// more turn at 0.1 s and 0.5 s, well inside the noise).
  double turn_tau = 0.5;
  /// s, and with this one (0: off) on a scan whose reading only bounds the heading (a leg
  /// hidden behind the other): such a reading cannot show a turn ending, so a rate kept at
  /// turn_tau carried the heading on past where the turn ended, onto the wrong branch of the
  /// legs' geometry when they came back (P3 scenario 3's walk-off after its turn; over 170
  /// seeds scenario 1 13.6° -> 10.1°, scenario 3 6.8° -> 5.7°, scenario 4 15.9° -> 16.4° with
  /// 0.2 s). 0.05 s with the bank of 32 and backward_per_metre 0.3: 6.7 / 3.7 / 4.9 / 13.4°
  /// against 7.8 / 3.7 / 5.6 / 14.2° (0.2 s, 8 hypotheses, 1 nat/m); 0.1 s: 7.0 / 3.7 / 5.2 /
  /// 13.0°, 0.02 s: 7.0 / 3.7 / 4.9 / 13.7°.
  double hidden_turn_tau = 0.05;
  /// rad, a hidden leg bounds the heading to the ray's perpendicular ± this (atan of the
  /// largest sagittal leg spread over the step width: 0.3 / 0.17 m; about 1.05 rad, the key's
  /// 60.1606°)
  double hidden_spread = 60.1606 * (M_PI / 180);
  /// rad/s and rad/s²: the turn rate's and its change's standard deviations are held below
  /// these. Unseen (legs hidden, bounds only) they would grow each scan until a hypothesis
  /// could reach any reading, its mirror image's too (capRateVariance). About 1 rad/s, the
  /// key's 57.2958°/s.
  double rate_sigma_max = 57.2958 * (M_PI / 180);
  double accel_sigma_max = 20;  // internal
  /// Chance per scan that the legs' names were swapped (a hypothesis reading d as right − left:
  /// `HeadingReading::mirrored`). The names are kept from scan to scan without the heading
  /// (LegPoseEstimator: nearest neighbour to where each leg was last seen), so left and right
  /// are evidence too: a turn in place of α reads, leg for leg, like one of π − α the other way,
  /// but only with the names exchanged. label_swap_hidden instead on a scan where a leg goes hidden
  /// or comes back (a name then rests on eq. 6's point or on where the leg was seen scans
  /// ago). 0 or 1: the names are no evidence. Both are set weaker than the naming's own error
  /// rate (~1 % of the scans with both legs seen, P3 scenario 4 against the simulator's legs): a
  /// hypothesis that lost the facing in a fast turn must be able to come back.
  double label_swap = 0.1;
  double label_swap_hidden = 0.2;
  double merge_angle = 0.05;  ///< rad: children closer than this (and in rate) merge
  double prune_log = 12;      ///< children this many nats below the best are dropped
};

/// One heading reading from a leg pair.
struct HeadingReading {
  double yaw = 0;         ///< rad
  double sigma = 0;       ///< rad
  bool sideways = false;  ///< legs side by side opened by a side step (else along the gait)
  /// > 0: not a measurement but a bound, the heading within ±spread of `yaw` (a leg hidden
  /// behind the other: the legs lie along the scanner's ray, so the heading is the ray's
  /// perpendicular give or take atan(L_p / W₀), L_p unknown). A hypothesis outside it loses
  /// weight (`sigma` the bound's softness); none moves. Consecutive scans of one occlusion
  /// repeat the same geometry, so as measurements they would add up to a false certainty.
  double spread = 0;
  /// Read from −d (the leg named left taken as the right one): see label_swap.
  bool mirrored = false;
};

/// The readings a leg vector d = left − right allows, for step width w0: the two gait branches
/// (L_p = ±√(|d|² − w0²); one when |d| ≤ w0), the side-step reading (d's perpendicular; only
/// when |d| > w0) and the same for −d (left and right the other way round), each σ from
/// sigma_leg (one leg's position error; `sigma_other` the other's, −1: the same) and `floor`. One
/// branch pair (d's perpendicular) while |L_p| ≤ 2·√2·sigma_leg (the legs passing each other); none
/// when |d| < w0 / 2.
std::vector<HeadingReading> legHeadingReadings(const Eigen::Vector2d& d, double w0,
                                               double sigma_leg, double floor,
                                               double sigma_other = -1);
/// The bound a hidden leg gives: d (visible leg minus eq. 6's point behind it, or the reverse)
/// lies along the ray, the heading within ±spread of its perpendicular, either way round.
std::vector<HeadingReading> hiddenLegHeadingBound(const Eigen::Vector2d& d, double spread,
                                                  double softness);

class HeadingHypotheses {
 public:
  struct Hypothesis {
    Eigen::Vector3d x;  ///< θ, θ̇, θ̈
    Eigen::Matrix3d P;
    double log_w = 0;
    bool backward = false;  ///< walking backward (see HeadingHypothesesParams::mode_switch)
    bool swapped = false;   ///< reads the legs' names the other way round (label_swap)
    double innovation = 0;  ///< its last reading minus its prediction, rad
  };

  HeadingHypotheses() = default;
  explicit HeadingHypotheses(const HeadingHypothesesParams& p) : p_(p) {}
  void setParams(const HeadingHypothesesParams& p) { p_ = p; }

  /// One hypothesis: this heading, rate and acceleration with covariance P (3×3).
  void start(const Eigen::Vector3d& x, const Eigen::Matrix3d& P);
  /// Several (e.g. an unknown facing: θ and θ + π), best first after sorting by log_w.
  void start(std::vector<Hypothesis> hypotheses);
  /// Every hypothesis predicted by dt with the acceleration variance var_a ((rad/s²)²), the
  /// rate held within ±max_rate (0: unbounded); `coast` (no leg seen) clears the acceleration
  /// first, as the pose filter's coasting does.
  void predict(double dt, double var_a, double max_rate, bool coast);
  /// Children per reading within the gate, weighed; `velocity` the person's, fixed frame.
  /// No readings: the hypotheses stay as predicted.
  /// `velocity_sigma` (m/s) its standard deviation: the motion's direction is then uncertain
  /// by about velocity_sigma / speed on top of motion_sigma.
  /// `names_uncertain`: a leg goes hidden or comes back this scan (label_swap_hidden).
  void update(const std::vector<HeadingReading>& readings, const Eigen::Vector2d& velocity,
              double velocity_sigma, double dt, double max_rate, bool names_uncertain = false);
  /// Every hypothesis turned round by π (the facing check), rate and acceleration cleared, the
  /// legs' names exchanged with it.
  void turnAround();

  const Hypothesis& best() const { return h_.front(); }
  const std::vector<Hypothesis>& all() const { return h_; }  ///< best first
  bool empty() const { return h_.empty(); }

 private:
  /// `spread` the motion's direction's, rad (motion_sigma and the velocity's own).
  double motionLogLikelihood(double yaw, bool sideways, bool backward, const Eigen::Vector2d& v,
                             double spread, double dt) const;
  void capRateVariance(Eigen::Matrix3d& P) const;

  HeadingHypothesesParams p_;
  std::vector<Hypothesis> h_;
};

}  // namespace pedtrack::track
