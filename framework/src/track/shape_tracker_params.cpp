// The parameters of the shape trackers, declared once for imm_shape, kf_bb, kf_circle and
// mhe_mlesac: the keys every one has, and one group per observation model.
#include <cmath>
#include <string>

#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::track {
namespace {

using P = ShapeTrackerParams;

// "must not exceed X (value)" when a > b.
std::string notAbove(double a, double b, const char* b_name) {
  return a > b ? "must not exceed " + std::string(b_name) + " (" + shortestNumber(b) + ")"
               : std::string();
}

}  // namespace

const ParamTable<ShapeTrackerParams>& ShapeTracker::commonTable() {
  static const auto t =
      ParamTable<P>()
          .real(&P::q_person, "q_person", "", 0, 1,
                "a detection scoring at least this starts a track (classifier score Q)")
          .real(&P::q_min, "q_min", "", 0, 1,
                "an existing track also takes detections scoring above this (hysteresis)")
          .real(&P::gate, "gate", "m", 0.01, 20,
                "largest distance between a track's prediction and a cluster (Hungarian)")
          .real(&P::tentative_penalty, "tentative_penalty", "m", 0, 20,
                "ours: added to a tentative track's association cost, so a confirmed track keeps "
                "its person's cluster unless a tentative one is this much nearer (0: off, P1)")
          .integer(&P::confirm_hits, "confirm_hits", "", 1, 32,
                   "M of M-of-N: associations that confirm a track")
          .integer(&P::confirm_window, "confirm_window", "", 1, 32,
                   "N of M-of-N: a new track's first scans that must hold M associations")
          .integer(&P::max_misses, "max_misses", "", 0, 10000,
                   "the scan that makes this many misses in a row deletes a confirmed track")
          .real(&P::confirm_evidence, "confirm_evidence", "", 0, 100,
                "> 0: confirm a track by accumulated classifier evidence instead of M-of-N: the "
                "sum over its scans of logit(score) (within +-3) and evidence_miss per missed "
                "scan must reach this; at -confirm_evidence / 2, or after confirm_window - "
                "confirm_hits + 1 misses in a row, a tentative track is deleted; 0: M-of-N (P1)")
          .real(&P::evidence_miss, "evidence_miss", "", -100, 0,
                "log-odds a missed scan adds to a tentative track's evidence")
          .vector(&P::q_rates, "q", "unit^2/s", 6, 0, 1e6,
                  "process noise rates of [x, y, theta, v, alpha, beta] (P1 Table I per 0.1 s "
                  "frame x 10)")
          .real(&P::fit_min_height, "fit_min_height", "m", -10, 10,
                "lowest point height the shapes are fitted to (P0: legs below 0.6 m dropped)")
          .real(&P::fit_max_height, "fit_max_height", "m", -10, 10,
                "highest point height the shapes are fitted to")
          .real(&P::init_speed_sigma, "init_speed_sigma", "m/s", 0.01, 10,
                "speed uncertainty of a new track (its facing direction is unknown)")
          .integer(&P::birth_points, "birth_points", "", 1, 100000,
                   "points in the fit band a cluster needs to start a track (N_b: a shape can be "
                   "fitted)")
          .real(&P::small_birth_score, "small_birth_score", "", 0, 1,
                "ours: a cluster with fewer fit-band points than birth_points (far away, mostly "
                "hidden) also starts a track when it scores at least this and no confirmed track "
                "is within gate; a track fed only by such clusters never keeps the static grid "
                "from learning its returns (0: never, P1)")
          .real(&P::flip_speed, "flip_speed", "m/s", 0, 10,
                "a track moving against its heading faster than this is turned round (the "
                "shapes give the heading modulo 180 deg)")
          .integer(&P::seed, "seed", "", 0, 4294967295.0, "seed of the RANSAC sampling")
          .boolean(&P::report_tentative, "report_tentative",
                   "also write tracks not yet confirmed to tracks.csv (status tentative)")
          .boolean(&P::static_scene, "static_scene",
                   "ours: a grid of the fixed frame learns where returns stay put for "
                   "static_persist seconds, not near any track; a cluster with static_share of "
                   "its fit-band points on it starts no track and updates none (P1: off)")
          .real(&P::static_share, "static_share", "", 0.01, 1,
                "share of a cluster's fit-band points on static cells that keeps it from "
                "starting or updating a track")
          .boolean(&P::static_feeds, "static_feeds",
                   "a cluster on the static scene still updates existing tracks (only births "
                   "are kept off it); false: a track that strays onto a bin or a hedge coasts "
                   "and ends there")
          .real(&P::static_radius, "static_radius", "m", 0, 2,
                "a fit-band point counts as on static cells when one lies within this distance "
                "(porous foliage leaves gaps in the grid; 0: the point's own cell)")
          .real(&P::static_height_margin, "static_height_margin", "m", -1, 10,
                "ours: a fit-band point counts as on static cells only within this height of "
                "the returns those cells were learned from (a sitter's head above a bench "
                "back, shoulders above a car bonnet are not); < 0: heights ignored")
          .real(path(&P::scene, &StaticScene::Options::persist), "static_persist", "s", 0, 3600,
                "a cell occupied this long (not near a track) is static scene: longer than a "
                "walker's stance, shorter than a moving robot sees a parked car")
          .real(path(&P::scene, &StaticScene::Options::cell), "static_cell", "m", 0.05, 1,
                "cell size of the static-scene grid (a square of side 2 x max(25, "
                "static_range + 5) m round the robot)")
          .real(path(&P::scene, &StaticScene::Options::max_range), "static_range", "m", 1, 100,
                "returns farther than this from the sensor are not learned (nor cleared past)")
          .real(&P::unmoved_time, "unmoved_time", "s", 0, 3600,
                "ours: a confirmed track that stayed within unmoved_distance of where it was born "
                "this long, its detections' mean score below unmoved_score, no longer keeps the "
                "static grid from learning its returns (a bin taken for a person at start-up "
                "becomes static scene); 0: off")
          .real(&P::unmoved_distance, "unmoved_distance", "m", 0, 100,
                "see unmoved_time: a track that moved this far from its birth has walked")
          .real(&P::unmoved_score, "unmoved_score", "", 0, 1,
                "see unmoved_time: an unmoved track whose detections score this on average is "
                "a person standing")
          .real(&P::reidentify_time, "reidentify_time", "s", 0, 60,
                "ours: a confirmed track deleted for misses is kept lost until unseen this long; a "
                "track confirmed within its radius takes its id back (0: off, P1)")
          .real(&P::revive_score, "revive_score", "", 0, 1,
                "ours: a cluster scoring at least this, off the static scene and clear of "
                "confirmed tracks' gates, within a lost track's radius (reidentify_time) brings "
                "that track back at once, confirmed, whatever its size (a person seen again by a "
                "few returns after being hidden); with static_scene, only within the grid's "
                "range; 0: off")
          .real(&P::reidentify_speed, "reidentify_speed", "m/s", 0, 10,
                "a lost track's re-identification radius grows from gate by this per second "
                "unseen ...")
          .real(&P::reidentify_max, "reidentify_max", "m", 0, 20, "... by at most this much")
          .text(path(&P::scene, &StaticScene::Options::prior_map), "prior_map",
                "optional map of the fixed frame: ROS map.yaml or MRPT .gridmap; its "
                "occupied cells are static scene")
          .check(&P::q_min, [](const P& p) { return notAbove(p.q_min, p.q_person, "q_person"); })
          .check(&P::confirm_hits,
                 [](const P& p) {
                   return notAbove(p.confirm_hits, p.confirm_window, "confirm_window");
                 })
          .check(&P::fit_min_height, [](const P& p) {
            return p.fit_min_height >= p.fit_max_height ? "must be below fit_max_height"
                                                        : std::string();
          });
  return t;
}

const ParamTable<ShapeTrackerParams>& ShapeTracker::ellipseTable() {
  const auto e = [](auto member) {
    return path(&P::observation, &ShapeObservationParams::ellipse, member);
  };
  using E = fit::EllipseRansacParams;
  static const auto t =
      ParamTable<P>()
          .integer(path(&P::observation, &ShapeObservationParams::n_e), "n_e", "", 1, 100000,
                   "N_e (P1 eq. 18): points for the full ellipse observation [x,y,theta,a,b]")
          .integer(e(&E::sample_size), "sample_size", "", 3, 1000,
                   "n(N): points per RANSAC sample (P1)")
          .integer(e(&E::max_iterations), "iterations", "", 1, 100000,
                   "m: RANSAC iterations at most (P1)")
          .real(e(&E::confidence), "confidence", "", 0, 0.999999,
                "C: RANSAC stops once an outlier-free sample was drawn this surely (P1)")
          .real(e(&E::alpha_min), "alpha_min", "m", 0.001, 2,
                "smallest semi-axis across the shoulders")
          .real(e(&E::alpha_max), "alpha_max", "m", 0.001, 2,
                "largest semi-axis across the shoulders")
          .real(e(&E::beta_min), "beta_min", "m", 0.001, 2, "smallest front-to-back semi-axis")
          .real(e(&E::beta_max), "beta_max", "m", 0.001, 2, "largest front-to-back semi-axis")
          .real(e(&E::theta_window), "theta_window", "rad", 0, M_PI / 2,
                "theta_th: the fit's heading stays this close to the prediction (P1 eq. 11)")
          .real(e(&E::inlier_threshold), "inlier_threshold", "", 1e-6, 100,
                "d_th: a point with |s| above this is an outlier (s of P1 eq. 7)")
          .boolean(e(&E::center_correction), "center_correction",
                   "the exp term of P1 eq. 6 that keeps the centre behind the surface")
          .vector(path(&P::observation, &ShapeObservationParams::r_ellipse), "r_ellipse", "unit^2",
                  5, 1e-12, 1e6, "R_e: variances of the ellipse's [x, y, theta, alpha, beta]")
          .vector(path(&P::observation, &ShapeObservationParams::r_cog), "r_cog", "m^2", 2, 1e-12,
                  1e6, "R_p: variances of the centre of gravity's [x, y]")
          .real(&P::cog_alpha, "cog_alpha", "m", 0.01, 2, "the PC-COG model's fixed alpha (P1)")
          .real(path(&P::observation, &ShapeObservationParams::cog_beta), "cog_beta", "m", 0.01, 2,
                "the PC-COG model's fixed beta; also the COG offset before any ellipse")
          .check(e(&E::alpha_min),
                 [](const P& p) {
                   const E& e = p.observation.ellipse;
                   return e.alpha_min > e.alpha_max ? "above alpha_max" : "";
                 })
          .check(e(&E::beta_min), [](const P& p) {
            const E& e = p.observation.ellipse;
            return e.beta_min > e.beta_max    ? "above beta_max"
                   : e.beta_min > e.alpha_max ? "above alpha_max (P1 eq. 8 needs alpha >= beta)"
                                              : "";
          });
  return t;
}

const ParamTable<ShapeTrackerParams>& ShapeTracker::boxTable() {
  using O = ShapeObservationParams;
  static const auto t =
      ParamTable<P>()
          .integer(path(&P::observation, &O::n_b), "n_b", "", 1, 100000,
                   "N_b (P1 eq. 18): points for the full box observation (and any ellipse)")
          .choice(path(&P::observation, &O::l_shape), "box",
                  {{"min_area", false}, {"l_shape", true}},
                  "bounding box: least-area rectangle or L-shape fit (closeness)")
          .vector(path(&P::observation, &O::r_box), "r_box", "unit^2", 5, 1e-12, 1e6,
                  "R_b: variances of the box's [x, y, theta, alpha, beta]");
  return t;
}

const ParamTable<ShapeTrackerParams>& ShapeTracker::circleTable() {
  using O = ShapeObservationParams;
  using C = fit::CircleRansacParams;
  const auto c = [](auto member) { return path(&P::observation, &O::circle, member); };
  static const auto t =
      ParamTable<P>()
          .real(c(&C::r_min), "r_min", "m", 0.001, 2, "smallest torso circle radius")
          .real(c(&C::r_max), "r_max", "m", 0.001, 2, "largest torso circle radius")
          .real(c(&C::inlier_threshold), "circle_threshold", "m", 1e-4, 1,
                "a point this close to a RANSAC circle is an inlier")
          .integer(c(&C::max_iterations), "circle_iterations", "", 1, 100000,
                   "RANSAC circle samples at most")
          .vector(path(&P::observation, &O::r_circle), "r_circle", "m^2", 3, 1e-12, 1e6,
                  "variances of the circle's [x, y, radius]")
          .check(c(&C::r_min), [](const P& p) {
            return p.observation.circle.r_min > p.observation.circle.r_max ? "above r_max" : "";
          });
  return t;
}

}  // namespace pedtrack::track
