// mhe_mlesac (P0): pedestrians tracked by their torso ellipse estimated by moving-horizon
// estimation inside MLESAC (Algorithm 1): j_max candidates, each fitted by Ipopt to |Ψ| points
// sampled from the last H frames under the motion model of eq. 2 and constraints (6)–(10), the
// most likely on its inliers wins. A KF on the RANSAC ellipse runs alongside (arrival cost, first
// H frames, fallback when Ipopt fails). Association and track management are imm_shape's.
#include <iostream>
#include <memory>

#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/mhe_estimator.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::mhemlesac {
namespace {

using namespace pedtrack::track;

// Eq. 3's s is negative inside the ellipse, so a point of the head, the neck or the hips (which
// project inside the torso's outline) pulls the fit inwards as hard as a stray point outside
// pulls it out: the data term must see the torso only. An adult's torso spans the hips (0.53 of
// the stature) to the shoulders (0.82; Drillis & Contini's proportions): 1.0–1.3 m above the
// ground is torso for every stature from 1.6 to 1.9 m (P0 dropped only the legs, below 0.6 m).
ParamSpec torsoBand(const std::string& name) {
  if (name == "fit_min_height")
    return ParamSpec::real("fit_min_height", 1.0, "m", -10, 10,
                           "lowest point height the torso is fitted to (hips of a 1.9 m adult)");
  return ParamSpec::real(
      "fit_max_height", 1.3, "m", -10, 10,
      "highest point height the torso is fitted to (shoulders of a 1.6 m adult)");
}

std::vector<ParamSpec> mheParams() {
  return {
      ParamSpec::integer("horizon", 10, "frames", 2, 100, "H: the moving horizon (P0)"),
      ParamSpec::integer("subset", 100, "points", 3, 100000,
                         "|Psi|: points each candidate samples from the whole horizon (P0)"),
      ParamSpec::integer("candidates", 100, "", 1, 100000,
                         "j_max: MLESAC candidates per frame (P0)"),
      ParamSpec::vector("system_noise", std::vector<double>{0.1, 0.1, 0.08, 1e-4, 1e-4}, "unit^2",
                        5, 1e-12, 1e6,
                        "Q (P0): variances of the noise on [vx, vy, omega] (accelerations) and "
                        "[alpha, beta] (rates) of eq. 2"),
      ParamSpec::real("r", 1e-4, "", 1e-12, 1e6, "R (P0): the ellipse deviation's variance"),
      ParamSpec::real("theta_th", M_PI / 18, "rad", 0.001, M_PI / 2,
                      "eq. 9: the axis stays this close to its a priori value each frame (P0)"),
      ParamSpec::real("d_th", 0.8, "", 1e-6, 100, "a point with |s| below this is an inlier (P0)"),
      ParamSpec::choice("selection", "inlier_mean", {"inlier_mean", "truncated"},
                        "candidate likelihood: eq. 5 on the inliers (P0) or every point with "
                        "outliers at d_th^2 (MLESAC)"),
      ParamSpec::boolean(
          "mlesac", true,
          "sample candidates (false: one MHE on every point, P0's MHE without MLESAC)"),
      ParamSpec::boolean("ransac_only", false,
                         "report the KF alongside on each frame's RANSAC ellipse and never run the "
                         "MHE (P0's RANSAC comparison)"),
      ParamSpec::integer("finalists", 1, "", 0, 100000,
                         "candidates Ipopt solves after the fast screen ranks them (0: every one, "
                         "P0's offline procedure)"),
      ParamSpec::integer("screen_iterations", 2, "", 1, 1000,
                         "Levenberg-Marquardt steps of the screen per candidate"),
      ParamSpec::integer("survivors", 10, "", 1, 100000,
                         "candidates the screen keeps after half its steps (pruning)"),
      ParamSpec::boolean("refit", true,
                         "solve the winner again on all its inliers (MLESAC's last step)"),
      ParamSpec::integer("refit_points", 400, "points", 3, 10000000,
                         "the refit's sample: at most this many of the winner's inliers"),
      ParamSpec::integer("ipopt_max_iter", 30, "", 1, 10000, "Ipopt iterations per solve at most"),
      ParamSpec::real("ipopt_tol", 1e-6, "", 1e-12, 1, "Ipopt's convergence tolerance (tol)"),
      ParamSpec::integer("ipopt_print_level", 0, "", 0, 12, "Ipopt's log on stdout (0: silent)"),
  };
}

MheEstimatorParams readMhe(const ParamSet& s) {
  ShapeTrackerParams shape;
  ShapeTracker::read(s, shape);
  MheEstimatorParams p;
  p.observation = shape.observation;
  p.flip_speed = shape.flip_speed;
  p.init_speed_sigma = shape.init_speed_sigma;
  mhe::MheParams& m = p.mhe;
  m.horizon = int(s.getInt("horizon"));
  m.subset = int(s.getInt("subset"));
  m.candidates = int(s.getInt("candidates"));
  const std::vector<double> q = s.getVector("system_noise");
  for (int i = 0; i < 5; ++i) m.q(i) = q[std::size_t(i)];
  m.r = s.getDouble("r");
  // Eq. 7–8 share the KF's RANSAC bounds (P0 and P1 use the same values).
  m.alpha_min = p.observation.ellipse.alpha_min;
  m.alpha_max = p.observation.ellipse.alpha_max;
  m.beta_min = p.observation.ellipse.beta_min;
  m.beta_max = p.observation.ellipse.beta_max;
  m.theta_th = s.getDouble("theta_th");
  m.d_th = s.getDouble("d_th");
  p.mlesac.selection = s.getString("selection") == "truncated" ? mhe::Selection::Truncated
                                                               : mhe::Selection::InlierMean;
  p.mlesac.sampling = s.getBool("mlesac");
  p.kf_only = s.getBool("ransac_only");
  p.mlesac.finalists = int(s.getInt("finalists"));
  p.mlesac.screen_iterations = int(s.getInt("screen_iterations"));
  p.mlesac.survivors = int(s.getInt("survivors"));
  p.mlesac.refit = s.getBool("refit");
  p.mlesac.refit_points = int(s.getInt("refit_points"));
  p.solver.max_iterations = int(s.getInt("ipopt_max_iter"));
  p.solver.tolerance = s.getDouble("ipopt_tol");
  p.solver.print_level = int(s.getInt("ipopt_print_level"));
  return p;
}

class MheMlesacStage : public Tracker {
 public:
  explicit MheMlesacStage(const ParamSet& params)
      : counters_(std::make_shared<MheCounters>()),
        stage_(params, mheTorsoEstimators(readMhe(params), counters_)) {}
  void process(Frame& f) override { stage_.process(f); }
  void finish() override {
    const MheCounters& c = *counters_;
    if (c.fallbacks > 0 || c.failed > 0)
      std::cerr << "warning: mhe_mlesac: " << c.failed << " of " << c.solves
                << " Ipopt solves failed; " << c.fallbacks << " of " << c.windows
                << " frames fell back to the KF estimate\n";
  }
  std::vector<std::pair<std::string, long>> counters() const override {
    const MheCounters& c = *counters_;
    return {{"mhe_windows", c.windows},
            {"mhe_candidates", c.candidates},
            {"ipopt_solves", c.solves},
            {"ipopt_failed", c.failed},
            {"kf_fallbacks", c.fallbacks}};
  }

 private:
  std::shared_ptr<MheCounters> counters_;
  ShapeTrackerStage stage_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P0: MHE-MLESAC torso ellipse [x,y,theta,vx,vy,omega,alpha,beta] solved with Ipopt";
  for (const ParamSpec& spec : ShapeTracker::commonParams()) {
    if (spec.name == "q") continue;  // the IMM's noise; P0's is system_noise
    if (spec.name == "fit_min_height" || spec.name == "fit_max_height")
      d.params.push_back(torsoBand(spec.name));
    else
      d.params.push_back(spec);
  }
  for (auto group : {ShapeTracker::ellipseParams(), mheParams()})
    d.params.insert(d.params.end(), group.begin(), group.end());
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<MheMlesacStage>(ctx.params);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::mhemlesac

PEDTRACK_PLUGIN("mhe_mlesac", pedtrack::mhemlesac::describe)
