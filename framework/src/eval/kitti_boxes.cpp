#include "pedtrack/eval/kitti_boxes.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

namespace pedtrack::eval {
namespace {

using Point = Eigen::Vector2d;

// The footprint (x, z) corners, counter-clockwise seen from above (y down: x right, z forward).
std::vector<Point> footprint(const KittiCameraBox& b) {
  const auto c = kittiCorners(b);
  std::vector<Point> p;
  for (int i = 3; i >= 0; --i) p.emplace_back(c[std::size_t(i)].x(), c[std::size_t(i)].z());
  return p;
}

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

double area(const std::vector<Point>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point &a = p[i], &b = p[(i + 1) % p.size()];
    s += a.x() * b.y() - b.x() * a.y();
  }
  return std::abs(s) / 2;
}

// Sutherland–Hodgman: `subject` clipped by the convex `clip`, both in the same winding, in double
// precision (OpenCV 4.6's float intersectConvexConvex misjudges touching corners).
std::vector<Point> clipConvex(std::vector<Point> subject, const std::vector<Point>& clip) {
  const double sign = cross(clip[0], clip[1], clip[2]) >= 0 ? 1 : -1;
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const Point &a = clip[e], &b = clip[(e + 1) % clip.size()];
    const auto inside = [&](const Point& p) { return sign * cross(a, b, p) >= 0; };
    std::vector<Point> out;
    for (std::size_t k = 0; k < subject.size(); ++k) {
      const Point &p = subject[k], &q = subject[(k + 1) % subject.size()];
      const bool pin = inside(p), qin = inside(q);
      if (pin) out.push_back(p);
      if (pin != qin) {
        const double dp = cross(a, b, p), dq = cross(a, b, q);
        out.push_back(p + (q - p) * (dp / (dp - dq)));
      }
    }
    subject = std::move(out);
  }
  return subject;
}

double footprintOverlap(const KittiCameraBox& a, const KittiCameraBox& b) {
  // Far apart: no overlap, and no clipping.
  const double reach = std::hypot(a.l, a.w) / 2 + std::hypot(b.l, b.w) / 2;
  if (std::hypot(a.x - b.x, a.z - b.z) > reach) return 0;
  const auto poly = clipConvex(footprint(a), footprint(b));
  return poly.size() < 3 ? 0 : area(poly);
}

}  // namespace

double kittiIou3d(const KittiCameraBox& a, const KittiCameraBox& b) {
  const double va = a.h * a.w * a.l, vb = b.h * b.w * b.l;
  if (!(va > 0) || !(vb > 0)) return 0;
  // y points down: a box spans [y − h, y].
  const double dy = std::min(a.y, b.y) - std::max(a.y - a.h, b.y - b.h);
  if (dy <= 0) return 0;
  const double inter = footprintOverlap(a, b) * dy;
  return inter / (va + vb - inter);
}

double kittiIouBev(const KittiCameraBox& a, const KittiCameraBox& b) {
  const double aa = a.w * a.l, ab = b.w * b.l;
  if (!(aa > 0) || !(ab > 0)) return 0;
  const double inter = footprintOverlap(a, b);
  return inter / (aa + ab - inter);
}

}  // namespace pedtrack::eval
