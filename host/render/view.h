#pragma once
// The top view: a square picture of the fixed frame, x to the right and y up. Tests use it to
// compute where a fixed-frame point lands in a rendered image.
#include <opencv2/core.hpp>
#include <vector>

namespace pedtrack::render {

struct View {
  double cx = 0, cy = 0;  ///< fixed-frame point at the image centre (m)
  double half_range = 8;  ///< metres from the centre to each image edge
  int size = 900;         ///< image side (px); the image is square

  double pixelsPerMeter() const { return size / (2 * half_range); }
  /// Sub-pixel image position of a fixed-frame point (image y grows downwards).
  cv::Point2d toImage(double x, double y) const {
    return {(x - cx) * pixelsPerMeter() + size / 2.0, size / 2.0 - (y - cy) * pixelsPerMeter()};
  }
  /// The pixel a fixed-frame point is drawn at.
  cv::Point pixel(double x, double y) const {
    const cv::Point2d p = toImage(x, y);
    return {cvRound(p.x), cvRound(p.y)};
  }
  /// A length in metres as pixels.
  double toPixels(double metres) const { return metres * pixelsPerMeter(); }
  /// Fixed-frame point of an image position (inverse of toImage).
  cv::Point2d toWorld(double u, double v) const {
    return {cx + (u - size / 2.0) / pixelsPerMeter(), cy - (v - size / 2.0) / pixelsPerMeter()};
  }
};

/// The view centred on `center`: `half_range` when > 0, else the smallest half-width holding
/// every point of `must_see` with `margin` metres to spare, and never less than `min_range`.
View fitView(const cv::Point2d& center, double half_range, int size,
             const std::vector<cv::Point2d>& must_see, double margin = 1.0, double min_range = 8.0);

}  // namespace pedtrack::render
