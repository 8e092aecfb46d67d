// `scan_segments`: 2D scans split into segments where consecutive returns are farther apart
// than a gap (P4 §2.1's range discontinuities), each segment a cluster with the features torso
// and leg classifiers use, among them a direct least-squares ellipse fit and a circle fit.
#include "pedtrack/seg/scan_segments.h"

#include <cmath>

#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/seg/cluster_features.h"

namespace pedtrack::scansegments {
namespace {

const ParamTable<seg::SegmentParams>& table() {
  using P = seg::SegmentParams;
  static const auto t =
      ParamTable<P>()
          .real(&P::gap, "gap", "m", 0.001, 10,
                "consecutive returns farther apart start a new segment")
          .integer(&P::max_missing, "max_missing", "", -1, 100000,
                   ">= 0: more beams than this without a return between two returns also start "
                   "a new segment (a discontinuity: those beams saw past both); -1: only the gap "
                   "counts")
          .integer(&P::min_points, "min_points", "", 1, 100000, "shorter segments are dropped")
          .real(&P::adaptive_angle, "adaptive_angle", "deg", 0, 89,
                "> 0: the gap grows with range as an adaptive breakpoint detector (Borges & "
                "Aldon 2004) with this incidence angle; 0: a fixed gap",
                kDegree);
  return t;
}

class ScanSegments : public Segmenter {
 public:
  explicit ScanSegments(const PluginContext& ctx)
      : p_(table().read(ctx.params)),
        names_(std::make_shared<const std::vector<std::string>>(seg::segmentFeatureNames())) {}

  void process(Frame& f) override {
    f.clusters.clear();
    f.cluster_feature_names = names_;
    const auto& c = f.cloud();
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    fit::Points2 pts;
    for (const seg::ScanRun& run : seg::scanRuns(f, p_.max_missing >= 0)) {
      auto range = [&](std::size_t i) {
        const double dx = xs[i] - run.sx, dy = ys[i] - run.sy;
        return std::sqrt(dx * dx + dy * dy);
      };
      const std::size_t end = run.first + run.count;
      auto segments = seg::splitRun(f, run, p_);
      f.clusters.reserve(f.clusters.size() + segments.size());
      for (auto& segment : segments) {
        // The kept returns just outside the segment, for the jump features.
        double jp = 0, jn = 0;
        for (std::size_t i = segment.front(); i-- > run.first;)
          if (f.isKept(i)) {
            jp = range(i) - range(segment.front());
            break;
          }
        for (std::size_t i = segment.back() + 1; i < end; ++i)
          if (f.isKept(i)) {
            jn = range(i) - range(segment.back());
            break;
          }
        pts.clear();
        for (std::uint32_t i : segment) pts.emplace_back(xs[i], ys[i]);
        Cluster cl;
        cl.indices = std::move(segment);
        seg::setCentroidAndExtent(cl, c);
        cl.features = seg::segmentFeatures(pts, run.sx, run.sy, jp, jn);
        f.clusters.push_back(std::move(cl));
      }
    }
  }

 private:
  const seg::SegmentParams p_;
  std::shared_ptr<const std::vector<std::string>> names_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc = "2D scan segments (P4 s2.1) with torso/leg features, ellipse and circle fits";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ScanSegments>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::scansegments

PEDTRACK_PLUGIN("scan_segments", pedtrack::scansegments::describe)
