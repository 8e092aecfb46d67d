#include "irls_ground/plane.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace pedtrack::fit {

void PlaneMoments::add(const Eigen::Vector3d& p, double w) {
  if (!(w > 0)) return;
  if (used_ == 0) ref_ = p;
  const Eigen::Vector3d q = p - ref_;
  sw_ += w;
  s1_ += w * q;
  s2_.noalias() += w * q * q.transpose();
  ++used_;
}

GroundPlane PlaneMoments::plane() const {
  GroundPlane out;
  if (used_ < 3 || !(sw_ > 0)) return out;
  const Eigen::Vector3d c = s1_ / sw_;  // centroid, relative to ref_
  const Eigen::Matrix3d M = s2_ - sw_ * c * c.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
  Eigen::Vector3d n = es.eigenvectors().col(0);  // eigenvalues ascending
  if (n.z() < 0) n = -n;
  out.valid = std::isfinite(n.x()) && n.norm() > 0.5;
  out.nx = n.x();
  out.ny = n.y();
  out.nz = n.z();
  out.d = -n.dot(c + ref_);
  return out;
}

GroundPlane fitPlaneWeighted(const std::vector<Eigen::Vector3d>& pts,
                             const std::vector<double>& weights) {
  if (weights.size() != pts.size()) return GroundPlane();
  PlaneMoments m;
  for (std::size_t i = 0; i < pts.size(); ++i) m.add(pts[i], weights[i]);
  return m.plane();
}

}  // namespace pedtrack::fit
