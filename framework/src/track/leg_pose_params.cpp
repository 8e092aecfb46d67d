#include "pedtrack/track/leg_pose_params.h"

#include <cmath>

#include "pedtrack/errors.h"

namespace pedtrack::track {

std::vector<ParamSpec> legPoseParamSpecs(const LegPoseParams& d) {
  const double deg = 180 / M_PI;
  return {
      ParamSpec::vector("accel_var", std::vector<double>{d.var_ax, d.var_ay, d.var_atheta}, "", 3,
                        1e-9, 1e9,
                        "variances of the X, Y, theta accelerations' white noise, (m/s2)2 and "
                        "(rad/s2)2 (P3 eq. 4: 10^2, 10^2, pi^2)"),
      ParamSpec::real("sigma_xy", d.sigma_xy, "m", 1e-6, 10,
                      "std. dev. of the legs' midpoint measurement (P3 eq. 5: 0.03)"),
      ParamSpec::real("sigma_theta", d.sigma_theta * deg, "deg", 1e-3, 180,
                      "std. dev. of the zoning's orientation measurement (P3 eq. 5: pi/15 = 12)"),
      ParamSpec::real("inferred_sigma_scale", d.inferred_sigma_scale, "", 1, 1000,
                      "measurement std. dev. factor when one leg was inferred (hidden)"),
      ParamSpec::boolean("occlusion", d.occlusion,
                         "P3 eq. 6-7: a hidden leg is attracted to the area behind the visible "
                         "one; false: the gait prediction alone"),
      ParamSpec::real("w0_default", d.w0_default, "m", 0.01, 1,
                      "step width W0 used until one is learned"),
      ParamSpec::real("w0_time", d.w0_time, "s", 0, 600,
                      "W0 is the mean frontal leg distance over the track's first seconds"),
      ParamSpec::real("leg_gate", d.leg_gate, "m", 0.01, 5,
                      "legs farther than this from both predicted legs are not the person's"),
      ParamSpec::integer("gait_frames", d.gait_frames, "frames", 5, 1000,
                         "N of eq. 3: the gait model's window (P3: 20, one gait cycle)"),
      ParamSpec::real("coast_tau", d.coast_tau, "s", 0, 3600,
                      "with neither leg seen the velocity decays with this time constant "
                      "(people stop and turn when out of sight; 0: velocity held)"),
      ParamSpec::real("max_turn_rate", d.max_turn_rate * deg, "deg/s", 0, 1e5,
                      "the turn rate state is held within +/- this (a quick pivot: 180 deg in "
                      "0.6 s; 0: unbounded, P3's model)"),
      ParamSpec::real("orientation_gate", d.orientation_gate, "sigma", 0, 1000,
                      "an orientation reading farther than this many std. devs. from the "
                      "prediction is down-weighted to this distance (robust update; 0: off)"),
      ParamSpec::real("backward_walk_max", d.backward_walk_max, "m", 0, 1000,
                      "facing check: a person who walks backward further than this (less after "
                      "a doubtful orientation reading) is turned round to face the way they walk; "
                      "0: off"),
      ParamSpec::real("mirror_margin", d.mirror_margin, "m", 0, 1000,
                      "facing check: backward walking beyond this after a doubtful reading "
                      "turns the estimate round"),
      ParamSpec::real("mirror_min_speed", d.mirror_min_speed, "m/s", 0, 100,
                      "facing check: slower motion is no evidence of the facing"),
      ParamSpec::real("motion_heading_sigma", d.motion_heading_sigma * 180 / M_PI, "deg", 0, 180,
                      "at motion_heading_speed or faster the velocity's direction is also an "
                      "orientation reading with this std. dev. (people walk forward; a side step "
                      "it misreads; 0: off, P3's model)"),
      ParamSpec::real("motion_heading_speed", d.motion_heading_speed, "m/s", 0, 100,
                      "see motion_heading_sigma"),
      ParamSpec::choice("gait_solver", "varpro", {"varpro", "ipopt"},
                        "eq. 3's solver: varpro (global in f, microseconds) or ipopt (local, "
                        "from the previous fit; P3 used a local method, COBYLA)"),
      ParamSpec::vector("gait_bounds",
                        std::vector<double>{d.gait.l0_min, d.gait.l0_max, d.gait.f_min,
                                            d.gait.f_max, d.gait.b_min, d.gait.b_max},
                        "", 6, -10, 10,
                        "L0 min max (m), f min max (Hz), b min max (m) of eq. 3 (P3: 0.1 0.5 0.5 "
                        "1.5 0 0.5)"),
      ParamSpec::real("width_tolerance", d.zoning.width_tolerance, "", 0, 10,
                      "go-straight zone: frontal leg distance within W0 +/- this fraction of W0"),
      ParamSpec::real("sideways_tolerance", d.zoning.sideways_tolerance, "", 0, 10,
                      "move-sideways zone: legs apart beyond the band with the sagittal leg "
                      "distance within this fraction of W0"),
      ParamSpec::boolean("refine_straight", d.zoning.refine_straight,
                         "measure small turns inside the go-straight band when the legs are apart "
                         "sagittally (ours); false: P3's constant orientation there"),
      ParamSpec::real("slight_turn_max", d.zoning.slight_turn_max * deg, "deg", 0, 180,
                      "larger orientation changes are turn-in-place (sagittal axis "
                      "perpendicular to the legs)"),
      ParamSpec::integer("heading_hypotheses", d.heading.count, "", 0, 256,
                         "hypotheses of the heading kept over scans (ours): each leg pair allows "
                         "two headings (either leg ahead) and a side step; 0: P3's zoning, one "
                         "reading per scan"),
      ParamSpec::real("heading_gate", d.heading.gate, "sigma", 0.5, 100,
                      "hypotheses: a reading farther than this from a hypothesis spawns no child"),
      ParamSpec::real("heading_sigma_leg", d.heading.sigma_leg, "m", 1e-4, 1,
                      "hypotheses: one leg circle's position error, from which each reading's "
                      "spread follows"),
      ParamSpec::real("heading_occluded_sigma_leg", d.heading.occluded_sigma_leg, "m", 0, 1,
                      "hypotheses: the same for a leg circle partly hidden by something nearer "
                      "beside it (leg_pose's occluded_width); 0: heading_sigma_leg"),
      ParamSpec::real("heading_sigma_floor", d.heading.sigma_floor * deg, "deg", 0.1, 180,
                      "hypotheses: no reading is taken as sharper than this; also the softness "
                      "of a hidden leg's bound"),
      ParamSpec::real("heading_turn_tau", d.heading.turn_tau, "s", 0, 3600,
                      "hypotheses: the turn rate reverts to zero with this time constant (people "
                      "turn in bursts; 0: P3's constant acceleration)"),
      ParamSpec::real("heading_hidden_turn_tau", d.heading.hidden_turn_tau, "s", 0, 3600,
                      "hypotheses: on a scan where a leg is hidden (a bound only, which cannot "
                      "show a turn ending) the turn rate also reverts to zero with this time "
                      "constant (0: off)"),
      ParamSpec::real("heading_stop_turn", d.heading.stop_turn_prior, "", 0, 0.5,
                      "hypotheses: chance per scan that a turn ends (a child with the turn rate "
                      "zeroed)"),
      ParamSpec::real("heading_start_turn", d.heading.start_turn_prior, "", 0, 0.5,
                      "hypotheses: chance per scan that a turn starts (a child whose turn rate "
                      "may take any value up to ~150 deg/s at once)"),
      ParamSpec::real("heading_rate_sigma_max", d.heading.rate_sigma_max * deg, "deg/s", 0, 1e5,
                      "hypotheses: unseen, the turn rate's std. dev. grows no further than this "
                      "(0: unbounded)"),
      ParamSpec::real("heading_hidden_spread", d.heading.hidden_spread * deg, "deg", 1, 90,
                      "hypotheses: a hidden leg bounds the heading to the scanner ray's "
                      "perpendicular +/- this"),
      ParamSpec::real("heading_mode_switch", d.heading.mode_switch, "", 0, 0.5,
                      "hypotheses: chance per scan of starting or ending a backward walk"),
      ParamSpec::real("heading_backward_per_metre", d.heading.backward_per_metre, "1/m", 0, 100,
                      "hypotheses: evidence (nats) against each metre walked backward"),
      ParamSpec::real("heading_motion_speed", d.heading.motion_speed, "m/s", 0, 100,
                      "hypotheses: at this speed or faster the motion's direction weighs them"),
      ParamSpec::real("heading_motion_sigma", d.heading.motion_sigma * deg, "deg", 1, 180,
                      "hypotheses: spread of the motion's direction about forward, backward "
                      "or sideways"),
      ParamSpec::real("heading_walk_weight", d.heading.walk_weight, "", 0, 1,
                      "hypotheses: share of walking scans whose motion is along the sagittal "
                      "axis (forward or backward)"),
      ParamSpec::real("heading_sideways_weight", d.heading.sideways_weight, "", 0, 1,
                      "hypotheses: share of side-step scans in which the motion is sideways"),
      ParamSpec::real("heading_still_sideways", d.heading.still_sideways_prior, "", 1e-6, 1,
                      "hypotheses: likelihood factor of a side step read while the person is "
                      "slower than heading_motion_speed"),
      ParamSpec::real("heading_label_swap", d.heading.label_swap, "", 0, 1,
                      "hypotheses: chance per scan that the legs' names (kept by nearest "
                      "neighbour to where each leg was last seen) were exchanged; 0 or 1: the "
                      "names are no evidence"),
      ParamSpec::real("heading_label_swap_hidden", d.heading.label_swap_hidden, "", 0, 1,
                      "hypotheses: the same on a scan where a leg goes hidden or comes back"),
  };
}

LegPoseParams readLegPoseParams(const ParamSet& s) {
  LegPoseParams p;
  const double rad = M_PI / 180;
  const std::vector<double> a = s.getVector("accel_var");
  p.var_ax = a[0], p.var_ay = a[1], p.var_atheta = a[2];
  p.sigma_xy = s.getDouble("sigma_xy");
  p.sigma_theta = s.getDouble("sigma_theta") * rad;
  p.inferred_sigma_scale = s.getDouble("inferred_sigma_scale");
  p.occlusion = s.getBool("occlusion");
  p.w0_default = s.getDouble("w0_default");
  p.w0_time = s.getDouble("w0_time");
  p.leg_gate = s.getDouble("leg_gate");
  p.gait_frames = int(s.getInt("gait_frames"));
  p.coast_tau = s.getDouble("coast_tau");
  p.max_turn_rate = s.getDouble("max_turn_rate") * rad;
  p.orientation_gate = s.getDouble("orientation_gate");
  p.backward_walk_max = s.getDouble("backward_walk_max");
  p.mirror_margin = s.getDouble("mirror_margin");
  p.mirror_min_speed = s.getDouble("mirror_min_speed");
  p.motion_heading_sigma = s.getDouble("motion_heading_sigma") * rad;
  p.motion_heading_speed = s.getDouble("motion_heading_speed");
  const std::vector<double> b = s.getVector("gait_bounds");
  p.gait = {b[0], b[1], b[2], b[3], b[4], b[5]};
  if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5] && b[2] > 0))
    throw ConfigError(s.where("gait_bounds") +
                      ": each min must not exceed its max and f_min must be positive");
  p.zoning.width_tolerance = s.getDouble("width_tolerance");
  p.zoning.sideways_tolerance = s.getDouble("sideways_tolerance");
  p.zoning.refine_straight = s.getBool("refine_straight");
  p.zoning.slight_turn_max = s.getDouble("slight_turn_max") * rad;
  p.heading.count = int(s.getInt("heading_hypotheses"));
  p.heading.gate = s.getDouble("heading_gate");
  p.heading.sigma_leg = s.getDouble("heading_sigma_leg");
  p.heading.occluded_sigma_leg = s.getDouble("heading_occluded_sigma_leg");
  p.heading.sigma_floor = s.getDouble("heading_sigma_floor") * rad;
  p.heading.motion_speed = s.getDouble("heading_motion_speed");
  p.heading.turn_tau = s.getDouble("heading_turn_tau");
  p.heading.hidden_turn_tau = s.getDouble("heading_hidden_turn_tau");
  p.heading.stop_turn_prior = s.getDouble("heading_stop_turn");
  p.heading.start_turn_prior = s.getDouble("heading_start_turn");
  p.heading.rate_sigma_max = s.getDouble("heading_rate_sigma_max") * rad;
  p.heading.hidden_spread = s.getDouble("heading_hidden_spread") * rad;
  p.heading.mode_switch = s.getDouble("heading_mode_switch");
  p.heading.backward_per_metre = s.getDouble("heading_backward_per_metre");
  p.heading.motion_sigma = s.getDouble("heading_motion_sigma") * rad;
  p.heading.walk_weight = s.getDouble("heading_walk_weight");
  p.heading.sideways_weight = s.getDouble("heading_sideways_weight");
  p.heading.still_sideways_prior = s.getDouble("heading_still_sideways");
  p.heading.label_swap = s.getDouble("heading_label_swap");
  p.heading.label_swap_hidden = s.getDouble("heading_label_swap_hidden");
  return p;
}

}  // namespace pedtrack::track
