#pragma once
// Weighted least-squares plane fit.
#include <Eigen/Core>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::fit {

/// Weighted moments of 3D points, accumulated in one pass, and the plane they give.
class PlaneMoments {
 public:
  void add(const Eigen::Vector3d& p, double w);
  /// Minimises Σ wᵢ (n·pᵢ + d)² over unit normals n: the total-least-squares plane through the
  /// weighted centroid, n the least eigenvector of the weighted scatter, oriented to +z. Invalid
  /// when the weights sum to zero or fewer than 3 points have weight.
  GroundPlane plane() const;

 private:
  Eigen::Vector3d ref_ = Eigen::Vector3d::Zero();  // first point: moments about it (precision)
  Eigen::Vector3d s1_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d s2_ = Eigen::Matrix3d::Zero();
  double sw_ = 0;
  int used_ = 0;
};

/// PlaneMoments over `pts` with `weights` (invalid when the two lists differ in length).
GroundPlane fitPlaneWeighted(const std::vector<Eigen::Vector3d>& pts,
                             const std::vector<double>& weights);

}  // namespace pedtrack::fit
