// `leg_circles`: P3 §2.2 leg detection. Each segment of a 2D segmenter (scan_segments) gets the
// bounded circle fit of P3 eq. 1; circular ones become the frame's clusters (centre = the
// circle's), with the segment's features plus `leg_radius` and `leg_residual`; a leg that
// several scanners of the frame saw becomes one cluster (seg::mergeLegs), and legs are paired
// into person candidates (Cluster::pair). With split_jump (ours), a segment that is no leg but
// two, one just behind the other (a person standing with one foot ahead), is cut between them.
#include <algorithm>

#include "leg_circles/leg_detection.h"
#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/seg/cluster_features.h"
#include "pedtrack/seg/scan_segments.h"

namespace pedtrack::legcircles {
namespace {

struct LegCirclesParams {
  seg::LegParams leg;           // P3 eq. 1's bounds and the acceptance tests (leg_detection.h)
  double pair_distance = 0.8;   // m: legs at most this far apart may be one person's
  double merge_distance = 0.1;  // m: one leg seen by several scanners; 0: never merged
  double split_jump = 0;        // m: a segment that is no leg splits at a range step this large
  int split_min_points = 3;     // each part of a split needs this many points
};

const ParamTable<LegCirclesParams>& table() {
  using P = LegCirclesParams;
  using L = seg::LegParams;
  static const auto t =
      ParamTable<P>()
          .real(path(&P::leg, &L::r_min), "min_radius", "m", 0, 1, "smallest leg radius (P3: 0.03)")
          .real(path(&P::leg, &L::r_max), "max_radius", "m", 0.001, 1,
                "largest leg radius (P3: 0.07)")
          .real(path(&P::leg, &L::max_residual), "max_residual", "m", 0, 1,
                "segments whose points lie farther from the circle (RMS) are not legs")
          .integer(path(&P::leg, &L::min_points), "min_points", "", 3, 100000,
                   "segments with fewer points are not legs (P3: 3)")
          .boolean(path(&P::leg, &L::require_convex), "require_convex",
                   "reject arcs whose circle centre is nearer the sensor than their points "
                   "(concave toward it); P3 has no such test")
          .real(&P::pair_distance, "pair_distance", "m", 0, 10,
                "two legs whose centres are at most this far apart may pair into a person")
          .real(&P::merge_distance, "merge_distance", "m", 0, 1,
                "legs of different scans (several scanners) whose centres are closer than this "
                "are one leg, refitted on all their points; 0: never merged")
          .real(&P::split_jump, "split_jump", "m", 0, 10,
                "ours: a segment that is no leg as a whole is cut at its largest range step "
                "between consecutive points when that is at least this, and when both parts are "
                "legs each becomes one (both legs of a person standing with one foot ahead, "
                "closer than the segmenter's gap); 0: off (P3)")
          .integer(&P::split_min_points, "split_min_points", "", 3, 100000,
                   "points each part of a split segment needs (a circle fitted to a few returns "
                   "says little)")
          .check(path(&P::leg, &L::r_max), [](const P& p) {
            return p.leg.r_max < p.leg.r_min
                       ? "below min_radius (" + shortestNumber(p.leg.r_min) + ")"
                       : std::string();
          });
  return t;
}

class LegCircles : public Segmenter {
 public:
  explicit LegCircles(const PluginContext& ctx) : LegCircles(table().read(ctx.params)) {}
  explicit LegCircles(const LegCirclesParams& p)
      : p_(p.leg),
        pair_distance_(p.pair_distance),
        merge_distance_(p.merge_distance),
        split_jump_(p.split_jump),
        split_min_points_(p.split_min_points) {}

  void process(Frame& f) override {
    const auto& c = f.cloud();
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    const std::vector<seg::ScanRun> runs = seg::scanRuns(f, false);
    std::vector<Cluster> legs;
    std::vector<seg::ScanLeg> found;
    legs.reserve(f.clusters.size());
    fit::Points2 pts;
    // Split parts get scan_segments' features recomputed: only segments that carry them split.
    const bool split = split_jump_ > 0 && segmentFeatured(f);
    for (Cluster& cl : f.clusters) {
      if (cl.indices.empty()) continue;
      // The scan the segment came from: the last run starting at or before its first point.
      const std::uint32_t first = cl.indices.front();
      auto run =
          std::upper_bound(runs.begin(), runs.end(), first,
                           [](std::uint32_t i, const seg::ScanRun& r) { return i < r.first; });
      if (run == runs.begin()) continue;
      --run;
      if (first >= run->first + run->count) continue;  // not from a 2D scan (a 3D cluster)
      pts.clear();
      for (std::uint32_t i : cl.indices) pts.emplace_back(xs[i], ys[i]);
      seg::Leg leg;
      const std::size_t scan = std::size_t(run - runs.begin());
      if (!seg::detectLeg(pts, run->sx, run->sy, p_, leg)) {
        if (split) splitLegs(cl, pts, *run, scan, c, legs, found);
        continue;
      }
      addLeg(std::move(cl), leg, pts, scan, legs, found);
    }
    if (runs.size() > 1 && merge_distance_ > 0) legs = merged(std::move(legs), found, c);
    std::vector<Eigen::Vector2d> centres;
    for (const Cluster& cl : legs) centres.emplace_back(cl.cx, cl.cy);
    const std::vector<int> partner = seg::pairLegs(centres, pair_distance_);
    for (std::size_t i = 0; i < legs.size(); ++i) legs[i].pair = partner[i];
    f.clusters = std::move(legs);
    f.cluster_feature_names = names(f.cluster_feature_names);
  }

 private:
  static void addLeg(Cluster cl, const seg::Leg& leg, const fit::Points2& pts, std::size_t scan,
                     std::vector<Cluster>& legs, std::vector<seg::ScanLeg>& found) {
    cl.cx = leg.circle.x;
    cl.cy = leg.circle.y;
    cl.features.push_back(leg.circle.r);
    cl.features.push_back(leg.residual);
    found.push_back({leg, scan, pts});
    legs.push_back(std::move(cl));
  }

  static std::size_t featureIndex(const std::string& name) {
    const auto& n = seg::segmentFeatureNames();
    return std::size_t(std::find(n.begin(), n.end(), name) - n.begin());
  }

  // Whether the clusters carry scan_segments' features (split parts get theirs recomputed).
  static bool segmentFeatured(const Frame& f) {
    return f.cluster_feature_names && *f.cluster_feature_names == seg::segmentFeatureNames();
  }

  // A segment that is no leg, cut at its largest range step (split_jump): when both parts are
  // legs, each becomes a cluster with its own segment features, the step being its jump feature
  // on the cut side (positive for the nearer part: it stands in front).
  void splitLegs(const Cluster& cl, const fit::Points2& pts, const seg::ScanRun& run,
                 std::size_t scan, const mrpt::maps::CSimplePointsMap& cloud,
                 std::vector<Cluster>& legs, std::vector<seg::ScanLeg>& found) const {
    seg::LegParams split = p_;
    split.min_points = std::max(p_.min_points, split_min_points_);
    double step = 0;
    const std::size_t cut = seg::legSplitPoint(pts, run.sx, run.sy, split_jump_, split, &step);
    if (cut == 0) return;
    static const std::size_t kJumpPrev = featureIndex("jump_prev"),
                             kJumpNext = featureIndex("jump_next");
    seg::Leg parts[2];
    fit::Points2 subs[2] = {fit::Points2(pts.begin(), pts.begin() + cut),
                            fit::Points2(pts.begin() + cut, pts.end())};
    for (int part = 0; part < 2; ++part)
      if (!seg::detectLeg(subs[part], run.sx, run.sy, split, parts[part])) return;
    for (int part = 0; part < 2; ++part) {
      const std::size_t from = part ? cut : 0, to = part ? pts.size() : cut;
      const fit::Points2& sub = subs[part];
      const seg::Leg& leg = parts[part];
      Cluster piece;
      piece.indices.assign(cl.indices.begin() + from, cl.indices.begin() + to);
      seg::setCentroidAndExtent(piece, cloud);
      piece.features =
          seg::segmentFeatures(sub, run.sx, run.sy, part ? -step : cl.features[kJumpPrev],
                               part ? cl.features[kJumpNext] : step);
      addLeg(std::move(piece), leg, sub, scan, legs, found);
    }
  }

  // One cluster per merged leg: the members' points together, the largest member's segment
  // features (one scan's view of the leg, as the classifiers were trained on), the merged circle.
  std::vector<Cluster> merged(std::vector<Cluster> legs, const std::vector<seg::ScanLeg>& found,
                              const mrpt::maps::CSimplePointsMap& cloud) const {
    std::vector<Cluster> out;
    for (const seg::MergedLeg& m : seg::mergeLegs(found, merge_distance_, p_)) {
      if (m.members.size() == 1) {
        out.push_back(std::move(legs[m.members[0]]));
        continue;
      }
      std::size_t largest = m.members[0];
      for (std::size_t i : m.members)
        if (legs[i].indices.size() > legs[largest].indices.size()) largest = i;
      Cluster cl;
      for (std::size_t i : m.members)
        cl.indices.insert(cl.indices.end(), legs[i].indices.begin(), legs[i].indices.end());
      seg::setCentroidAndExtent(cl, cloud);
      cl.cx = m.leg.circle.x;
      cl.cy = m.leg.circle.y;
      cl.features = std::move(legs[largest].features);
      cl.features[cl.features.size() - 2] = m.leg.circle.r;
      cl.features.back() = m.leg.residual;
      out.push_back(std::move(cl));
    }
    return out;
  }

  // The segmenter's feature names plus ours, made once per distinct list.
  std::shared_ptr<const std::vector<std::string>> names(
      const std::shared_ptr<const std::vector<std::string>>& upstream) {
    if (upstream != upstream_ || !names_) {
      upstream_ = upstream;
      auto v = upstream ? *upstream : std::vector<std::string>();
      v.push_back("leg_radius");
      v.push_back("leg_residual");
      names_ = std::make_shared<const std::vector<std::string>>(std::move(v));
    }
    return names_;
  }

  seg::LegParams p_;
  double pair_distance_, merge_distance_, split_jump_;
  int split_min_points_;
  std::shared_ptr<const std::vector<std::string>> upstream_, names_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc = "Leg circles (P3 eq. 1) on 2D segments, paired into person candidates";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<LegCircles>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::legcircles

PEDTRACK_PLUGIN("leg_circles", pedtrack::legcircles::describe)
