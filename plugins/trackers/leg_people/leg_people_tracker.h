#pragma once
// Multi-person tracking from leg-height scans, in the manner of leg_tracker (Leigh et al., ICRA
// 2015) with P3's pose estimator per person:
//  - every leg-circle cluster is an object tracked by a constant-velocity filter, people's legs
//    and clutter alike, so a bin or a table leg keeps its own track and cannot steal a leg's
//    association; one global nearest-neighbour assignment (Hungarian) per scan;
//  - a person's two leg objects are predicted by their LegPoseEstimator (gait model, step width),
//    other objects by their own filter;
//  - two free objects that look like legs (mean classifier score) and stand close together
//    become a tentative person, never where the static scene says a wall or furniture stands;
//  - a confirmed person lost from sight takes back a new leg pair near where they were predicted
//    (re-identification), so walkers hidden by others in a crowd keep their ids; one whose leg
//    objects are all gone takes back a lone walking leg there too (reidentify_leg_scans);
//  - two people closer than a body is deep are one (a person split in two by scans merged out of
//    step, a coasting track beside its person's new one): the weaker is deleted;
//  - a person is confirmed once it has moved (legs' classifier confidence and motion, as
//    leg_tracker confirms) with legs that scissor as a walker's do, and deleted after a stretch
//    with neither leg seen.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/leg_pose_estimator.h"
#include "pedtrack/track/motion_models.h"

namespace pedtrack::track {

/// leg_people's pose-estimator defaults: P3's model with a crowd's position noise (below), and
/// no turn-rate bound, no orientation gate, no facing check, no motion heading. leg_people turns
/// a person round by its own rule (flip_speed, flip_time), and on the simulated crowds (4 seeds
/// each, static and moving) the three changed MOTA and ID switches by less than the seeds' spread;
/// they stay options.
inline LegPoseParams legPeoplePoseDefaults() {
  LegPoseParams p;
  // In a crowd a person's legs are often hidden or misassigned, and P3's 10 m/s² acceleration
  // noise (one tracked walker, both legs nearly always seen) lets one bad leg swing the velocity
  // by metres per second within a scan, so the prediction leaves the person. People walk with
  // accelerations of ~1-2 m/s² (σ 2 m/s²: variance 4), and the legs' midpoint is the body
  // centre only to a few cm over the gait cycle plus each circle's ~2 cm error (σ 5 cm).
  // Confirmed people only (tentative ones keep P3's: tentative_accel_var). Measured on
  // legs_crowd_10 and _moving (12 seeds each): MOTA 0.761 / 0.748 with P3's values throughout,
  // 0.795 / 0.774 with these; ID switches 255 / 336 -> 169 / 271.
  p.var_ax = p.var_ay = 4;
  p.sigma_xy = 0.05;
  // motion_heading_sigma stays off (0), though it helps the crowds' heading: on the simulated
  // crowds the velocity's direction alone was 17° off a fast walker's facing, the zoning 41°,
  // and with a 15° motion reading (confirmed people only) heading MAE fell 48° -> 37°
  // (legs_crowd_10 / _moving, 24 seeds each) with MOTA and ID switches within the seeds'
  // spread; but on leg_tracker's positive_4 bag it kept a confirmed track on furniture alive
  // for 227 scans instead of 34.
  p.max_turn_rate = 0;
  p.orientation_gate = 0;
  p.backward_walk_max = 0;
  // The heading hypotheses (heading_hypotheses.h) stay off: on the crowds (24 seeds each) they
  // lowered heading MAE 48.5° -> 35.0° (static) and 48.6° -> 36.3° (moving robot) but cost
  // MOTA (0.798 -> 0.787, 0.759 -> 0.755) and false positives (436 -> 690, 752 -> 1,052): in a
  // crowd the legs a person is given are often someone else's, and the pose, not the facing,
  // is what the association needs. The heading written is the direction of motion instead
  // (LegPeopleParams::report_heading_speed).
  p.heading.count = 0;
  // A crowd's global leg assignment swaps two legs far more often than anyone turns about
  // between two scans: a turn in place of over 90° is read as the legs swapped.
  p.zoning.resolve_swaps = true;
  return p;
}

struct LegPeopleParams {
  LegPoseParams pose = legPeoplePoseDefaults();
  double object_q = 4;         ///< m²/s³, CV noise of a lone object (a swinging leg: large)
  double object_sigma = 0.03;  ///< m, leg centre measurement noise
  double gate = 0.45;          ///< m, largest object-to-cluster distance of an association
  /// m, the gate of a standing confirmed person's legs (their centre moved less than 0.2 m over
  /// the last second), and of a tentative person standing 0.3 s where a person is expected
  /// (step's `expected`: the follow zone): a leg at rest does not jump 0.45 m within a scan; it is
  /// its detection that dropped while clutter beside the person was seen. On the outdoor following
  /// recording a standing followee's leg slid onto a bag or passing clutter 0.2-0.45 m away and
  /// dragged the track off (ID switches 6.1 -> 2.9, tracks on no one 0.63 -> 0.54 per scan, MOTP
  /// 0.104 -> 0.096 m; 0.15 lost the legs of a person starting to walk: misses 53 -> 74). 0: off.
  double standing_gate = 0.25;
  /// s: where the robot's motion is unknown, a person's velocity decays with this time constant
  /// before each prediction (and their acceleration is dropped): in the tracking frame it is
  /// theirs less the robot's, which changes as the robot turns. On the outdoor following
  /// recording a followee's estimate was carried 0.2 m a scan past them through scans that saw
  /// neither leg while the chair turned (8 runs, 0.5 % of returns dropped: MOTP 0.084 -> 0.068 m,
  /// misses 31.6 -> 24.9, ID switches 2.4 -> 0.75; without follow MOTP 0.102 -> 0.076 m). 0: off.
  double unknown_motion_tau = 0.1;
  double object_max_coast = 0.5;  ///< s, an object unseen this long is dropped
  /// Objects with a mean classifier score ≥ this are leg-like. The shipped leg models are
  /// Platt-calibrated on 1 leg per 19 non-legs, so 0.25 is already ~6× the prior odds.
  double leg_score = 0.25;
  /// A free object moving at init_speed or more is leg-like from this mean score on, and so is
  /// one where a confirmed person's missing leg is predicted (a leg of theirs seen this scan or
  /// within max_coast): on the simulated crowds, whose far legs score low, MOTA 0.819 -> 0.823
  /// static, 0.803 -> 0.809 moving (seeds 11-34); on leg_tracker's positive_3 bag a track
  /// follows a person 13 scans further, past the labels.
  double moving_leg_score = 0.05;
  double pair_distance = 0.7;   ///< m, two legs at most this far apart form a person
  double confirm_travel = 0.5;  ///< m, a tentative person that moved this far is confirmed
  /// m, a person whose legs score below leg_score is confirmed once it moved this far instead:
  /// about one step (0.7 m), on legs that scissored (confirm_stride). With 1 m the crowds'
  /// far walkers (2-3 returns a leg, SVM scores near 0.05) waited ~0.3 s longer: MOTA 0.800 /
  /// 0.777 instead of 0.809 / 0.783 (12 seeds each); negative_2 stays at 0 either way.
  double moving_confirm_travel = 0.7;
  /// A person whose legs' mean classifier score reaches sure_leg_score is confirmed after
  /// sure_confirm_travel (at most confirm_travel; legs that scissored still; the static-scene
  /// grid still keeps furniture out). The shipped models' 0.7 is ~44x the prior odds of a leg;
  /// on leg_tracker's labelled bags a person standing by the robot at the start was confirmed
  /// 12 s earlier (positive_4), and no furniture pair of negative_2 scored that high (with 0.5:
  /// 6 confirmed tracks there). The simulated crowds' legs score lower: unchanged.
  double sure_leg_score = 0.7;
  double sure_confirm_travel = 0.25;  ///< m, see sure_leg_score
  double max_confirm_speed = 2.0;     ///< m/s, no person is confirmed while estimated faster
  /// m, a walker's legs scissor: the sagittal part of the leg vector (along the person's motion,
  /// both legs seen) must have swung over at least this range before they are confirmed. Two
  /// objects that move rigidly together (a wall or chair slid by the robot's own motion, scans
  /// merged out of step) never do; one step of a walker swings it by ~0.5 m. 0: off.
  /// Where the robot's motion is unknown (scan matching found nothing to match, outdoors) a
  /// person's motion in the fixed frame is no evidence, and one who keeps pace with the robot
  /// moves nowhere in it: a tentative person whose legs' mean score reaches leg_score is then
  /// confirmed once the distance between their legs changed by this much within one second,
  /// which a rigid pair turned or slid by the robot never does, whatever the robot did. On
  /// leg_tracker's outdoor following recording (both legs seen, thigh height) that distance
  /// ranged over 0.14 m in the median second, over 0.10 m in 80 % of them.
  double confirm_stride = 0.1;
  /// The way a tentative person is seen to go while the robot turns faster than this
  /// does not count towards their confirmation (confirm_travel). A real scanner sweeps its
  /// scan over ~0.1 s while the robot turns, and matching such skewed scans (scan odometry) errs
  /// most in turns: furniture then slides through the fixed frame at a walker's pace. At 15
  /// deg/s a 0.1 s sweep already shifts a thing 4 m away by confirm_stride. On leg_tracker's
  /// negative_2 bag (a wheelchair driving and turning among furniture, no people; plain and 8
  /// fault seeds) 22 -> 4 confirmed tracks in all (20 deg/s: 13); simulated crowd from a robot
  /// turning in place at ~56 deg/s (no sweep skew in the simulator) MOTA -0.005 (seeds 11, 100,
  /// 200, 300); following dev bag unchanged. 0: off. Held in rad/s (the key is in deg/s).
  double max_travel_turn_rate = 15 * (M_PI / 180);
  double reacquire_spread =
      0.5;  ///< m/s, a confirmed person's missing-leg gate widens this fast while unseen
  double reacquire_max = 0.6;  ///< m, ... by at most this much
  /// m/s: a confirmed person lost from sight (neither leg tracked) takes back a new leg pair
  /// that forms within leg_gate plus this speed times the time unseen of where they were
  /// predicted, instead of the pair starting a new tentative person (a walker reappearing from
  /// behind someone keeps their id and needs no second confirmation); or a lone leg
  /// (reidentify_leg_scans). 0: off, both.
  double reidentify_speed = 1.0;
  double reidentify_max = 2.0;  ///< m, ... the radius grows by at most this much
  /// scans: a confirmed person with no leg left takes back a lone walking leg within that
  /// radius once the leg has been tracked this many scans (a walker coming out from behind
  /// others is often seen by one leg for many scans; a single leg never forms a pair). On the
  /// simulated crowds MOTA 0.823 / 0.809 -> 0.836 / 0.811 (seeds 11-34, static / moving
  /// robot), 0.825 / 0.818 -> 0.837 / 0.823 (seeds 100-123); 1 scan: 0.830 / 0.801, 5: 0.830 /
  /// 0.813, 8: 0.823 / 0.808. 0: off.
  int reidentify_leg_scans = 3;
  /// s: a confirmed person lost from sight (neither leg seen) coasts at the mean velocity of
  /// their centre over the last this long they were seen, when that is slower than their
  /// filter's. The pose filter follows each leg fit, and the last fits before an occlusion (a
  /// leg partly hidden by someone passing in front, two legs merging) often read a jump: coasting
  /// on it, a standing person's track drifted off at 0.5 m/s and took a passer-by's legs, and the
  /// person, who travels no distance, could not be confirmed again. Simulated crowds, mean of
  /// seeds 11, 100, 200, 300 (24 runs each): MOTA 0.859 -> 0.870 static, 0.819 -> 0.824 moving;
  /// ID switches 289 -> 249 and 456 -> 438. Tentative people too: 0.871 / 0.826, but leg_tracker's
  /// negative_2 bag then confirmed 3 tracks on furniture instead of 0 (and there 0.5 s or 2 s,
  /// or the window's velocity taken however fast, gained less). 0: off.
  double lost_velocity_window = 1.0;
  double max_coast = 3.0;  ///< s, a person with no leg seen this long is deleted (tentative)
  /// s, a confirmed person with no leg seen is deleted after as long as they had been seen
  /// while confirmed, at least max_coast and at most this. On the simulated crowds (seeds
  /// 11-34 / 100-123) MOTA 0.798 / 0.797 -> 0.819 / 0.812 static, 0.759 / 0.756 -> 0.803 /
  /// 0.815 from a moving robot: people who come back from behind others or from outside the
  /// field of view are re-identified (lostPersonNear) and need no second confirmation. A flat
  /// 8 s kept a short-lived confirmed track on furniture of leg_tracker's positive_4 bag alive
  /// until it took the person's legs (track rows near no labelled leg 153 -> 204); tying the
  /// wait to the time tracked does not (156).
  double max_coast_confirmed = 20.0;
  /// m, two people whose centres come closer than this are one (bodies do not interpenetrate):
  /// the tentative, else the one seen less recently, else the newer is deleted. Two confirmed
  /// people merge only when both are seen this scan (one coasting beside a seen one is most
  /// likely hidden by them). 0: off.
  double merge_distance = 0.3;
  double max_leg_spread = 1.0;  ///< m, a person whose legs drift farther apart loses one
  double flip_speed = 0.5;      ///< m/s, walking backwards faster than this turns the track
  double flip_time = 0.5;       ///< s, ... for this long
  double init_speed = 0.3;      ///< m/s, a new person's facing is their legs' motion above this
  /// (m/s)², σ²_ax = σ²_ay of a tentative person's pose filter (P3's 10²); pose.var_ax/var_ay
  /// apply once confirmed. Tracking its legs this closely, the filter shows a leg jumping to a
  /// neighbouring object as a speed no walker has, and a pair whose association hops along
  /// furniture as the robot drives past (negative_2.bag) does not pass for a smooth walk: with
  /// the confirmed people's noise from the start, negative_2 gave 5 confirmed ghosts instead of 0.
  double tentative_accel_var = 100;
  double tentative_sigma_xy = 0.03;  ///< m, σ_X = σ_Y of a tentative person (P3's)
  /// m/s: a person's reported heading is their direction of motion, the way their body centre
  /// moved over the last report_heading_window, whenever that is at least this fast (and at
  /// least this times the window, 0.15 m, for a person seen for less than the window: the first
  /// scans of a new or re-identified pose settle by a few cm); while slower, the last such
  /// direction (the pose estimator's orientation until they first move). In a crowd a person's
  /// legs are often hidden or someone else's, and the zoning reads those legs: on the simulated
  /// crowds (seeds 11-34, static / moving robot) heading MAE 49.4° / 49.2° with the pose
  /// estimator's orientation, 28.0° / 27.0° with this (0.5 m/s: 36.4° / 35.0°; 0.2 m/s: 26.9° /
  /// 26.4°, but a standing person's sway comes nearer). People walk forwards: one backing up or
  /// sidestepping faster than this is reported facing their way (leg_people's flip_speed already
  /// turns a backing person round). The pose estimator's orientation still predicts the legs.
  /// 0: off (the pose estimator's orientation throughout).
  double report_heading_speed = 0.3;
  /// s, see report_heading_speed. Over half a second the gait's sway averages out, and a walker
  /// stopping does not read as a step back (the filter's velocity overshoots, the way moved
  /// does not); over 1 s a turn shows late. Crowds: 0.3 s 28.4° / 27.9°, 1 s 34.8° / 33.9°.
  double report_heading_window = 0.5;
  /// m: a confirmed person's leg that no leg circle shows is still seen where scan returns
  /// that belong to no leg circle (one or two beams: a leg far away or all but hidden behind
  /// another; many that fit no circle: wide trousers close by) lie within this of where the
  /// gait predicts it (legFromReturns). On the simulated crowds (seeds
  /// 11, 100, 200, 300; 24 runs each) MOTA 0.826 -> 0.856 static, 0.804 -> 0.815 moving robot;
  /// 0.3 m: 0.858 / 0.813; 0.4 m: 0.856 / 0.804. 0: off.
  double support_gate = 0.25;
  /// s: a confirmed person held up this long by one leg object alone, standing (it stays
  /// within 0.1 m) on the static scene, is a track left on a pole or a table leg by a walker
  /// who passed it; the object is let go and never becomes a person's leg again. A person
  /// standing there is kept out of the static grid, so the place is static only if it was
  /// before they came. Simulated crowds (seeds 11-34 / 100-123, 24 runs each): moving robot
  /// MOTA 0.829 / 0.835 -> 0.835 / 0.837, false positives 1,841 / 2,158 -> 1,244 / 1,934;
  /// static scanner unchanged (0.879 / 0.878). 2 s: the same within 0.0005; 5 s: 0.833 /
  /// 0.835. Without the static-scene condition (any standing leg, 5 s) the static crowd lost
  /// 0.001 (people standing side-on). Most of those poles stood on the robot's loop, which the
  /// clutter of other seeds ignored; with them moved off it ([clutter] robot_clearance) the
  /// moving crowd's MOTA is the same with and without this, false positives 3,317 -> 3,064.
  /// On leg_tracker's positive_4 bag 241 -> 215 track rows near no labelled leg. The same
  /// holds, static scene or not, for a leg standing while the scanner moves 45 deg or more round
  /// it (a person would have shown their second leg), and then for one seen only in returns of
  /// no circle (support_gate): see checkOneLegStand. 0: off, both.
  double one_leg_stand = 3;
  /// s: a tentative person where a person is expected (step's `expected`: a following robot's
  /// zone in front of it) is confirmed once both legs were seen, looking like legs, over this
  /// long. The person a robot is asked to follow stands in front of it before walking off, and
  /// where scan matching finds nothing to match (outdoors) the robot cannot tell a person who
  /// walks with it from one who stands. 0: off.
  double follow_confirm_time = 0.5;
  /// s: a confirmed person unseen while something nearer the scanner hides where they are
  /// predicted (a pillar, a passer-by) is kept this long at most, however briefly they had been
  /// tracked; time unseen in plain view still counts towards max_coast / max_coast_confirmed.
  /// Their absence is explained, and a person who waits behind a pillar comes back on their
  /// track (re-identification). 0: off.
  double max_coast_occluded = 30;
  /// s: a confirmed person not seen by both legs for this long is deleted, counting only time
  /// nothing nearer explains: scans with one leg seen and the other's predicted place in plain
  /// view (no nearer return hiding it), and the gaps between sightings with the person's place
  /// in plain view, each up to max_coast (a person lost long and found again by one leg is
  /// re-identification's case). A person's legs are seen
  /// together again within seconds unless one hides the other; a track that lives on single
  /// sightings is most often one that slid off its person onto clutter. On the outdoor following
  /// recording one such track hopped from clutter to clutter for 180 s (seen by one "leg" in 10 %
  /// of the scans, by two in 0.6 %): tracks on no one 0.54 -> 0.29 per scan (5 s: 0.23, 20 s:
  /// 0.41). 0: off.
  double max_one_leg = 10;
};

/// A scan return that is part of no leg circle: fixed-frame position and the sensor seeing it.
struct LegReturn {
  Eigen::Vector2d p;
  Eigen::Vector2d sensor = Eigen::Vector2d::Zero();
};

/// A leg detection this scan: position (fixed frame), classifier score, the sensor seeing it.
struct LegDetection {
  Eigen::Vector2d p;
  double score = 1;
  Eigen::Vector2d sensor = Eigen::Vector2d::Zero();
  int cluster = -1;
  bool scored = true;  ///< a classifier gave the score (false: none ran, score is 1)
};

/// A person as reported.
struct PersonState {
  long id = 0;
  bool confirmed = false;
  bool seen = false;  ///< a leg of theirs was associated this scan
  double unseen = 0;  ///< s since a leg of theirs was last seen
  /// Unseen longer than max_coast: a confirmed person kept only for re-identification
  /// (max_coast_confirmed), not written, followed or kept out of scan matching.
  bool lost = false;
  Eigen::Vector2d p, v;
  double yaw = 0;  ///< reported heading (report_heading_speed)
  Eigen::Matrix2d cov;
  double score = 0;  ///< mean leg-classifier score
  MotionZone zone = MotionZone::GoStraight;
  int cluster = -1;  ///< a cluster of theirs this scan, -1 none
};

class LegPeopleTracker {
 public:
  explicit LegPeopleTracker(const LegPeopleParams& p);
  ~LegPeopleTracker();

  /// One scan at time t. `is_static(x, y)` (may be empty) says whether a fixed-frame point lies
  /// in the static scene, where no person may start.
  /// `returns`: the scan's returns that are part of no leg circle (support_gate).
  /// `motion_known` false: the robot may have moved by an unknown amount up to this scan
  /// (Frame::motion_unknown), so the way a person moved in the fixed frame says nothing; a
  /// tentative person is then confirmed on their gait alone (confirm_stride).
  /// `expected(x, y)` (may be empty): whether a fixed-frame place is where a person is expected,
  /// the zone in front of a robot asked to follow someone; a tentative person there whose legs
  /// look like legs (mean score ≥ leg_score) and were both seen over follow_confirm_time is
  /// confirmed without walking (the person about to be followed stands in front of the robot).
  /// `occluded(x, y, half_width)` (may be empty): whether something nearer the scanner lies
  /// within half_width (m) of the ray to a fixed-frame place this scan, hiding a thing that wide
  /// there (a body: max_coast_occluded; a leg: max_one_leg).
  /// `turn_rate`: how fast the robot turned (rad/s, absolute) since the last scan, by the
  /// frame's pose (max_travel_turn_rate).
  void step(double t, const std::vector<LegDetection>& legs,
            const std::function<bool(double, double)>& is_static,
            const std::vector<LegReturn>& returns = {}, bool motion_known = true,
            const std::function<bool(double, double)>& expected = {},
            const std::function<bool(double, double, double)>& occluded = {}, double turn_rate = 0);

  std::vector<PersonState> people() const;
  /// Fixed-frame positions of every confirmed person seen within max_coast, and their legs:
  /// what a static-scene map must not absorb (a person standing still for minutes).
  std::vector<Eigen::Vector2d> occupiedByPeople() const;
  std::size_t objectCount() const;
  /// The person a following robot follows (0: none; the stage's `follow`), from the last scan.
  void setFollowed(long id) { followed_ = id; }

 private:
  struct Object;
  struct Person;
  bool legLike(const Object& o) const;
  double coastLimit(const Person& q) const;
  /// q is deleted: merged or on the static scene, or unseen too long (coastLimit, counting time
  /// hidden behind something nearer only up to max_coast_occluded).
  bool expired(const Person& q, double t) const;
  bool lostLong(const Person& q, double t) const;
  Person* personById(long id) const;
  /// q seen at c: the reported heading (report_heading_speed), then c recorded.
  void recordCentre(Person& q, double t, const Eigen::Vector2d& c) const;
  /// The scan q is lost: they coast at their recent mean velocity when that is slower
  /// (lost_velocity_window).
  void updateLostVelocity(Person& q) const;
  void associate(double t, const std::vector<LegDetection>& legs);
  void checkOneLegStand(Person& P, double t, const std::vector<LegDetection>& legs,
                        const Eigen::Vector2d& sensor, LegSeen& l, LegSeen& r,
                        const std::function<bool(double, double)>& is_static);
  void updatePeople(double t, const std::vector<LegDetection>& legs,
                    const std::function<bool(double, double)>& is_static,
                    const std::vector<LegReturn>& returns);
  std::optional<LegSeen> legFromReturns(const Person& q, double t, const Eigen::Vector2d& want,
                                        const Eigen::Vector2d& other,
                                        const std::function<bool(double, double)>& is_static,
                                        const std::vector<LegReturn>& returns,
                                        Eigen::Vector2d& sensor) const;
  double adoptGate(const Person& P, double t) const;
  bool takesFollowedClaim(const Person& P) const;
  static bool wantsLeg(long slot, const Object* held, bool followed);
  bool mayAdopt(const Object& o, bool predicted, bool followed,
                const std::function<bool(double, double)>& is_static) const;
  std::unordered_map<long, double> nearestClaims(
      double t, const std::function<bool(double, double)>& is_static) const;
  double reidentifyRadius(const Person& q, double t) const;
  int legsSeen(const Person& q) const;
  double lostDistance(const Person& q, double t, const Eigen::Vector2d& p) const;
  Person* lostPersonNear(double t, const Eigen::Vector2d& p);
  Object* reidentifyByOneLeg(Person& q, double t,
                             const std::function<bool(double, double)>& is_static);
  void formPeople(double t, const std::vector<LegDetection>& legs,
                  const std::function<bool(double, double)>& is_static);

  LegPeopleParams p_;
  ConstantVelocity object_model_;
  std::vector<std::unique_ptr<Object>> objects_;
  std::vector<std::unique_ptr<Person>> people_;
  long next_object_ = 0, next_person_ = 0;
  double t_ = 0;
  bool started_ = false;
  bool classified_ = false;    // some leg so far was scored by a classifier (sure_leg_score)
  bool motion_known_ = true;   // this scan's: see step()
  bool turning_fast_ = false;  // this scan's: the robot turns faster than max_travel_turn_rate
  // Where the robot's motion is unknown, the followed person (setFollowed) has the first claim
  // on legs where their gait predicts them: a leg object of theirs unseen this scan gives way to
  // a seen one there, and a tentative person's leg there becomes theirs. The frame then moves by
  // an unknown amount, an unseen leg object drifts off on a velocity that is partly the robot's,
  // and new people form on the followee's own legs: on the outdoor following recording a
  // tentative person took the followee's far leg, who then coasted on one leg and eq. 6's
  // inferred one, 0.3 m off. Where the motion is known the legs' predictions hold and a
  // tentative person beside the followee is most often a passer-by (the rule there cost
  // simulated following 0.003 MOTA); for everyone, not just the followee, it cost static crowds
  // 0.003-0.012 MOTA (new people confirmed later).
  long followed_ = 0;
  std::function<bool(double, double)> expected_;          // this scan's: see step()
  std::function<bool(double, double, double)> occluded_;  // this scan's: see step()
};

}  // namespace pedtrack::track
