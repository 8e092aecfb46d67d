// `height_band`: keeps the points in a band of heights above the ground plane (P0 drops the
// legs below 0.6 m) and in a region of interest around the sensor; the rest are removed.
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"

namespace pedtrack::heightband {
namespace {

struct HeightBandParams {
  double min_height = 0.6, max_height = 2.2;  // m above the ground plane
  double min_range = 0, max_range = 0;        // m from the sensor; max 0: no limit
  double fov = 360 * kDegree;                 // rad, the kept sector's width
  double heading = 0;                         // rad, its centre from the sensor's forward axis
  std::vector<double> footprint{0, 0, 0, 0};  // x_min x_max y_min y_max, robot frame (m)
};

const ParamTable<HeightBandParams>& table() {
  using P = HeightBandParams;
  static const auto t =
      ParamTable<P>()
          .real(&P::min_height, "min_height", "m", -100, 100,
                "lowest height kept above the ground plane (P0: 0.6, drops the legs); "
                "robot-frame z when no ground stage ran")
          .real(&P::max_height, "max_height", "m", -100, 100, "highest height kept")
          .real(&P::min_range, "min_range", "m", 0, 1000,
                "nearest horizontal distance from the sensor kept")
          .real(&P::max_range, "max_range", "m", 0, 1000,
                "farthest horizontal distance from the sensor kept (0: no limit)")
          .real(&P::fov, "fov", "deg", 0, 360, "width of the kept sector around `heading`", kDegree)
          .real(&P::heading, "heading", "deg", -360, 360,
                "centre of the kept sector, from the sensor's forward axis (+ = left)", kDegree)
          .vector(&P::footprint, "footprint", "m", 4, -100, 100,
                  "x_min x_max y_min y_max of a robot-frame box whose points are removed: the "
                  "robot's own body and what it carries (a wheelchair user's legs), which move "
                  "with the robot; an empty box (the default) removes nothing")
          .check(&P::footprint, [](const P& p) {
            const auto& f = p.footprint;
            return f[0] > f[1] || f[2] > f[3] ? "expected x_min x_max y_min y_max with x_min <= "
                                                "x_max, y_min <= y_max"
                                              : "";
          });
  return t;
}

class HeightBand : public Segmenter {
 public:
  explicit HeightBand(const PluginContext& ctx) : p_(table().read(ctx.params)) {}

  void process(Frame& f) override {
    const auto& c = f.cloud();
    if (c.size() == 0) return;
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    const auto& zs = c.getPointsBufferRef_z();
    const GroundPlane& g = f.ground;
    const mrpt::poses::CPose3D mount = f.sensorMount();
    const double sx = mount.x(), sy = mount.y(), axis = mount.yaw() + p_.heading;
    const double half_fov = 0.5 * p_.fov;
    const bool sector = half_fov < M_PI;
    const double min_h = p_.min_height, max_h = p_.max_height;
    const double min_r = p_.min_range, max_r = p_.max_range;
    const std::vector<double>& footprint = p_.footprint;
    auto& labels = f.labels();
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (labels[i] != PointLabel::Kept) continue;
      const double h = g.heightOrZ(xs[i], ys[i], zs[i]);
      const double dx = xs[i] - sx, dy = ys[i] - sy, r = std::hypot(dx, dy);
      bool keep = h >= min_h && h <= max_h && r >= min_r && (max_r <= 0 || r <= max_r);
      if (keep && xs[i] > footprint[0] && xs[i] < footprint[1] && ys[i] > footprint[2] &&
          ys[i] < footprint[3])
        keep = false;
      if (keep && sector)
        keep = std::abs(std::remainder(std::atan2(dy, dx) - axis, 2 * M_PI)) <= half_fov;
      if (!keep) labels[i] = PointLabel::Removed;
    }
  }

 private:
  const HeightBandParams p_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc = "Keeps points in a height band above the ground and a region of interest";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<HeightBand>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::heightband

PEDTRACK_PLUGIN("height_band", pedtrack::heightband::describe)
