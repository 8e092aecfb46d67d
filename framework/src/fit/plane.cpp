#include "pedtrack/fit/plane.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace pedtrack::fit {

GroundPlane fitPlaneWeighted(const std::vector<Eigen::Vector3d>& pts,
                             const std::vector<double>& weights) {
  GroundPlane out;
  if (weights.size() != pts.size()) return out;
  double sw = 0;
  int used = 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!(weights[i] > 0)) continue;
    sw += weights[i];
    c += weights[i] * pts[i];
    ++used;
  }
  if (used < 3 || !(sw > 0)) return out;
  c /= sw;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!(weights[i] > 0)) continue;
    const Eigen::Vector3d q = pts[i] - c;
    M += weights[i] * q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
  Eigen::Vector3d n = es.eigenvectors().col(0);  // eigenvalues ascending
  if (n.z() < 0) n = -n;
  out.valid = std::isfinite(n.x()) && n.norm() > 0.5;
  out.nx = n.x();
  out.ny = n.y();
  out.nz = n.z();
  out.d = -n.dot(c);
  return out;
}

}  // namespace pedtrack::fit
