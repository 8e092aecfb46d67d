#include "view.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::render {

View fitView(const cv::Point2d& center, double half_range, int size,
             const std::vector<cv::Point2d>& must_see, double margin, double min_range) {
  View v;
  v.cx = center.x;
  v.cy = center.y;
  v.size = size;
  if (half_range > 0) {
    v.half_range = half_range;
    return v;
  }
  double extent = 0;
  for (const auto& p : must_see) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    extent = std::max({extent, std::abs(p.x - center.x), std::abs(p.y - center.y)});
  }
  v.half_range = std::max(min_range, extent + margin);
  return v;
}

}  // namespace pedtrack::render
