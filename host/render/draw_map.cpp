// Grid, scale bar, points and the sensor: the map under the objects.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "draw.h"
#include "palette.h"

namespace pedtrack::render {
namespace {

/// The smallest step of the 1-2-5 series (at least 1 m) not shorter than `min_metres`.
double niceStep(double min_metres) {
  for (double base = 1;; base *= 10)
    for (double m : {1.0, 2.0, 5.0})
      if (m * base >= min_metres) return m * base;
}

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-9 ? 0.0 : v);
  return buf;
}

void gridLines(cv::Mat& img, const View& view, double step, const cv::Scalar& color, bool labels) {
  const double h = view.half_range;
  for (double x = std::ceil((view.cx - h) / step) * step; x <= view.cx + h; x += step) {
    const int u = view.pixel(x, view.cy).x;
    cv::line(img, {u, 0}, {u, view.size - 1}, color, 1);
    // No labels in the bottom-right corner, where the two label rows would meet.
    if (labels && u < view.size - 40)
      drawText(img, metres(x), {u + 3, view.size - 6}, colors::kGridLabel, 0.4);
  }
  for (double y = std::ceil((view.cy - h) / step) * step; y <= view.cy + h; y += step) {
    const int v = view.pixel(view.cx, y).y;
    cv::line(img, {0, v}, {view.size - 1, v}, color, 1);
    if (labels && v > 14 && v < view.size - 22) {
      const std::string s = metres(y);
      const int w = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, nullptr).width;
      drawText(img, s, {view.size - w - 5, v - 3}, colors::kGridLabel, 0.4);
    }
  }
}

}  // namespace

void drawGrid(cv::Mat& img, const View& view) {
  // Minor lines every metre unless they would be closer than 6 px; labelled major lines about
  // 70 px apart, so labels never collide at any range.
  const double ppm = view.pixelsPerMeter();
  gridLines(img, view, niceStep(6 / ppm), colors::kGridMinor, false);
  gridLines(img, view, niceStep(70 / ppm), colors::kGridMajor, true);
}

void drawScaleBar(cv::Mat& img, const View& view) {
  const double len = niceStep(view.size / 8.0 / view.pixelsPerMeter());
  const int px = static_cast<int>(std::lround(view.toPixels(len)));
  const int right = view.size - 16, left = right - px, y = 26;
  cv::line(img, {left, y}, {right, y}, colors::kOutline, 5);
  cv::line(img, {left, y}, {right, y}, colors::kText, 2);
  for (int x : {left, right}) cv::line(img, {x, y - 6}, {x, y + 6}, colors::kText, 2);
  const std::string label = metres(len) + " m";
  const int w = cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, nullptr).width;
  drawText(img, label, {(left + right - w) / 2, y - 9}, colors::kText);
}

PointCounts drawPoints(cv::Mat& img, const View& view, const Frame& frame, double ground_z,
                       const LabelFrame* labels, LabelKind kind) {
  bool planar = !frame.observations.empty();
  for (const auto& obs : frame.observations)
    if (obs && isRangeObservation(*obs) && !IS_CLASS(*obs, mrpt::obs::CObservation2DRangeScan))
      planar = false;
  const auto& cloud = frame.cloud();
  PointCounts counts;
  std::vector<cv::Point> ground, other, removed;
  std::vector<std::pair<cv::Point, std::int32_t>> grouped;  // cluster or person points
  ground.reserve(cloud.size());
  other.reserve(cloud.size());
  if (labels && labels->labels.size() != cloud.size()) labels = nullptr;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    float lx, ly, lz;
    cloud.getPoint(i, lx, ly, lz);
    double gx, gy, gz;
    frame.robot_pose.composePoint(lx, ly, lz, gx, gy, gz);
    const cv::Point px = view.pixel(gx, gy);
    if (!labels) {
      const bool is_ground = !planar && lz < ground_z;
      (is_ground ? counts.ground : counts.other)++;
      (is_ground ? ground : other).push_back(px);
      continue;
    }
    const std::int32_t l = labels->labels[i];
    const bool truth = kind == LabelKind::Truth;
    if (truth ? l == truth_label::kGround : l == run_label::kGround) {
      ++counts.ground;
      ground.push_back(px);
    } else if (!truth && l == run_label::kRemoved) {
      ++counts.removed;
      removed.push_back(px);
    } else if (truth ? truth_label::isPerson(l) : l >= 0) {
      ++counts.clustered;
      grouped.emplace_back(px, l);
    } else {
      ++counts.other;
      other.push_back(px);
    }
  }
  // 2x2 px per point: single pixels vanish on a 900 px picture of a sparse 2D scan. Ground
  // first, so obstacles stay visible where both project to the same pixel.
  auto paint = [&](const std::vector<cv::Point>& pts, const cv::Scalar& color) {
    const cv::Vec3b c(cv::saturate_cast<uchar>(color[0]), cv::saturate_cast<uchar>(color[1]),
                      cv::saturate_cast<uchar>(color[2]));
    for (const auto& p : pts)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const int u = p.x + dx, v = p.y + dy;
          if (u >= 0 && v >= 0 && u < img.cols && v < img.rows) img.at<cv::Vec3b>(v, u) = c;
        }
  };
  paint(ground, colors::kGround);
  paint(removed, colors::kRemoved);
  paint(other, colors::kPoint);
  std::vector<cv::Point> one(1);
  for (const auto& [p, id] : grouped) {
    one[0] = p;
    paint(one, clusterColor(id));
  }
  return counts;
}

void drawSensor(cv::Mat& img, const View& view, const mrpt::poses::CPose3D& pose) {
  const cv::Point2d c = view.toImage(pose.x(), pose.y());
  const double len = std::max(16.0, view.toPixels(0.5));
  // Image y points down: a heading of +yaw turns towards -v.
  const cv::Point2d f(std::cos(pose.yaw()), -std::sin(pose.yaw())), s(-f.y, f.x);
  const std::vector<cv::Point> tri = {c + f * (0.6 * len), c - f * (0.4 * len) + s * (0.35 * len),
                                      c - f * (0.4 * len) - s * (0.35 * len)};
  cv::fillConvexPoly(img, tri, colors::kSensor, cv::LINE_AA);
  cv::polylines(img, tri, true, colors::kOutline, 1, cv::LINE_AA);
}

void drawPolyline(cv::Mat& img, const View& view, const std::vector<cv::Point2d>& path,
                  const cv::Scalar& color, int thickness) {
  if (path.size() < 2) return;
  std::vector<cv::Point> px;
  px.reserve(path.size());
  for (const auto& p : path) px.push_back(view.pixel(p.x, p.y));
  cv::polylines(img, px, false, color, thickness, cv::LINE_AA);
}

}  // namespace pedtrack::render
