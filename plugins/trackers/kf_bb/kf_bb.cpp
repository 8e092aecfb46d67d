// kf_bb (P0 §VI's KF-BB baseline; P1 Fig. 11's single bounding-box EKF): one filter on the
// torso state [x, y, θ, v, α, β] of P1 observing the bounding box of each person's points —
// centre, orientation and half-sides — with the association and track management of imm_shape.
#include <memory>

#include "pedtrack/plugin.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::kfbb {
namespace {

using namespace pedtrack::track;

const ParamTable<ShapeTrackerParams>& table() {
  static const auto t = ParamTable<ShapeTrackerParams>()
                            .append(ShapeTracker::commonTable())
                            .append(ShapeTracker::boxTable());
  return t;
}

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P0's KF-BB: one EKF on bounding-box observations [x, y, theta, alpha, beta]";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    ShapeTrackerParams p = table().read(ctx.params);
    p.models = {ShapeModel::Box};
    p.transition = Eigen::MatrixXd::Identity(1, 1);
    return std::make_unique<ShapeTrackerStage>(std::move(p));
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::kfbb

PEDTRACK_PLUGIN("kf_bb", pedtrack::kfbb::describe)
