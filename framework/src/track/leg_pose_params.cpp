// The parameters of P3's leg-pair pose estimator, declared once for every plugin that runs it
// (leg_pose, leg_people); each plugin's own defaults come from the LegPoseParams it holds.
#include "pedtrack/track/leg_pose_params.h"

#include <cmath>
#include <string>

namespace pedtrack::track {

const ParamTable<LegPoseParams>& legPoseTable() {
  using P = LegPoseParams;
  using B = gait::Bounds;
  static const auto t =
      ParamTable<P>()
          .vector(fields(&P::var_ax, &P::var_ay, &P::var_atheta), "accel_var", "", 3, 1e-9, 1e9,
                  "variances of the X, Y, theta accelerations' white noise, (m/s2)2 and (rad/s2)2 "
                  "(P3 eq. 4: "
                  "10^2, 10^2, pi^2)")
          .real(&P::sigma_xy, "sigma_xy", "m", 1e-6, 10,
                "std. dev. of the legs' midpoint measurement (P3 eq. 5: 0.03)")
          .real(&P::sigma_theta, "sigma_theta", "deg", 1e-3, 180,
                "std. dev. of the zoning's orientation measurement (P3 eq. 5: pi/15 = 12)", kDegree)
          .real(&P::inferred_sigma_scale, "inferred_sigma_scale", "", 1, 1000,
                "measurement std. dev. factor when one leg was inferred (hidden)")
          .boolean(&P::occlusion, "occlusion",
                   "P3 eq. 6-7: a hidden leg is attracted to the area behind the visible "
                   "one; false: the gait prediction alone")
          .real(&P::w0_default, "w0_default", "m", 0.01, 1,
                "step width W0 used until one is learned")
          .real(&P::w0_time, "w0_time", "s", 0, 600,
                "W0 is the mean frontal leg distance over the track's first seconds")
          .real(&P::leg_gate, "leg_gate", "m", 0.01, 5,
                "legs farther than this from both predicted legs are not the person's")
          .integer(&P::gait_frames, "gait_frames", "frames", 5, 1000,
                   "N of eq. 3: the gait model's window (P3: 20, one gait cycle)")
          .real(&P::coast_tau, "coast_tau", "s", 0, 3600,
                "with neither leg seen the velocity decays with this time constant "
                "(people stop and turn when out of sight; 0: velocity held)")
          .real(&P::max_turn_rate, "max_turn_rate", "deg/s", 0, 1e5,
                "the turn rate state is held within +/- this (a quick pivot: 180 deg in "
                "0.6 s; 0: unbounded, P3's model)",
                kDegree)
          .real(&P::orientation_gate, "orientation_gate", "sigma", 0, 1000,
                "an orientation reading farther than this many std. devs. from the "
                "prediction is down-weighted to this distance (robust update; 0: off)")
          .real(&P::backward_walk_max, "backward_walk_max", "m", 0, 1000,
                "facing check: a person who walks backward further than this (less after "
                "a doubtful orientation reading) is turned round to face the way they walk; "
                "0: off")
          .real(&P::mirror_margin, "mirror_margin", "m", 0, 1000,
                "facing check: backward walking beyond this after a doubtful reading "
                "turns the estimate round")
          .real(&P::mirror_min_speed, "mirror_min_speed", "m/s", 0, 100,
                "facing check: slower motion is no evidence of the facing")
          .real(&P::motion_heading_sigma, "motion_heading_sigma", "deg", 0, 180,
                "at motion_heading_speed or faster the velocity's direction is also an "
                "orientation reading with this std. dev. (people walk forward; a side step "
                "it misreads; 0: off, P3's model)",
                kDegree)
          .real(&P::motion_heading_speed, "motion_heading_speed", "m/s", 0, 100,
                "see motion_heading_sigma")
          .choice(&P::solver, "gait_solver",
                  {{"varpro", LegPoseParams::GaitSolver::VarPro},
                   {"ipopt", LegPoseParams::GaitSolver::Ipopt}},
                  "eq. 3's solver: varpro (global in f, microseconds) or ipopt (local, from the "
                  "previous fit; "
                  "P3 used a local method, COBYLA)")
          .vector(
              fields(path(&P::gait, &B::l0_min), path(&P::gait, &B::l0_max),
                     path(&P::gait, &B::f_min), path(&P::gait, &B::f_max),
                     path(&P::gait, &B::b_min), path(&P::gait, &B::b_max)),
              "gait_bounds", "", 6, -10, 10,
              "L0 min max (m), f min max (Hz), b min max (m) of eq. 3 (P3: 0.1 0.5 0.5 1.5 0 0.5)")
          .real(path(&P::zoning, &ZoningParams::width_tolerance), "width_tolerance", "", 0, 10,
                "go-straight zone: frontal leg distance within W0 +/- this fraction of W0")
          .real(path(&P::zoning, &ZoningParams::sideways_tolerance), "sideways_tolerance", "", 0,
                10,
                "move-sideways zone: legs apart beyond the band with the sagittal leg "
                "distance within this fraction of W0")
          .boolean(path(&P::zoning, &ZoningParams::refine_straight), "refine_straight",
                   "measure small turns inside the go-straight band when the legs are apart "
                   "sagittally (ours); false: P3's constant orientation there")
          .real(path(&P::zoning, &ZoningParams::slight_turn_max), "slight_turn_max", "deg", 0, 180,
                "larger orientation changes are turn-in-place (sagittal axis "
                "perpendicular to the legs)",
                kDegree)
          .integer(path(&P::heading, &HeadingHypothesesParams::count), "heading_hypotheses", "", 0,
                   256,
                   "hypotheses of the heading kept over scans (ours): each leg pair allows "
                   "two headings (either leg ahead) and a side step; 0: P3's zoning, one "
                   "reading per scan")
          .real(path(&P::heading, &HeadingHypothesesParams::gate), "heading_gate", "sigma", 0.5,
                100, "hypotheses: a reading farther than this from a hypothesis spawns no child")
          .real(path(&P::heading, &HeadingHypothesesParams::sigma_leg), "heading_sigma_leg", "m",
                1e-4, 1,
                "hypotheses: one leg circle's position error, from which each reading's "
                "spread follows")
          .real(path(&P::heading, &HeadingHypothesesParams::occluded_sigma_leg),
                "heading_occluded_sigma_leg", "m", 0, 1,
                "hypotheses: the same for a leg circle partly hidden by something nearer "
                "beside it (leg_pose's occluded_width); 0: heading_sigma_leg")
          .real(path(&P::heading, &HeadingHypothesesParams::sigma_floor), "heading_sigma_floor",
                "deg", 0.1, 180,
                "hypotheses: no reading is taken as sharper than this; also the softness "
                "of a hidden leg's bound",
                kDegree)
          .real(path(&P::heading, &HeadingHypothesesParams::turn_tau), "heading_turn_tau", "s", 0,
                3600,
                "hypotheses: the turn rate reverts to zero with this time constant (people "
                "turn in bursts; 0: P3's constant acceleration)")
          .real(path(&P::heading, &HeadingHypothesesParams::hidden_turn_tau),
                "heading_hidden_turn_tau", "s", 0, 3600,
                "hypotheses: on a scan where a leg is hidden (a bound only, which cannot "
                "show a turn ending) the turn rate also reverts to zero with this time "
                "constant (0: off)")
          .real(path(&P::heading, &HeadingHypothesesParams::stop_turn_prior), "heading_stop_turn",
                "", 0, 0.5,
                "hypotheses: chance per scan that a turn ends (a child with the turn rate "
                "zeroed)")
          .real(path(&P::heading, &HeadingHypothesesParams::start_turn_prior), "heading_start_turn",
                "", 0, 0.5,
                "hypotheses: chance per scan that a turn starts (a child whose turn rate "
                "may take any value up to ~150 deg/s at once)")
          .real(path(&P::heading, &HeadingHypothesesParams::rate_sigma_max),
                "heading_rate_sigma_max", "deg/s", 0, 1e5,
                "hypotheses: unseen, the turn rate's std. dev. grows no further than this "
                "(0: unbounded)",
                kDegree)
          .real(path(&P::heading, &HeadingHypothesesParams::hidden_spread), "heading_hidden_spread",
                "deg", 1, 90,
                "hypotheses: a hidden leg bounds the heading to the scanner ray's "
                "perpendicular +/- this",
                kDegree)
          .real(path(&P::heading, &HeadingHypothesesParams::mode_switch), "heading_mode_switch", "",
                0, 0.5, "hypotheses: chance per scan of starting or ending a backward walk")
          .real(path(&P::heading, &HeadingHypothesesParams::backward_per_metre),
                "heading_backward_per_metre", "1/m", 0, 100,
                "hypotheses: evidence (nats) against each metre walked backward")
          .real(path(&P::heading, &HeadingHypothesesParams::motion_speed), "heading_motion_speed",
                "m/s", 0, 100,
                "hypotheses: at this speed or faster the motion's direction weighs them")
          .real(path(&P::heading, &HeadingHypothesesParams::motion_sigma), "heading_motion_sigma",
                "deg", 1, 180,
                "hypotheses: spread of the motion's direction about forward, backward "
                "or sideways",
                kDegree)
          .real(path(&P::heading, &HeadingHypothesesParams::walk_weight), "heading_walk_weight", "",
                0, 1,
                "hypotheses: share of walking scans whose motion is along the sagittal "
                "axis (forward or backward)")
          .real(path(&P::heading, &HeadingHypothesesParams::sideways_weight),
                "heading_sideways_weight", "", 0, 1,
                "hypotheses: share of side-step scans in which the motion is sideways")
          .real(path(&P::heading, &HeadingHypothesesParams::still_sideways_prior),
                "heading_still_sideways", "", 1e-6, 1,
                "hypotheses: likelihood factor of a side step read while the person is "
                "slower than heading_motion_speed")
          .real(path(&P::heading, &HeadingHypothesesParams::label_swap), "heading_label_swap", "",
                0, 1,
                "hypotheses: chance per scan that the legs' names (kept by nearest "
                "neighbour to where each leg was last seen) were exchanged; 0 or 1: the "
                "names are no evidence")
          .real(path(&P::heading, &HeadingHypothesesParams::label_swap_hidden),
                "heading_label_swap_hidden", "", 0, 1,
                "hypotheses: the same on a scan where a leg goes hidden or comes back")
          .check(fields(path(&P::gait, &B::l0_min)), [](const P& p) {
            const B& b = p.gait;
            return b.l0_min <= b.l0_max && b.f_min <= b.f_max && b.b_min <= b.b_max && b.f_min > 0
                       ? std::string()
                       : "each min must not exceed its max and f_min must be positive";
          });
  return t;
}

}  // namespace pedtrack::track
