// range_gate: a segmenter that keeps the points within [min_range, max_range] of the sensor as
// one region-of-interest cluster. An example of a third-party plugin: one file, parameters
// declared once, built against the installed framework.
#include <pedtrack/param_table.h>
#include <pedtrack/plugin.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

// The parameters: the struct's initialisers are the defaults, the table binds each INI key to
// its member once (name, unit, range, doc), and a rule checks what one key cannot.
struct RangeGateParams {
  double min_range = 0.1;  // m
  double max_range = 8.0;  // m
};

const pedtrack::ParamTable<RangeGateParams>& table() {
  using P = RangeGateParams;
  static const auto t =
      pedtrack::ParamTable<P>()
          .real(&P::min_range, "min_range", "m", 0, 1000, "closest range kept")
          .real(&P::max_range, "max_range", "m", 0, 1000, "farthest range kept")
          .check(&P::max_range, [](const P& p) {
            return p.max_range < p.min_range ? std::string("below min_range") : std::string();
          });
  return t;
}

class RangeGate : public pedtrack::Segmenter {
 public:
  explicit RangeGate(const RangeGateParams& p) : min_(p.min_range), max_(p.max_range) {}

  void process(pedtrack::Frame& frame) override {
    const auto& cloud = frame.cloud();  // robot frame
    const auto& xs = cloud.getPointsBufferRef_x();
    const auto& ys = cloud.getPointsBufferRef_y();
    pedtrack::Cluster roi;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double r = std::hypot(xs[i], ys[i]);
      if (r >= min_ && r <= max_) roi.indices.push_back(static_cast<std::uint32_t>(i));
    }
    kept_ += roi.indices.size();
    total_ += xs.size();
    ++frames_;
    frame.clusters.push_back(std::move(roi));
  }

  void finish() override {
    std::fprintf(stderr, "range_gate: kept %zu of %zu points in %zu frames\n", kept_, total_,
                 frames_);
  }

 private:
  double min_, max_;
  std::size_t kept_ = 0, total_ = 0, frames_ = 0;
};

pedtrack::PluginDescriptor describe() {
  pedtrack::PluginDescriptor d;
  d.category = pedtrack::Category::Segmenter;
  d.doc = "Keeps the points within a range band as one region-of-interest cluster (example plugin)";
  d.params = table().specs();
  d.create = [](const pedtrack::PluginContext& ctx) -> std::unique_ptr<pedtrack::Plugin> {
    return std::make_unique<RangeGate>(table().read(ctx.params));
  };
  return d;
}

}  // namespace

PEDTRACK_PLUGIN("range_gate", describe)
