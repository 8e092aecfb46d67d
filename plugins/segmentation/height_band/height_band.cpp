// `height_band`: keeps the points in a band of heights above the ground plane (P0 drops the
// legs below 0.6 m) and in a region of interest around the sensor; the rest are removed.
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"

namespace pedtrack::heightband {
namespace {

constexpr double kDeg = M_PI / 180.0;

class HeightBand : public Segmenter {
 public:
  explicit HeightBand(const PluginContext& ctx)
      : min_h_(ctx.params.getDouble("min_height")),
        max_h_(ctx.params.getDouble("max_height")),
        min_r_(ctx.params.getDouble("min_range")),
        max_r_(ctx.params.getDouble("max_range")),
        half_fov_(0.5 * ctx.params.getDouble("fov") * kDeg),
        heading_(ctx.params.getDouble("heading") * kDeg),
        footprint_(ctx.params.getVector("footprint")) {
    if (footprint_[0] > footprint_[1] || footprint_[2] > footprint_[3])
      throw ConfigError(ctx.params.where("footprint") +
                        ": expected x_min x_max y_min y_max with x_min <= x_max, y_min <= y_max");
  }

  void process(Frame& f) override {
    const auto& c = f.cloud();
    if (c.size() == 0) return;
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    const auto& zs = c.getPointsBufferRef_z();
    const GroundPlane& g = f.ground;
    const mrpt::poses::CPose3D mount = f.sensorMount();
    const double sx = mount.x(), sy = mount.y(), axis = mount.yaw() + heading_;
    const bool sector = half_fov_ < M_PI;
    auto& labels = f.labels();
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (labels[i] != PointLabel::Kept) continue;
      const double h = g.heightOrZ(xs[i], ys[i], zs[i]);
      const double dx = xs[i] - sx, dy = ys[i] - sy, r = std::hypot(dx, dy);
      bool keep = h >= min_h_ && h <= max_h_ && r >= min_r_ && (max_r_ <= 0 || r <= max_r_);
      if (keep && xs[i] > footprint_[0] && xs[i] < footprint_[1] && ys[i] > footprint_[2] &&
          ys[i] < footprint_[3])
        keep = false;
      if (keep && sector)
        keep = std::abs(std::remainder(std::atan2(dy, dx) - axis, 2 * M_PI)) <= half_fov_;
      if (!keep) labels[i] = PointLabel::Removed;
    }
  }

 private:
  double min_h_, max_h_, min_r_, max_r_, half_fov_, heading_;
  std::vector<double> footprint_;  // robot-frame box whose points are the robot itself
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc = "Keeps points in a height band above the ground and a region of interest";
  d.params = {
      ParamSpec::real("min_height", 0.6, "m", -100, 100,
                      "lowest height kept above the ground plane (P0: 0.6, drops the legs); "
                      "robot-frame z when no ground stage ran"),
      ParamSpec::real("max_height", 2.2, "m", -100, 100, "highest height kept"),
      ParamSpec::real("min_range", 0, "m", 0, 1000,
                      "nearest horizontal distance from the sensor kept"),
      ParamSpec::real("max_range", 0, "m", 0, 1000,
                      "farthest horizontal distance from the sensor kept (0: no limit)"),
      ParamSpec::real("fov", 360, "deg", 0, 360, "width of the kept sector around `heading`"),
      ParamSpec::real("heading", 0, "deg", -360, 360,
                      "centre of the kept sector, from the sensor's forward axis (+ = left)"),
      ParamSpec::vector("footprint", std::vector<double>{0, 0, 0, 0}, "m", 4, -100, 100,
                        "x_min x_max y_min y_max of a robot-frame box whose points are removed: "
                        "the robot's own body and what it carries (a wheelchair user's legs), "
                        "which move with the robot; an empty box (the default) removes nothing"),
  };
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<HeightBand>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::heightband

PEDTRACK_PLUGIN("height_band", pedtrack::heightband::describe)
