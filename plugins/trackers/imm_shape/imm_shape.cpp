// imm_shape (P1): pedestrians tracked by their torso through an IMM over three observation
// models of one random-walk state [x, y, θ, v, α, β] — the RANSAC ellipse (P1 §III-B), the
// bounding box and the point cloud's centre of gravity — whose observation dimension switches
// with the point count (eq. 18), so a person stays one track from dense to sparse clouds. Q, R
// and Π default to P1 Table I; the per-track model probabilities go to `model_probs`
// (ellipse;box;cog).
#include <cmath>
#include <memory>

#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::immshape {
namespace {

using namespace pedtrack::track;

// Π from the `transition` key, row by row; rows must sum to 1.
Eigen::MatrixXd transition(const ParamSet& s) {
  const std::vector<double> pi = s.getVector("transition");
  const Eigen::MatrixXd t =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(pi.data());
  for (int i = 0; i < 3; ++i)
    if (std::abs(t.row(i).sum() - 1) > 1e-6)
      throw ConfigError(s.where("transition") + ": row " + std::to_string(i + 1) +
                        " does not sum to 1");
  return t;
}

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P1: IMM over ellipse (RANSAC), bounding-box and point-cloud-COG observation models";
  d.params = ShapeTracker::commonParams();
  for (auto group : {ShapeTracker::ellipseParams(), ShapeTracker::boxParams()})
    d.params.insert(d.params.end(), group.begin(), group.end());
  d.params.push_back(ParamSpec::vector(
      "transition", std::vector<double>{0.99, 0.005, 0.005, 0.005, 0.99, 0.005, 0.005, 0.005, 0.99},
      "", 9, 0, 1,
      "Pi (P1 Table I): model switching probabilities, row by row (ellipse, box, cog)"));
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ShapeTrackerStage>(
        ctx.params, std::vector<ShapeModel>{ShapeModel::Ellipse, ShapeModel::Box, ShapeModel::Cog},
        transition(ctx.params));
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::immshape

PEDTRACK_PLUGIN("imm_shape", pedtrack::immshape::describe)
