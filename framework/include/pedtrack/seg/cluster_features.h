#pragma once
// Per-cluster measurements of 3D clusters: P2's feature vector [h, w, d, v, λ, ρ] (§3.3, §5.1),
// computed in the ground-aligned frame (P2 rotates the cloud so the ground normal is vertical).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::seg {

/// Robot-frame points expressed with the ground as the horizontal plane: (u, v) horizontal,
/// h = height above the ground. Without a valid plane this is the robot frame itself.
class GroundAligned {
 public:
  explicit GroundAligned(const GroundPlane& g);
  Eigen::Vector3d operator()(double x, double y, double z) const {
    const Eigen::Vector3d q = R_ * Eigen::Vector3d(x, y, z);
    return {q.x(), q.y(), q.z() + offset_};
  }

 private:
  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();
  double offset_ = 0;
};

struct P2Features {
  double h = 0;       ///< highest point above the ground (eq. 17), m
  double w = 0;       ///< width: extent across the bearing from the sensor, m
  double d = 0;       ///< depth: extent along the bearing from the sensor, m
  double v = 0;       ///< bounding-box volume w·d·(h_max − h_min), m³
  double lambda = 0;  ///< top-heaviness: share of points above h/2 (eq. 18)
  double rho = 0;     ///< density of the width–height projection at `pixel` resolution
};

/// Sets a cluster's position (the centroid of its points) and extent (sizes of their bounding
/// box along the robot's axes) from `cloud`.
void setCentroidAndExtent(Cluster& c, const mrpt::maps::CSimplePointsMap& cloud);

/// The names under which voxel_ccl reports P2Features in Cluster::features (clusters.csv).
const std::vector<std::string>& p2FeatureNames();

/// Features of one cluster from its ground-aligned points; (su, sv) is the sensor's horizontal
/// position in the same frame, `pixel` the projection's cell size (P2: 10 cm).
P2Features p2Features(const std::vector<Eigen::Vector3d>& aligned, double su, double sv,
                      double pixel);

/// The shape features voxel_ccl reports after P2's (shape_features.cpp): what separates a person
/// from a post, a bush, a car or a wall fragment, and does not change with the sensor's density.
const std::vector<std::string>& shapeFeatureNames();
/// Appends them, in shapeFeatureNames() order, to `out`.
void appendShapeFeatures(const std::vector<Eigen::Vector3d>& aligned, double su, double sv,
                         std::vector<double>& out);

}  // namespace pedtrack::seg
