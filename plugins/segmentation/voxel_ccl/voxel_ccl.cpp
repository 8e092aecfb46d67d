// `voxel_ccl`: P2 §3.2's segmentation — the remaining points voxelised in the ground-aligned
// frame, 6/18/26-connected components labelled, small ones dropped, and each cluster described
// by P2's [h, w, d, v, λ, ρ] with its centroid and extent.
#include <algorithm>
#include <cmath>
#include <limits>

#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/seg/cluster_features.h"
#include "voxel_ccl/crowd_split.h"
#include "voxel_ccl/voxel_labelling.h"

namespace pedtrack::voxelccl {
namespace {

// floor() of a value known to fit an int, without the libm call.
int floorInt(double x) {
  const int i = static_cast<int>(x);
  return i - (x < i);
}

struct VoxelCclParams {
  double voxel = 0.10;                      // m, horizontal side
  double voxel_height = 0;                  // m, vertical side; 0: voxel
  bool p2_grid = false;                     // P2's 64 x 50 x 100 image in front of the sensor
  double max_range = 30;                    // m (range grid)
  double min_height = 0, max_height = 2.2;  // m above the ground (range grid)
  seg::Connectivity connectivity = seg::Connectivity::TwentySix;
  long min_points = 5;
  bool split = false;  // ours (#45); P2 keeps every component whole
  CrowdSplitParams crowd;
};

const ParamTable<VoxelCclParams>& table() {
  using P = VoxelCclParams;
  const auto crowd = [](auto member) { return path(&P::crowd, member); };
  static const auto t =
      ParamTable<P>()
          .real(&P::voxel, "voxel", "m", 0.01, 5, "horizontal voxel side (P2: 10 cm)")
          .real(&P::voxel_height, "voxel_height", "m", 0, 10,
                "vertical voxel side (0: the same as voxel, P2's cubes)")
          .choice(&P::p2_grid, "grid", {{"range", false}, {"p2", true}},
                  "range: every point within max_range and the height band; p2: P2's "
                  "64 x 50 x 100-voxel image in front of the sensor (6.4 x 5 x 10 m at 10 cm)")
          .real(&P::max_range, "max_range", "m", 0.1, 1000,
                "grid = range: farthest horizontal distance from the sensor")
          .real(&P::min_height, "min_height", "m", -100, 100,
                "grid = range: lowest height above the ground plane (robot-frame z without a "
                "ground stage)")
          .real(&P::max_height, "max_height", "m", -100, 100, "grid = range: highest height")
          .choice(&P::connectivity, "connectivity",
                  {{"6", seg::Connectivity::Six},
                   {"18", seg::Connectivity::Eighteen},
                   {"26", seg::Connectivity::TwentySix}},
                  "voxel neighbourhood: faces (6), + edges (18), + corners (26)")
          .integer(&P::min_points, "min_points", "", 1, 1000000,
                   "components with fewer points are dropped (left unclustered)")
          .boolean(&P::split, "split",
                   "ours: a component with two or more heads (peaks of its height map "
                   "split_head_dip apart) is split into one cluster per person")
          .real(crowd(&CrowdSplitParams::min_head), "split_min_head", "m", 0, 5,
                "split: the lowest head above the ground (a child)")
          .real(crowd(&CrowdSplitParams::head_dip), "split_head_dip", "", 0.01, 1,
                "split: how far the highest returns between two heads lie below the lower "
                "head, as a share of its height (head and neck: 0.25 m of an adult 1.75 m tall)")
          .real(crowd(&CrowdSplitParams::min_spacing), "split_min_spacing", "m", 0.05, 5,
                "split: the closest two heads (people shoulder to shoulder)")
          .real(crowd(&CrowdSplitParams::max_extent), "split_max_extent", "m", 0.5, 100,
                "split: components whose horizontal bounding box has a longer diagonal are walls "
                "or hedges and stay whole")
          .real(crowd(&CrowdSplitParams::min_share), "split_min_share", "", 0, 0.5,
                "split: a head left with a smaller share of the component's points is an arm "
                "or a bag, not a person")
          .real(crowd(&CrowdSplitParams::top_elevation), "split_top_elevation", "deg", 0, 90,
                "split: the sensor's highest beam above its horizon (VLP-16: 15, HDL-64: 2; "
                "0: no limit): a peak within 0.5 deg of it is where the view ends, not a head");
  return t;
}

// P2's six features, then the shape features (cluster_features.h).
std::vector<std::string> featureNames() {
  std::vector<std::string> n = seg::p2FeatureNames();
  const auto& more = seg::shapeFeatureNames();
  n.insert(n.end(), more.begin(), more.end());
  return n;
}

class VoxelCcl : public Segmenter {
 public:
  explicit VoxelCcl(const PluginContext& ctx) : VoxelCcl(table().read(ctx.params)) {}
  explicit VoxelCcl(const VoxelCclParams& p)
      : voxel_(p.voxel),
        voxel_h_(p.voxel_height > 0 ? p.voxel_height : voxel_),
        p2_grid_(p.p2_grid),
        max_range_(p.max_range),
        min_h_(p.min_height),
        max_h_(p.max_height),
        min_points_(std::size_t(p.min_points)),
        connectivity_(p.connectivity),
        split_(p.split),
        crowd_(p.crowd),
        names_(std::make_shared<const std::vector<std::string>>(featureNames())) {}

  void process(Frame& f) override {
    const auto& c = f.cloud();
    f.clusters.clear();
    f.cluster_feature_names = names_;
    if (c.size() == 0) return;
    const auto& xs = c.getPointsBufferRef_x();
    const auto& ys = c.getPointsBufferRef_y();
    const auto& zs = c.getPointsBufferRef_z();
    const seg::GroundAligned align(f.ground);
    const mrpt::poses::CPose3D mount = f.sensorMount();
    const Eigen::Vector3d s = align(mount.x(), mount.y(), mount.z());
    // The sensor's forward axis on the ground (P2's grid lies in front of the sensor).
    const Eigen::Vector3d ahead =
        align(mount.x() + std::cos(mount.yaw()), mount.y() + std::sin(mount.yaw()), mount.z()) - s;
    const double fx = ahead.x() / std::hypot(ahead.x(), ahead.y()),
                 fy = ahead.y() / std::hypot(ahead.x(), ahead.y());
    auto& labels = f.labels();
    index_.clear();
    voxels_.clear();
    aligned_.clear();
    const double inv = 1.0 / voxel_, inv_h = 1.0 / voxel_h_;
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (labels[i] != PointLabel::Kept) continue;
      const Eigen::Vector3d q = align(xs[i], ys[i], zs[i]);
      const double du = q.x() - s.x(), dv = q.y() - s.y();
      // Bounds are tested on the doubles: only points inside (finite, bounded) are cast.
      double v[3];
      bool inside;
      if (p2_grid_) {  // 100 voxels ahead, 64 across, 50 up (P2's 64 × 50 × 100 image)
        v[0] = (fx * du + fy * dv) * inv;
        v[1] = (-fy * du + fx * dv) * inv + 32;
        v[2] = q.z() * inv_h;
        inside = v[0] >= 0 && v[0] < 100 && v[1] >= 0 && v[1] < 64 && v[2] >= 0 && v[2] < 50;
      } else {
        v[0] = q.x() * inv;
        v[1] = q.y() * inv;
        v[2] = q.z() * inv_h;
        inside = du * du + dv * dv <= max_range_ * max_range_ && q.z() >= min_h_ &&
                 q.z() <= max_h_ && std::abs(v[0]) < 1e8 && std::abs(v[1]) < 1e8;
      }
      if (!inside) {  // NaN coordinates fail every comparison and land here too
        labels[i] = PointLabel::Removed;
        continue;
      }
      voxels_.push_back({floorInt(v[0]), floorInt(v[1]), floorInt(v[2])});
      index_.push_back(std::uint32_t(i));
      aligned_.push_back(q);
    }
    const int count = labeler_.label(voxels_, connectivity_, component_);
    // Points grouped by component (counting sort), then one cluster per large component.
    start_.assign(count + 1, 0);
    for (int k : component_) ++start_[k + 1];
    for (int k = 0; k < count; ++k) start_[k + 1] += start_[k];
    order_.resize(component_.size());
    fill_ = start_;
    for (std::size_t j = 0; j < component_.size(); ++j) order_[fill_[component_[j]]++] = j;
    for (int k = 0; k < count; ++k) {
      const std::size_t n = start_[k + 1] - start_[k];
      if (n < min_points_) continue;
      int people = 1;
      if (split_) {
        component_pts_.clear();
        for (std::size_t m = start_[k]; m < start_[k + 1]; ++m)
          component_pts_.push_back(aligned_[order_[m]]);
        people = splitCrowd(component_pts_, s, crowd_, part_);
      }
      for (int person = 0; person < people; ++person) {
        Cluster cl;
        pts_.clear();
        for (std::size_t m = start_[k]; m < start_[k + 1]; ++m) {
          if (people > 1 && part_[m - start_[k]] != person) continue;
          cl.indices.push_back(index_[order_[m]]);
          pts_.push_back(aligned_[order_[m]]);
        }
        if (pts_.size() < min_points_) continue;  // left unclustered, as a small component
        seg::setCentroidAndExtent(cl, c);
        const seg::P2Features ft = seg::p2Features(pts_, s.x(), s.y(), voxel_);
        cl.features = {ft.h, ft.w, ft.d, ft.v, ft.lambda, ft.rho};
        seg::appendShapeFeatures(pts_, s.x(), s.y(), cl.features);
        f.clusters.push_back(std::move(cl));
      }
    }
  }

 private:
  double voxel_, voxel_h_;
  bool p2_grid_;
  double max_range_, min_h_, max_h_;
  std::size_t min_points_;
  seg::Connectivity connectivity_;
  bool split_;
  CrowdSplitParams crowd_;
  std::shared_ptr<const std::vector<std::string>> names_;
  seg::VoxelLabeler labeler_;
  // Per-frame buffers, reused.
  std::vector<std::uint32_t> index_;
  std::vector<seg::Voxel> voxels_;
  std::vector<Eigen::Vector3d> aligned_;
  std::vector<int> component_;
  std::vector<std::size_t> start_, fill_, order_;
  std::vector<Eigen::Vector3d> component_pts_, pts_;
  std::vector<int> part_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Segmenter;
  d.doc =
      "Voxel connected components (P2 s3.2) with P2's features [h, w, d, v, lambda, rho] and "
      "shape features (range, principal axes, height-slice profile, density, head)";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<VoxelCcl>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::voxelccl

PEDTRACK_PLUGIN("voxel_ccl", pedtrack::voxelccl::describe)
