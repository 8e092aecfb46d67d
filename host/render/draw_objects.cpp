// Tracks, truth and detections: the objects drawn over the map.
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "draw.h"
#include "palette.h"

namespace pedtrack::render {
namespace {

constexpr double kDefaultRadius = 0.25;  // m, a torso-sized circle when a row has no shape
constexpr double kChi2Two95 = 5.991;     // 95 % quantile of chi-square with 2 degrees of freedom

/// An ellipse with semi-axes (a, b) in metres, major axis at `yaw` (fixed frame, CCW).
cv::RotatedRect worldEllipse(const View& view, double x, double y, double a, double b, double yaw) {
  const cv::Point2d c = view.toImage(x, y);
  // cv angles turn clockwise on screen, which is counter-clockwise in the y-up fixed frame
  // flipped onto the y-down image: hence the minus.
  return cv::RotatedRect(cv::Point2f(c), cv::Size2f(2 * view.toPixels(a), 2 * view.toPixels(b)),
                         static_cast<float>(-yaw * 180 / M_PI));
}

double headingOf(const ObjectRow& r) {
  if (std::isfinite(r.yaw)) return r.yaw;
  if (std::isfinite(r.vx) && std::isfinite(r.vy) && std::hypot(r.vx, r.vy) > 0.05)
    return std::atan2(r.vy, r.vx);
  return 0;
}

/// Radius in pixels of the mark drawn for a row: its larger semi-axis, or the default circle.
double markRadiusPx(const View& view, const ObjectRow& r) {
  const double m = r.hasShape() ? std::max(r.alpha, r.beta) : kDefaultRadius;
  return std::max(4.0, view.toPixels(m));
}

void outline(cv::Mat& img, const View& view, const ObjectRow& r, const cv::Scalar& color,
             int thickness) {
  if (r.hasShape() && r.alpha > 0 && r.beta > 0) {
    // alpha lies across the shoulders, beta along the heading (the truth.csv convention).
    cv::ellipse(img, worldEllipse(view, r.x, r.y, r.beta, r.alpha, headingOf(r)), color, thickness,
                cv::LINE_AA);
  } else {
    cv::circle(img, view.pixel(r.x, r.y),
               std::max(3, static_cast<int>(std::lround(view.toPixels(kDefaultRadius)))), color,
               thickness, cv::LINE_AA);
  }
}

cv::Scalar dimmed(const cv::Scalar& c, double f) {
  return {c[0] * f, c[1] * f, c[2] * f};
}

}  // namespace

void drawTrackBody(cv::Mat& img, const View& view, const ObjectRow& t) {
  const cv::Scalar color = trackColor(t.id);
  if (t.hasCov()) {
    cv::Matx22d cov(t.cov_xx, t.cov_xy, t.cov_xy, t.cov_yy);
    cv::Mat values, vectors;
    if (cv::eigen(cov, values, vectors)) {  // descending eigenvalues, eigenvectors as rows
      const double l1 = std::max(0.0, values.at<double>(0)),
                   l2 = std::max(0.0, values.at<double>(1));
      const double angle = std::atan2(vectors.at<double>(0, 1), vectors.at<double>(0, 0));
      const double a = std::sqrt(kChi2Two95 * l1), b = std::sqrt(kChi2Two95 * l2);
      if (view.toPixels(a) >= 0.5)
        cv::ellipse(img, worldEllipse(view, t.x, t.y, a, b, angle), dimmed(color, 0.7), 1,
                    cv::LINE_AA);
    }
  }
  outline(img, view, t, color, 2);
  if (std::isfinite(t.vx) && std::isfinite(t.vy) && std::hypot(t.vx, t.vy) > 0.02) {
    const cv::Point2d from = view.toImage(t.x, t.y), to = view.toImage(t.x + t.vx, t.y + t.vy);
    const double len = cv::norm(to - from);
    if (len >= 3)
      cv::arrowedLine(img, from, to, color, 2, cv::LINE_AA, 0, std::min(0.4, 10.0 / len));
  }
}

void drawTrackMarker(cv::Mat& img, const View& view, const ObjectRow& t) {
  const cv::Scalar color = trackColor(t.id);
  const cv::Point c = view.pixel(t.x, t.y);
  // LINE_8, not anti-aliased: the centre pixel carries exactly the track's colour.
  cv::circle(img, c, 5, colors::kOutline, cv::FILLED, cv::LINE_8);
  cv::circle(img, c, 3, color, cv::FILLED, cv::LINE_8);
  const int r = static_cast<int>(markRadiusPx(view, t) * 0.75);
  drawText(img, std::to_string(t.id), {c.x + r + 3, c.y - r - 3}, color, 0.5);
}

void drawTruth(cv::Mat& img, const View& view, const ObjectRow& g) {
  outline(img, view, g, colors::kTruth, 1);
  const int leg_r = std::max(2, static_cast<int>(std::lround(view.toPixels(0.06))));
  if (std::isfinite(g.left_leg_x) && std::isfinite(g.left_leg_y))
    cv::circle(img, view.pixel(g.left_leg_x, g.left_leg_y), leg_r, colors::kTruth, 1, cv::LINE_AA);
  if (std::isfinite(g.right_leg_x) && std::isfinite(g.right_leg_y))
    cv::circle(img, view.pixel(g.right_leg_x, g.right_leg_y), leg_r, colors::kTruth, 1,
               cv::LINE_AA);
  const cv::Point c = view.pixel(g.x, g.y);
  const int r = static_cast<int>(markRadiusPx(view, g) * 0.75);
  drawText(img, "T" + std::to_string(g.id), {c.x + r + 2, c.y + r + 12}, colors::kTruth, 0.38);
}

void drawDetection(cv::Mat& img, const View& view, const ObjectRow& d, int size_px) {
  const int size =
      size_px > 0 ? size_px : std::max(9, static_cast<int>(std::lround(view.toPixels(0.3))));
  cv::drawMarker(img, view.pixel(d.x, d.y), colors::kDetection, cv::MARKER_TILTED_CROSS, size,
                 size_px > 0 && size_px < 8 ? 1 : 2, cv::LINE_AA);
}

void drawDetectionScore(cv::Mat& img, const View& view, const ObjectRow& d, double person_score) {
  if (!std::isfinite(d.score)) return;
  const bool person = d.score >= person_score;
  const cv::Point p = view.pixel(d.x, d.y);
  drawText(img, mrpt::format("%.2f", d.score), p + cv::Point(7, 4),
           person ? colors::kDetection : colors::kDimText, person ? 0.42 : 0.32);
}

void drawLabelBox(cv::Mat& img, const View& view, const LabelBox& b) {
  const double c = std::cos(b.yaw), s = std::sin(b.yaw);
  std::vector<cv::Point> corners;
  for (const auto& [u, v] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) {
    const double a = u * b.l / 2, q = v * b.w / 2;
    corners.push_back(view.pixel(b.x + c * a - s * q, b.y + s * a + c * q));
  }
  const cv::Scalar colour = b.person ? colors::kTruth : colors::kLabelBox;
  cv::polylines(img, corners, true, colour, b.person ? 2 : 1, cv::LINE_AA);
  const cv::Point top =
      *std::min_element(corners.begin(), corners.end(),
                        [](const cv::Point& p, const cv::Point& q) { return p.y < q.y; });
  drawText(img, b.name, top + cv::Point(-10, -6), colour, 0.42);
}

void drawPath(cv::Mat& img, const View& view, const std::vector<const ObjectRow*>& path,
              const cv::Scalar& color, int thickness, LineStyle style) {
  if (path.size() < 2) return;
  std::vector<cv::Point2d> px;
  px.reserve(path.size());
  for (const ObjectRow* r : path) px.push_back(view.toImage(r->x, r->y));
  if (style == LineStyle::Solid) {
    std::vector<cv::Point> ipx(px.begin(), px.end());
    cv::polylines(img, ipx, false, color, thickness, cv::LINE_AA);
    return;
  }
  // Dashes of 7 px with 5 px gaps, carried across vertices so short steps still dash.
  const double dash = 7, period = 12;
  double phase = 0;
  for (std::size_t i = 1; i < px.size(); ++i) {
    const cv::Point2d a = px[i - 1], d = px[i] - a;
    const double len = cv::norm(d);
    double s = 0;
    while (s < len) {
      const double in_period = std::fmod(phase + s, period);
      const double step = in_period < dash ? dash - in_period : period - in_period;
      const double e = std::min(len, s + step);
      if (in_period < dash)
        cv::line(img, a + d * (s / len), a + d * (e / len), color, thickness, cv::LINE_AA);
      s = e;
    }
    phase = std::fmod(phase + len, period);
  }
}

void drawPathEnds(cv::Mat& img, const View& view, const std::vector<const ObjectRow*>& path,
                  const cv::Scalar& color, int radius_px) {
  if (path.empty()) return;
  const ObjectRow& first = *path.front();
  const ObjectRow& last = *path.back();
  cv::circle(img, view.pixel(first.x, first.y), radius_px, color, 1, cv::LINE_AA);
  cv::circle(img, view.pixel(last.x, last.y), radius_px + 1, colors::kOutline, cv::FILLED,
             cv::LINE_8);
  cv::circle(img, view.pixel(last.x, last.y), radius_px - 1, color, cv::FILLED, cv::LINE_8);
}

}  // namespace pedtrack::render
