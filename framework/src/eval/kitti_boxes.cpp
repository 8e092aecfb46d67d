#include "pedtrack/eval/kitti_boxes.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace pedtrack::eval {
namespace {

// The footprint (x, z) corners, in order around the box.
std::vector<cv::Point2f> footprint(const KittiCameraBox& b) {
  const auto c = kittiCorners(b);
  std::vector<cv::Point2f> p;
  for (int i = 0; i < 4; ++i) p.emplace_back(float(c[i].x()), float(c[i].z()));
  return p;
}

double footprintOverlap(const KittiCameraBox& a, const KittiCameraBox& b) {
  // Far apart: no overlap, and no call into the polygon clipper.
  const double reach = std::hypot(a.l, a.w) / 2 + std::hypot(b.l, b.w) / 2;
  if (std::hypot(a.x - b.x, a.z - b.z) > reach) return 0;
  std::vector<cv::Point2f> out;
  return std::max(0.f, cv::intersectConvexConvex(footprint(a), footprint(b), out, true));
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
