#pragma once
// Solid primitives the simulator ray-casts: everything in a scene (torsos, heads, limbs, walls,
// poles, trees) is one of four shapes, so one intersection routine per shape covers the world.
#include <Eigen/Core>
#include <limits>

namespace pedtrack::sim {

constexpr double kNoHit = std::numeric_limits<double>::infinity();

enum class Shape {
  EllipticCylinder,  ///< vertical; semi-axis `ru` along `yaw`, `rv` across it; z in [z0, z1]
  Sphere,            ///< centre `a`, radius `ru`
  Capsule,           ///< segment a–b, radius `ru` (limbs)
  Box                ///< vertical; half sizes `ru` along `yaw`, `rv` across; z in [z0, z1]
};

/// Who a returned point belongs to, encoded as the truth labels of point_labels.h: the ground
/// (0), a person (its id, >= 1) or a static object (minus its id, objects being numbered from 1
/// in the order the scenario declares them).
constexpr int kOwnerGround = 0;
inline int objectOwner(int object_id) {
  return -object_id;
}

struct Primitive {
  Shape shape = Shape::Sphere;
  int owner = kOwnerGround;
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  ///< centre (cylinder/box: x, y of the axis)
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  ///< capsule end
  double ru = 0, rv = 0;
  double yaw = 0;
  double z0 = 0, z1 = 0;
  /// m, foliage (a tree crown, a bush, a hedge): a ray that enters goes on for an exponential
  /// depth of this mean before it returns, and passes through when that is deeper than the
  /// volume; 0: a solid surface.
  double foliage = 0;

  static Primitive ellipticCylinder(double x, double y, double yaw, double ru, double rv, double z0,
                                    double z1, int owner);
  static Primitive sphere(const Eigen::Vector3d& c, double r, int owner);
  static Primitive capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r, int owner);
  static Primitive box(double x, double y, double yaw, double half_u, double half_v, double z0,
                       double z1, int owner);

  /// Smallest sphere-ish bound (centre, radius) used to cull rays.
  void bound(Eigen::Vector3d& centre, double& radius) const;
};

/// Distance t > 0 along the ray o + t·d (d unit) to the first surface of `p`, or kNoHit. A ray
/// starting inside a solid sees nothing of it (a sensor never sits inside a body).
double intersect(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d);

/// The ground plane through the origin, tilted by `tilt` (rad) towards azimuth `direction`.
struct Ground {
  double gx = 0, gy = 0;  ///< z = gx·x + gy·y
  Ground() = default;
  Ground(double tilt, double direction);
  double height(double x, double y) const { return gx * x + gy * y; }
  double intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const;
};

}  // namespace pedtrack::sim
