// `irls_ground`: P2's IRLS ground plane (eq. 1–4) tracked frame to frame; points within
// `threshold` of the plane (or below it) are labelled ground.
#include <cmath>
#include <iostream>

#include "irls_ground/irls_ground_fit.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::irlsground {
namespace {

struct IrlsGroundParams {
  seg::IrlsParams fit;      // P2 eq. 1-4's parameters (irls_ground_fit.h)
  double threshold = 0.05;  // m: points at most this high above the plane are ground
};

const ParamTable<IrlsGroundParams>& table() {
  using P = IrlsGroundParams;
  using F = seg::IrlsParams;
  static const auto t =
      ParamTable<P>()
          .real(path(&P::fit, &F::max_range), "max_range", "m", 0.5, 100,
                "fit the points within this horizontal distance of the sensor")
          .real(path(&P::fit, &F::bin), "bin", "m", 0.01, 2,
                "cell side of the horizontal binning; the lowest point of a cell is fitted")
          .real(path(&P::fit, &F::A), "weight_a", "", 0, 1e6,
                "A of the weight W(x) = 1/(1 + A e^(B(x-C))) + D")
          .real(path(&P::fit, &F::B), "weight_b", "1/m", 0, 1e4, "B of the weight W(x) (steepness)")
          .real(path(&P::fit, &F::C), "weight_c", "m", 0, 10,
                "C of the weight W(x) (distance of the fall)")
          .real(path(&P::fit, &F::D), "weight_d", "", 0, 1, "D of the weight W(x) (floor weight)")
          .integer(path(&P::fit, &F::seed_rows), "seed_rows", "", 0, 100,
                   "rows of the seed mesh on the default plane (0: no seeds)")
          .integer(path(&P::fit, &F::seed_cols), "seed_cols", "", 0, 100,
                   "columns of the seed mesh")
          .real(path(&P::fit, &F::seed_extent), "seed_extent", "m", 0, 100,
                "the seed mesh spans this distance on each side of the sensor")
          .real(path(&P::fit, &F::default_height), "default_height", "m", -100, 100,
                "robot-frame z of the default (level) ground plane")
          .boolean(path(&P::fit, &F::auto_height), "auto_height",
                   "take the default plane's height from the first frame (the lowest "
                   "well-populated level of the cells' lowest points) instead of default_height")
          .integer(path(&P::fit, &F::iterations), "iterations", "", 1, 1000,
                   "IRLS iterations per frame at most")
          .real(path(&P::fit, &F::tolerance), "tolerance", "m", 0, 1,
                "stop iterating when the plane moves less than this")
          .real(path(&P::fit, &F::max_tilt), "max_tilt", "deg", 0, 90,
                "an estimate tilted more than this from the default plane is refused (the "
                "previous plane is kept)",
                kDegree)
          .real(path(&P::fit, &F::refine_band), "refine_band", "m", 0, 10,
                "> 0: after IRLS, refit by least squares to the fitted points within this "
                "distance of the plane (removes the tilt the weight floor D gives toward "
                "obstacles); 0: P2 as published")
          .real(&P::threshold, "threshold", "m", 0, 10,
                "points at most this high above the plane (or below it) are ground");
  return t;
}

class IrlsGroundStage : public Segmenter {
 public:
  explicit IrlsGroundStage(const PluginContext& ctx) : IrlsGroundStage(table().read(ctx.params)) {}
  explicit IrlsGroundStage(const IrlsGroundParams& p) : ground_(p.fit), threshold_(p.threshold) {}

  void finish() override {
    if (ground_.refused())
      std::cerr << "warning: irls_ground: " << ground_.refused()
                << " frames' planes were refused (tilted beyond max_tilt or degenerate); the "
                   "previous plane was kept\n";
  }

  void process(Frame& f) override {
    const auto& c = f.cloud();
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    const auto& zs = c.getPointsBufferRef_z();
    const mrpt::poses::CPose3D mount = f.sensorMount();
    f.ground =
        ground_.update(xs.data(), ys.data(), zs.data(), c.size(),
                       f.point_labels.empty() ? nullptr : &f.point_labels, mount.x(), mount.y());
    if (c.size() == 0) return;
    auto& labels = f.labels();
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (labels[i] != PointLabel::Kept) continue;
      const double h = f.ground.height(xs[i], ys[i], zs[i]);
      if (!std::isfinite(h))
        labels[i] = PointLabel::Removed;  // a non-finite point is no measurement
      else if (h <= threshold_)
        labels[i] = PointLabel::Ground;
    }
  }

 private:
  seg::IrlsGround ground_;
  double threshold_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc = "Ground plane by IRLS (P2 eq. 1-4), tracked frame to frame; labels ground points";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<IrlsGroundStage>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::irlsground

PEDTRACK_PLUGIN("irls_ground", pedtrack::irlsground::describe)
