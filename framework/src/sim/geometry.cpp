#include "pedtrack/sim/geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace pedtrack::sim {
namespace {

constexpr double kEps = 1e-9;

// Ray against the vertical elliptic cylinder x²/ru² + y²/rv² = 1 (local frame) with caps.
double hitEllipticCylinder(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const double c = std::cos(p.yaw), s = std::sin(p.yaw);
  const double ox = o.x() - p.a.x(), oy = o.y() - p.a.y();
  const double U = (ox * c + oy * s) / p.ru, V = (-ox * s + oy * c) / p.rv;
  const double dU = (d.x() * c + d.y() * s) / p.ru, dV = (-d.x() * s + d.y() * c) / p.rv;
  const double C = U * U + V * V - 1;
  double best = kNoHit;
  const double A = dU * dU + dV * dV;
  if (C > 0 && A > kEps) {
    const double B = U * dU + V * dV, disc = B * B - A * C;
    if (disc >= 0) {
      const double t = (-B - std::sqrt(disc)) / A;
      const double z = o.z() + t * d.z();
      if (t > kEps && z >= p.z0 && z <= p.z1) best = t;
    }
  }
  // Caps: a ray from above (or below) entering through the flat top (bottom).
  if (std::abs(d.z()) > kEps) {
    for (double zc : {p.z1, p.z0}) {
      if ((zc == p.z1 && o.z() <= p.z1) || (zc == p.z0 && o.z() >= p.z0)) continue;
      const double t = (zc - o.z()) / d.z();
      if (t <= kEps || t >= best) continue;
      const double u = U + t * dU, v = V + t * dV;
      if (u * u + v * v <= 1) best = t;
    }
  }
  return best;
}

double hitSphere(const Eigen::Vector3d& c, double r, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& d) {
  const Eigen::Vector3d oc = o - c;
  const double b = oc.dot(d), cc = oc.squaredNorm() - r * r;
  if (cc <= 0) return kNoHit;
  const double h = b * b - cc;
  if (h < 0) return kNoHit;
  const double t = -b - std::sqrt(h);
  return t > kEps ? t : kNoHit;
}

// Capsule: the infinite cylinder around a–b clipped to the segment, then the end spheres.
double hitCapsule(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const Eigen::Vector3d ba = p.b - p.a, oa = o - p.a;
  const double baba = ba.squaredNorm(), bard = ba.dot(d), baoa = ba.dot(oa), rdoa = d.dot(oa),
               oaoa = oa.squaredNorm(), r = p.ru;
  const double a = baba - bard * bard;
  double best = kNoHit;
  if (a > kEps) {
    const double b = baba * rdoa - baoa * bard, c = baba * oaoa - baoa * baoa - r * r * baba;
    const double h = b * b - a * c;
    if (h >= 0 && c > 0) {
      const double t = (-b - std::sqrt(h)) / a, y = baoa + t * bard;
      if (t > kEps && y > 0 && y < baba) best = t;
    }
  }
  best = std::min(best, hitSphere(p.a, r, o, d));
  best = std::min(best, hitSphere(p.b, r, o, d));
  return best;
}

// Oriented vertical box by slabs in its local frame.
double hitBox(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const double c = std::cos(p.yaw), s = std::sin(p.yaw);
  const double ox = o.x() - p.a.x(), oy = o.y() - p.a.y();
  const double lo[3] = {ox * c + oy * s, -ox * s + oy * c, o.z()};
  const double ld[3] = {d.x() * c + d.y() * s, -d.x() * s + d.y() * c, d.z()};
  const double mn[3] = {-p.ru, -p.rv, p.z0}, mx[3] = {p.ru, p.rv, p.z1};
  double t0 = -kNoHit, t1 = kNoHit;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(ld[i]) < kEps) {
      if (lo[i] < mn[i] || lo[i] > mx[i]) return kNoHit;
      continue;
    }
    double ta = (mn[i] - lo[i]) / ld[i], tb = (mx[i] - lo[i]) / ld[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kNoHit;
  }
  return t0 > kEps ? t0 : kNoHit;
}

}  // namespace

Primitive Primitive::ellipticCylinder(double x, double y, double yaw, double ru, double rv,
                                      double z0, double z1, int owner) {
  Primitive p;
  p.shape = Shape::EllipticCylinder;
  p.a = {x, y, 0};
  p.yaw = yaw;
  p.ru = ru;
  p.rv = rv;
  p.z0 = z0;
  p.z1 = z1;
  p.owner = owner;
  return p;
}

Primitive Primitive::sphere(const Eigen::Vector3d& c, double r, int owner) {
  Primitive p;
  p.shape = Shape::Sphere;
  p.a = c;
  p.ru = r;
  p.owner = owner;
  return p;
}

Primitive Primitive::capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r,
                             int owner) {
  Primitive p;
  p.shape = Shape::Capsule;
  p.a = a;
  p.b = b;
  p.ru = r;
  p.owner = owner;
  return p;
}

Primitive Primitive::box(double x, double y, double yaw, double half_u, double half_v, double z0,
                         double z1, int owner) {
  Primitive p = ellipticCylinder(x, y, yaw, half_u, half_v, z0, z1, owner);
  p.shape = Shape::Box;
  return p;
}

void Primitive::bound(Eigen::Vector3d& centre, double& radius) const {
  switch (shape) {
    case Shape::Sphere:
      centre = a;
      radius = ru;
      return;
    case Shape::Capsule:
      centre = 0.5 * (a + b);
      radius = 0.5 * (b - a).norm() + ru;
      return;
    case Shape::EllipticCylinder:
    case Shape::Box: {
      const double h = 0.5 * (z1 - z0);
      const double rxy = shape == Shape::Box ? std::hypot(ru, rv) : std::max(ru, rv);
      centre = {a.x(), a.y(), 0.5 * (z0 + z1)};
      radius = std::hypot(rxy, h);
      return;
    }
  }
}

double intersect(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  switch (p.shape) {
    case Shape::EllipticCylinder:
      return hitEllipticCylinder(p, o, d);
    case Shape::Sphere:
      return hitSphere(p.a, p.ru, o, d);
    case Shape::Capsule:
      return hitCapsule(p, o, d);
    case Shape::Box:
      return hitBox(p, o, d);
  }
  return kNoHit;
}

Ground::Ground(double tilt, double direction)
    : gx(std::tan(tilt) * std::cos(direction)), gy(std::tan(tilt) * std::sin(direction)) {}

double Ground::intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
  const double denom = d.z() - gx * d.x() - gy * d.y();
  if (std::abs(denom) < 1e-12) return kNoHit;
  const double t = (gx * o.x() + gy * o.y() - o.z()) / denom;
  return t > 1e-9 ? t : kNoHit;
}

}  // namespace pedtrack::sim
