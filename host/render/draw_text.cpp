// Text, the information panel and the legend.
#include <algorithm>
#include <functional>
#include <opencv2/imgproc.hpp>

#include "draw.h"
#include "palette.h"

namespace pedtrack::render {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

/// A filled panel with a thin border, the background of the info box and the legend.
void panel(cv::Mat& img, const cv::Rect& r) {
  const cv::Rect clipped = r & cv::Rect(0, 0, img.cols, img.rows);
  if (clipped.empty()) return;
  // Blend rather than paint over, so the map under a panel is still faintly visible.
  cv::Mat roi = img(clipped);
  cv::Mat fill(roi.size(), roi.type(), colors::kPanel);
  cv::addWeighted(roi, 0.25, fill, 0.75, 0, roi);
  cv::rectangle(img, clipped, colors::kGridMajor, 1);
}

/// Pixels in `r` brighter than the grid: what a panel there would hide.
int busyPixels(const cv::Mat& img, const cv::Rect& r) {
  const cv::Rect clipped = r & cv::Rect(0, 0, img.cols, img.rows);
  cv::Mat gray;
  cv::cvtColor(img(clipped), gray, cv::COLOR_BGR2GRAY);
  return cv::countNonZero(gray > 100);
}

}  // namespace

void drawText(cv::Mat& img, const std::string& text, cv::Point origin, const cv::Scalar& color,
              double scale) {
  cv::putText(img, text, origin, kFont, scale, colors::kOutline, 3, cv::LINE_AA);
  cv::putText(img, text, origin, kFont, scale, color, 1, cv::LINE_AA);
}

void drawInfoPanel(cv::Mat& img, const std::vector<std::string>& lines) {
  const double scale = 0.48;
  const int line_h = 20, pad = 8;
  int width = 0;
  for (const auto& l : lines)
    width = std::max(width, cv::getTextSize(l, kFont, scale, 1, nullptr).width);
  panel(img, {6, 6, width + 2 * pad, static_cast<int>(lines.size()) * line_h + pad});
  for (std::size_t i = 0; i < lines.size(); ++i)
    drawText(img, lines[i], {6 + pad, 6 + pad + 10 + static_cast<int>(i) * line_h}, colors::kText,
             scale);
}

void drawLegend(cv::Mat& img, bool overlay, bool with_truth, bool with_detections, bool pick_corner,
                PointColours points, bool with_scores, bool with_boxes) {
  // One entry per mark: a glyph drawn by a small lambda, then its meaning.
  struct Entry {
    std::string text;
    std::function<void(cv::Point)> glyph;
  };
  const cv::Scalar track = trackColor(1);
  std::vector<Entry> entries;
  auto dots = [&](const std::string& text, const cv::Scalar& a, const cv::Scalar& b) {
    entries.push_back({text, [&img, a, b](cv::Point c) {
                         cv::rectangle(img, c - cv::Point(1, 1), c, a, cv::FILLED);
                         cv::rectangle(img, c + cv::Point(4, 2), c + cv::Point(5, 3), b,
                                       cv::FILLED);
                       }});
  };
  switch (points) {
    case PointColours::ByHeight:
      dots("points", colors::kPoint, colors::kPoint);
      dots("ground points", colors::kGround, colors::kGround);
      break;
    case PointColours::RunLabels:
      dots("clusters (a colour each)", clusterColor(1), clusterColor(2));
      dots("unclustered points", colors::kPoint, colors::kPoint);
      dots("ground (removed)", colors::kGround, colors::kGround);
      dots("removed by band / region", colors::kRemoved, colors::kRemoved);
      break;
    case PointColours::TruthLabels:
      dots("true people (a colour each)", clusterColor(1), clusterColor(2));
      dots("objects", colors::kPoint, colors::kPoint);
      dots("ground", colors::kGround, colors::kGround);
      break;
  }
  entries.push_back({"sensor", [&](cv::Point c) {
                       const std::vector<cv::Point> tri = {
                           c + cv::Point(8, 0), c + cv::Point(-5, -5), c + cv::Point(-5, 5)};
                       cv::fillConvexPoly(img, tri, colors::kSensor, cv::LINE_AA);
                     }});
  entries.push_back({"track: torso, id, velocity 1 s", [&](cv::Point c) {
                       cv::circle(img, c, 6, track, 2, cv::LINE_AA);
                       cv::circle(img, c, 2, track, cv::FILLED);
                       cv::arrowedLine(img, c, c + cv::Point(14, -4), track, 1, cv::LINE_AA, 0,
                                       0.4);
                     }});
  entries.push_back({"track 95% covariance", [&](cv::Point c) {
                       cv::ellipse(img, c, {10, 5}, -20, 0, 360, track * 0.7, 1, cv::LINE_AA);
                     }});
  if (with_truth)
    entries.push_back({overlay ? "truth path (dashed)" : "truth: torso, legs", [&](cv::Point c) {
                         cv::ellipse(img, c, {8, 5}, 0, 0, 360, colors::kTruth, 1, cv::LINE_AA);
                       }});
  if (with_detections)
    entries.push_back({with_scores ? "detection, person score (bright: a person)" : "detection",
                       [&](cv::Point c) {
                         cv::drawMarker(img, c, colors::kDetection, cv::MARKER_TILTED_CROSS, 10, 2);
                       }});
  if (with_boxes) {
    for (const bool person : {true, false})
      entries.push_back({person ? "labelled person" : "labelled object (not a person)",
                         [&img, person](cv::Point c) {
                           cv::rectangle(img, c - cv::Point(9, 5), c + cv::Point(9, 5),
                                         person ? colors::kTruth : colors::kLabelBox, 1,
                                         cv::LINE_AA);
                         }});
  }
  if (overlay)
    entries.push_back({"path start / end", [&](cv::Point c) {
                         cv::circle(img, c - cv::Point(6, 0), 4, track, 1, cv::LINE_AA);
                         cv::circle(img, c + cv::Point(7, 0), 4, track, cv::FILLED);
                       }});

  const double scale = 0.42;
  const int line_h = 19, pad = 8, glyph_w = 30;
  int width = 0;
  for (const auto& e : entries)
    width = std::max(width, cv::getTextSize(e.text, kFont, scale, 1, nullptr).width);
  const int w = glyph_w + width + 2 * pad, h = static_cast<int>(entries.size()) * line_h + pad;
  const cv::Rect left(6, img.rows - 6 - h, w, h), right(img.cols - 6 - w, img.rows - 6 - h, w, h);
  const cv::Rect box =
      !pick_corner || busyPixels(img, left) <= busyPixels(img, right) ? left : right;
  panel(img, box);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = box.y + pad / 2 + line_h / 2 + static_cast<int>(i) * line_h;
    entries[i].glyph({box.x + pad + 10, y});
    drawText(img, entries[i].text, {box.x + pad + glyph_w, y + 5}, colors::kText, scale);
  }
}

}  // namespace pedtrack::render
