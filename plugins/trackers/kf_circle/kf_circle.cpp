// kf_circle (P0 §VI's KF-circle baseline, after P0 ref. 15): one filter on the torso state
// [x, y, θ, v, α, β] of P1 observing a RANSAC circle fitted to each person's points — its centre
// and radius (the mean semi-axis) — with the association and track management of imm_shape.
// A circle has no orientation: the heading comes from the motion alone.
#include <memory>

#include "pedtrack/plugin.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::kfcircle {
namespace {

using namespace pedtrack::track;

const ParamTable<ShapeTrackerParams>& table() {
  static const auto t = ParamTable<ShapeTrackerParams>()
                            .append(ShapeTracker::commonTable())
                            .append(ShapeTracker::circleTable());
  return t;
}

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P0's KF-circle: one EKF on RANSAC circle observations [x, y, radius]";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    ShapeTrackerParams p = table().read(ctx.params);
    p.models = {ShapeModel::Circle};
    p.transition = Eigen::MatrixXd::Identity(1, 1);
    return std::make_unique<ShapeTrackerStage>(std::move(p));
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::kfcircle

PEDTRACK_PLUGIN("kf_circle", pedtrack::kfcircle::describe)
