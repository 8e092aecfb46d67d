// `irls_ground`: P2's IRLS ground plane (eq. 1–4) tracked frame to frame; points within
// `threshold` of the plane (or below it) are labelled ground.
#include "pedtrack/seg/irls_ground.h"

#include <cmath>
#include <iostream>

#include "pedtrack/plugin.h"

namespace pedtrack::irlsground {
namespace {

constexpr double kDeg = M_PI / 180.0;

seg::IrlsParams readParams(const ParamSet& p) {
  seg::IrlsParams q;
  q.max_range = p.getDouble("max_range");
  q.bin = p.getDouble("bin");
  q.A = p.getDouble("weight_a");
  q.B = p.getDouble("weight_b");
  q.C = p.getDouble("weight_c");
  q.D = p.getDouble("weight_d");
  q.seed_rows = int(p.getInt("seed_rows"));
  q.seed_cols = int(p.getInt("seed_cols"));
  q.seed_extent = p.getDouble("seed_extent");
  q.default_height = p.getDouble("default_height");
  q.auto_height = p.getBool("auto_height");
  q.iterations = int(p.getInt("iterations"));
  q.tolerance = p.getDouble("tolerance");
  q.max_tilt = p.getDouble("max_tilt") * kDeg;
  q.refine_band = p.getDouble("refine_band");
  return q;
}

class IrlsGroundStage : public Segmenter {
 public:
  explicit IrlsGroundStage(const PluginContext& ctx)
      : ground_(readParams(ctx.params)), threshold_(ctx.params.getDouble("threshold")) {}

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
  const seg::IrlsParams def;
  d.params = {
      ParamSpec::real("max_range", def.max_range, "m", 0.5, 100,
                      "fit the points within this horizontal distance of the sensor"),
      ParamSpec::real("bin", def.bin, "m", 0.01, 2,
                      "cell side of the horizontal binning; the lowest point of a cell is fitted"),
      ParamSpec::real("weight_a", def.A, "", 0, 1e6,
                      "A of the weight W(x) = 1/(1 + A e^(B(x-C))) + D"),
      ParamSpec::real("weight_b", def.B, "1/m", 0, 1e4, "B of the weight W(x) (steepness)"),
      ParamSpec::real("weight_c", def.C, "m", 0, 10, "C of the weight W(x) (distance of the fall)"),
      ParamSpec::real("weight_d", def.D, "", 0, 1, "D of the weight W(x) (floor weight)"),
      ParamSpec::integer("seed_rows", def.seed_rows, "", 0, 100,
                         "rows of the seed mesh on the default plane (0: no seeds)"),
      ParamSpec::integer("seed_cols", def.seed_cols, "", 0, 100, "columns of the seed mesh"),
      ParamSpec::real("seed_extent", def.seed_extent, "m", 0, 100,
                      "the seed mesh spans this distance on each side of the sensor"),
      ParamSpec::real("default_height", def.default_height, "m", -100, 100,
                      "robot-frame z of the default (level) ground plane"),
      ParamSpec::boolean("auto_height", def.auto_height,
                         "take the default plane's height from the first frame (the lowest "
                         "well-populated level of the cells' lowest points) instead of "
                         "default_height"),
      ParamSpec::integer("iterations", def.iterations, "", 1, 1000,
                         "IRLS iterations per frame at most"),
      ParamSpec::real("tolerance", def.tolerance, "m", 0, 1,
                      "stop iterating when the plane moves less than this"),
      ParamSpec::real("max_tilt", def.max_tilt / kDeg, "deg", 0, 90,
                      "an estimate tilted more than this from the default plane is refused (the "
                      "previous plane is kept)"),
      ParamSpec::real("refine_band", def.refine_band, "m", 0, 10,
                      "> 0: after IRLS, refit by least squares to the fitted points within this "
                      "distance of the plane (removes the tilt the weight floor D gives toward "
                      "obstacles); 0: P2 as published"),
      ParamSpec::real("threshold", 0.05, "m", 0, 10,
                      "points at most this high above the plane (or below it) are ground"),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<IrlsGroundStage>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::irlsground

PEDTRACK_PLUGIN("irls_ground", pedtrack::irlsground::describe)
