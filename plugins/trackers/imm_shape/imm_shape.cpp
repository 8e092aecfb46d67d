// imm_shape (P1): pedestrians tracked by their torso through an IMM over three observation
// models of one random-walk state [x, y, θ, v, α, β] — the RANSAC ellipse (P1 §III-B), the
// bounding box and the point cloud's centre of gravity — whose observation dimension switches
// with the point count (eq. 18), so a person stays one track from dense to sparse clouds. Q, R
// and Π default to P1 Table I; the per-track model probabilities go to `model_probs`
// (ellipse;box;cog).
#include <cmath>
#include <memory>

#include "pedtrack/plugin.h"
#include "pedtrack/track/shape_tracker.h"

namespace pedtrack::immshape {
namespace {

using namespace pedtrack::track;

// The IMM over the ellipse, box and COG models (ShapeTrackerParams' default models), with Π
// from the `transition` key, row by row.
const ParamTable<ShapeTrackerParams>& table() {
  using P = ShapeTrackerParams;
  static const auto t =
      ParamTable<P>()
          .append(ShapeTracker::commonTable())
          .append(ShapeTracker::ellipseTable())
          .append(ShapeTracker::boxTable())
          .vector(&P::transition, "transition", "", 9, 0, 1,
                  "Pi (P1 Table I): model switching probabilities, row by row (ellipse, box, "
                  "cog)")
          .check(&P::transition, [](const P& p) {
            for (int i = 0; i < 3; ++i)
              if (std::abs(p.transition.row(i).sum() - 1) > 1e-6)
                return "row " + std::to_string(i + 1) + " does not sum to 1";
            return std::string();
          });
  return t;
}

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Tracker;
  d.doc = "P1: IMM over ellipse (RANSAC), bounding-box and point-cloud-COG observation models";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<ShapeTrackerStage>(table().read(ctx.params));
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::immshape

PEDTRACK_PLUGIN("imm_shape", pedtrack::immshape::describe)
