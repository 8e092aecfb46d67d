// mhe_mlesac (P0): pedestrians tracked by their torso ellipse estimated by moving-horizon
// estimation inside MLESAC (Algorithm 1): j_max candidates, each fitted by Ipopt to |Ψ| points
// sampled from the last H frames under the motion model of eq. 2 and constraints (6)–(10), the
// most likely on its inliers wins. A KF on the RANSAC ellipse runs alongside (arrival cost, first
// H frames, fallback when Ipopt fails). Association and track management are imm_shape's.
#include <iostream>
#include <memory>

#include "mhe_mlesac/mhe_estimator.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::mhemlesac {
namespace {

using namespace pedtrack::track;

struct MheMlesacParams {
  ShapeTrackerParams shape;  // association, management, the torso band, the KF alongside
  MheEstimatorParams estimator;
  MheMlesacParams() {
    // Eq. 3's s is negative inside the ellipse, so a point of the head, the neck or the hips
    // (which project inside the torso's outline) pulls the fit inwards as hard as a stray point
    // outside pulls it out: the data term must see the torso only. An adult's torso spans the
    // hips (0.53 of the stature) to the shoulders (0.82; Drillis & Contini's proportions):
    // 1.0–1.3 m above the ground is torso for every stature from 1.6 to 1.9 m (P0 dropped only
    // the legs, below 0.6 m).
    shape.fit_min_height = 1.0;
    shape.fit_max_height = 1.3;
  }
};

const ParamTable<MheMlesacParams>& table() {
  using P = MheMlesacParams;
  const auto mhe = [](auto member) {
    return path(&P::estimator, &MheEstimatorParams::mhe, member);
  };
  const auto sel = [](auto member) {
    return path(&P::estimator, &MheEstimatorParams::mlesac, member);
  };
  const auto ipopt = [](auto member) {
    return path(&P::estimator, &MheEstimatorParams::solver, member);
  };
  using M = mhe::MheParams;
  using S = mhe::MlesacOptions;
  using I = mhe::SolverOptions;
  static const auto t =
      ParamTable<P>()
          // The IMM's noise `q` is not P0's: its model's noise is system_noise. The torso band
          // is the torso's (see MheMlesacParams).
          .include(&P::shape, ShapeTracker::commonTable()
                                  .without("q")
                                  .without("fit_min_height")
                                  .without("fit_max_height"))
          .real(path(&P::shape, &ShapeTrackerParams::fit_min_height), "fit_min_height", "m", -10,
                10, "lowest point height the torso is fitted to (hips of a 1.9 m adult)")
          .real(path(&P::shape, &ShapeTrackerParams::fit_max_height), "fit_max_height", "m", -10,
                10, "highest point height the torso is fitted to (shoulders of a 1.6 m adult)")
          .check(path(&P::shape, &ShapeTrackerParams::fit_min_height),
                 [](const P& p) {
                   return p.shape.fit_min_height >= p.shape.fit_max_height
                              ? "must be below fit_max_height"
                              : "";
                 })
          .include(&P::shape, ShapeTracker::ellipseTable())
          .integer(mhe(&M::horizon), "horizon", "frames", 2, 100, "H: the moving horizon (P0)")
          .integer(mhe(&M::subset), "subset", "points", 3, 100000,
                   "|Psi|: points each candidate samples from the whole horizon (P0)")
          .integer(mhe(&M::candidates), "candidates", "", 1, 100000,
                   "j_max: MLESAC candidates per frame (P0)")
          .vector(mhe(&M::q), "system_noise", "unit^2", 5, 1e-12, 1e6,
                  "Q (P0): variances of the noise on [vx, vy, omega] (accelerations) and "
                  "[alpha, beta] (rates) of eq. 2")
          .real(mhe(&M::r), "r", "", 1e-12, 1e6, "R (P0): the ellipse deviation's variance")
          .real(mhe(&M::theta_th), "theta_th", "rad", 0.001, M_PI / 2,
                "eq. 9: the axis stays this close to its a priori value each frame (P0)")
          .real(mhe(&M::d_th), "d_th", "", 1e-6, 100,
                "a point with |s| below this is an inlier (P0)")
          .choice(sel(&S::selection), "selection",
                  {{"inlier_mean", mhe::Selection::InlierMean},
                   {"truncated", mhe::Selection::Truncated}},
                  "candidate likelihood: eq. 5 on the inliers (P0) or every point with outliers "
                  "at d_th^2 (MLESAC)")
          .boolean(sel(&S::sampling), "mlesac",
                   "sample candidates (false: one MHE on every point, P0's MHE without MLESAC)")
          .boolean(path(&P::estimator, &MheEstimatorParams::kf_only), "ransac_only",
                   "report the KF alongside on each frame's RANSAC ellipse and never run the MHE "
                   "(P0's RANSAC comparison)")
          .integer(sel(&S::finalists), "finalists", "", 0, 100000,
                   "candidates Ipopt solves after the fast screen ranks them (0: every one, P0's "
                   "offline procedure)")
          .integer(sel(&S::screen_iterations), "screen_iterations", "", 1, 1000,
                   "Levenberg-Marquardt steps of the screen per candidate")
          .integer(sel(&S::survivors), "survivors", "", 1, 100000,
                   "candidates the screen keeps after half its steps (pruning)")
          .boolean(sel(&S::refit), "refit",
                   "solve the winner again on all its inliers (MLESAC's last step)")
          .integer(sel(&S::refit_points), "refit_points", "points", 3, 10000000,
                   "the refit's sample: at most this many of the winner's inliers")
          .integer(ipopt(&I::max_iterations), "ipopt_max_iter", "", 1, 10000,
                   "Ipopt iterations per solve at most")
          .real(ipopt(&I::tolerance), "ipopt_tol", "", 1e-12, 1,
                "Ipopt's convergence tolerance (tol)")
          .integer(ipopt(&I::print_level), "ipopt_print_level", "", 0, 12,
                   "Ipopt's log on stdout (0: silent)");
  return t;
}

// The estimator's parameters with what it shares with the tracker: the KF's observation and
// noise, and eq. 7–8's bounds, which are the RANSAC's (P0 and P1 use the same values).
MheEstimatorParams estimatorParams(const MheMlesacParams& p) {
  MheEstimatorParams e = p.estimator;
  e.observation = p.shape.observation;
  e.flip_speed = p.shape.flip_speed;
  e.init_speed_sigma = p.shape.init_speed_sigma;
  const fit::EllipseRansacParams& r = p.shape.observation.ellipse;
  e.mhe.alpha_min = r.alpha_min;
  e.mhe.alpha_max = r.alpha_max;
  e.mhe.beta_min = r.beta_min;
  e.mhe.beta_max = r.beta_max;
  return e;
}

class MheMlesacStage : public Tracker {
 public:
  explicit MheMlesacStage(const MheMlesacParams& p)
      : counters_(std::make_shared<MheCounters>()),
        stage_(p.shape, mheTorsoEstimators(estimatorParams(p), counters_)) {}
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
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<MheMlesacStage>(table().read(ctx.params));
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::mhemlesac

PEDTRACK_PLUGIN("mhe_mlesac", pedtrack::mhemlesac::describe)
