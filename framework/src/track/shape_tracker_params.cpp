// The parameters of the shape trackers, declared once for imm_shape, kf_bb and kf_circle.
#include <cmath>
#include <stdexcept>

#include "pedtrack/errors.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::track {
namespace {

Eigen::VectorXd vec(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
}

}  // namespace

std::vector<ParamSpec> ShapeTracker::commonParams() {
  return {
      ParamSpec::real("q_person", 0.5, "", 0, 1,
                      "a detection scoring at least this starts a track (classifier score Q)"),
      ParamSpec::real("q_min", 0.2, "", 0, 1,
                      "an existing track also takes detections scoring above this (hysteresis)"),
      ParamSpec::real("gate", 1.0, "m", 0.01, 20,
                      "largest distance between a track's prediction and a cluster (Hungarian)"),
      ParamSpec::integer("confirm_hits", 3, "", 1, 32,
                         "M of M-of-N: associations that confirm a track"),
      ParamSpec::integer("confirm_window", 5, "", 1, 32,
                         "N of M-of-N: a new track's first scans that must hold M associations"),
      ParamSpec::integer("max_misses", 10, "", 0, 10000,
                         "the scan that makes this many misses in a row deletes a confirmed track"),
      ParamSpec::vector("q", std::vector<double>{0, 0, 10, 10, 1e-3, 1e-3}, "unit^2/s", 6, 0, 1e6,
                        "process noise rates of [x, y, theta, v, alpha, beta] (P1 Table I per "
                        "0.1 s frame x 10)"),
      ParamSpec::real(
          "fit_min_height", 0.6, "m", -10, 10,
          "lowest point height the shapes are fitted to (P0: legs below 0.6 m dropped)"),
      ParamSpec::real("fit_max_height", 2.2, "m", -10, 10,
                      "highest point height the shapes are fitted to"),
      ParamSpec::real("init_speed_sigma", 1.0, "m/s", 0.01, 10,
                      "speed uncertainty of a new track (its facing direction is unknown)"),
      ParamSpec::integer(
          "birth_points", 10, "", 1, 100000,
          "points in the fit band a cluster needs to start a track (N_b: a shape can be fitted)"),
      ParamSpec::real("flip_speed", 0.2, "m/s", 0, 10,
                      "a track moving against its heading faster than this is turned round (the "
                      "shapes give the heading modulo 180 deg)"),
      ParamSpec::integer("seed", 1, "", 0, 4294967295.0, "seed of the RANSAC sampling"),
      ParamSpec::boolean("report_tentative", false,
                         "also write tracks not yet confirmed to tracks.csv (status tentative)"),
  };
}

std::vector<ParamSpec> ShapeTracker::ellipseParams() {
  const double th = std::pow(M_PI / 12, 2);
  return {
      ParamSpec::integer(
          "n_e", 40, "", 1, 100000,
          "N_e (P1 eq. 18): points for the full ellipse observation [x,y,theta,a,b]"),
      ParamSpec::integer("sample_size", 9, "", 3, 1000, "n(N): points per RANSAC sample (P1)"),
      ParamSpec::integer("iterations", 100, "", 1, 100000, "m: RANSAC iterations at most (P1)"),
      ParamSpec::real("confidence", 0.95, "", 0, 0.999999,
                      "C: RANSAC stops once an outlier-free sample was drawn this surely (P1)"),
      ParamSpec::real("alpha_min", 0.10, "m", 0.001, 2, "smallest semi-axis across the shoulders"),
      ParamSpec::real("alpha_max", 0.20, "m", 0.001, 2, "largest semi-axis across the shoulders"),
      ParamSpec::real("beta_min", 0.05, "m", 0.001, 2, "smallest front-to-back semi-axis"),
      ParamSpec::real("beta_max", 0.10, "m", 0.001, 2, "largest front-to-back semi-axis"),
      ParamSpec::real("theta_window", M_PI / 12, "rad", 0, M_PI / 2,
                      "theta_th: the fit's heading stays this close to the prediction (P1 eq. 11)"),
      ParamSpec::real("inlier_threshold", 0.5, "", 1e-6, 100,
                      "d_th: a point with |s| above this is an outlier (s of P1 eq. 7)"),
      ParamSpec::boolean("center_correction", true,
                         "the exp term of P1 eq. 6 that keeps the centre behind the surface"),
      ParamSpec::vector("r_ellipse", std::vector<double>{9e-4, 9e-4, th, 9e-2, 9e-2}, "unit^2", 5,
                        1e-12, 1e6, "R_e: variances of the ellipse's [x, y, theta, alpha, beta]"),
      ParamSpec::vector("r_cog", std::vector<double>{3.6e-3, 3.6e-3}, "m^2", 2, 1e-12, 1e6,
                        "R_p: variances of the centre of gravity's [x, y]"),
      ParamSpec::real("cog_alpha", 0.17, "m", 0.01, 2, "the PC-COG model's fixed alpha (P1)"),
      ParamSpec::real("cog_beta", 0.08, "m", 0.01, 2,
                      "the PC-COG model's fixed beta; also the COG offset before any ellipse"),
  };
}

std::vector<ParamSpec> ShapeTracker::boxParams() {
  const double th = std::pow(M_PI / 12, 2);
  return {
      ParamSpec::integer("n_b", 10, "", 1, 100000,
                         "N_b (P1 eq. 18): points for the full box observation (and any ellipse)"),
      ParamSpec::choice("box", "min_area", {"min_area", "l_shape"},
                        "bounding box: least-area rectangle or L-shape fit (closeness)"),
      ParamSpec::vector("r_box", std::vector<double>{9e-4, 9e-4, th, 16e-2, 16e-2}, "unit^2", 5,
                        1e-12, 1e6, "R_b: variances of the box's [x, y, theta, alpha, beta]"),
  };
}

std::vector<ParamSpec> ShapeTracker::circleParams() {
  return {
      ParamSpec::real("r_min", 0.10, "m", 0.001, 2, "smallest torso circle radius"),
      ParamSpec::real("r_max", 0.30, "m", 0.001, 2, "largest torso circle radius"),
      ParamSpec::real("circle_threshold", 0.03, "m", 1e-4, 1,
                      "a point this close to a RANSAC circle is an inlier"),
      ParamSpec::integer("circle_iterations", 100, "", 1, 100000, "RANSAC circle samples at most"),
      ParamSpec::vector("r_circle", std::vector<double>{9e-4, 9e-4, 9e-2}, "m^2", 3, 1e-12, 1e6,
                        "variances of the circle's [x, y, radius]"),
  };
}

void ShapeTracker::read(const ParamSet& s, ShapeTrackerParams& p) {
  p.q_person = s.getDouble("q_person");
  p.q_min = s.getDouble("q_min");
  if (p.q_min > p.q_person)
    throw ConfigError(s.where("q_min") + ": must not exceed q_person (" +
                      std::to_string(p.q_person) + ")");
  p.gate = s.getDouble("gate");
  p.confirm_hits = int(s.getInt("confirm_hits"));
  p.confirm_window = int(s.getInt("confirm_window"));
  if (p.confirm_hits > p.confirm_window)
    throw ConfigError(s.where("confirm_hits") + ": must not exceed confirm_window (" +
                      std::to_string(p.confirm_window) + ")");
  p.max_misses = int(s.getInt("max_misses"));
  if (s.has("q")) p.q_rates = vec(s.getVector("q"));  // mhe_mlesac has P0's noise instead
  p.fit_min_height = s.getDouble("fit_min_height");
  p.fit_max_height = s.getDouble("fit_max_height");
  if (p.fit_min_height >= p.fit_max_height)
    throw ConfigError(s.where("fit_min_height") + ": must be below fit_max_height");
  p.init_speed_sigma = s.getDouble("init_speed_sigma");
  p.flip_speed = s.getDouble("flip_speed");
  p.birth_points = int(s.getInt("birth_points"));
  p.seed = unsigned(s.getInt("seed"));
  p.report_tentative = s.getBool("report_tentative");
  ShapeObservationParams& o = p.observation;
  if (s.has("n_e")) {
    o.n_e = int(s.getInt("n_e"));
    auto& e = o.ellipse;
    e.sample_size = int(s.getInt("sample_size"));
    e.max_iterations = int(s.getInt("iterations"));
    e.confidence = s.getDouble("confidence");
    e.alpha_min = s.getDouble("alpha_min");
    e.alpha_max = s.getDouble("alpha_max");
    e.beta_min = s.getDouble("beta_min");
    e.beta_max = s.getDouble("beta_max");
    if (e.alpha_min > e.alpha_max) throw ConfigError(s.where("alpha_min") + ": above alpha_max");
    if (e.beta_min > e.beta_max) throw ConfigError(s.where("beta_min") + ": above beta_max");
    if (e.beta_min > e.alpha_max)
      throw ConfigError(s.where("beta_min") + ": above alpha_max (P1 eq. 8 needs alpha >= beta)");
    e.theta_window = s.getDouble("theta_window");
    e.inlier_threshold = s.getDouble("inlier_threshold");
    e.center_correction = s.getBool("center_correction");
    o.r_ellipse = vec(s.getVector("r_ellipse"));
    o.r_cog = vec(s.getVector("r_cog"));
    p.cog_alpha = s.getDouble("cog_alpha");
    p.cog_beta = s.getDouble("cog_beta");
    o.cog_beta = p.cog_beta;
  }
  if (s.has("n_b")) {
    o.n_b = int(s.getInt("n_b"));
    o.l_shape = s.getString("box") == "l_shape";
    o.r_box = vec(s.getVector("r_box"));
  }
  if (s.has("r_min")) {
    auto& c = o.circle;
    c.r_min = s.getDouble("r_min");
    c.r_max = s.getDouble("r_max");
    if (c.r_min > c.r_max) throw ConfigError(s.where("r_min") + ": above r_max");
    c.inlier_threshold = s.getDouble("circle_threshold");
    c.max_iterations = int(s.getInt("circle_iterations"));
    o.r_circle = vec(s.getVector("r_circle"));
  }
}

ShapeTrackerParams ShapeTrackerStage::makeParams(const ParamSet& params,
                                                 std::vector<ShapeModel> models,
                                                 Eigen::MatrixXd transition) {
  ShapeTrackerParams p;
  ShapeTracker::read(params, p);
  p.models = std::move(models);
  p.transition = std::move(transition);
  return p;
}

ShapeTrackerStage::ShapeTrackerStage(const ParamSet& params, std::vector<ShapeModel> models,
                                     Eigen::MatrixXd transition)
    : tracker_(makeParams(params, std::move(models), std::move(transition))) {}

ShapeTrackerStage::ShapeTrackerStage(const ParamSet& params, TorsoEstimatorFactory estimators)
    : tracker_(makeParams(params, {}, {}), std::move(estimators)) {}

}  // namespace pedtrack::track
