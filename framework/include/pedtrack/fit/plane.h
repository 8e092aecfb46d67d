#pragma once
// Weighted least-squares plane fit.
#include <Eigen/Core>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::fit {

/// Minimises Σ wᵢ (n·pᵢ + d)² over unit normals n (the total-least-squares plane through the
/// weighted centroid, n the scatter's least eigenvector), n oriented to +z. Invalid when the
/// weights sum to zero, fewer than 3 points have weight or the two lists differ in length.
GroundPlane fitPlaneWeighted(const std::vector<Eigen::Vector3d>& pts,
                             const std::vector<double>& weights);

}  // namespace pedtrack::fit
