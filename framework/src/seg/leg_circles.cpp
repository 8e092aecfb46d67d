#include "pedtrack/seg/leg_circles.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace pedtrack::seg {

bool detectLeg(const fit::Points2& pts, double sx, double sy, const LegParams& p, Leg& out) {
  if (int(pts.size()) < std::max(3, p.min_points)) return false;
  if (!fit::fitCircleBounded(pts, p.r_min, p.r_max, out.circle)) return false;
  out.residual = fit::circleResidual(pts, out.circle);
  if (out.residual > p.max_residual) return false;
  if (!p.require_convex) return true;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : pts) mean += q;
  mean /= double(pts.size());
  return std::hypot(out.circle.x - sx, out.circle.y - sy) >
         std::hypot(mean.x() - sx, mean.y() - sy);
}

std::vector<int> pairLegs(const std::vector<Eigen::Vector2d>& centres, double max_distance) {
  std::vector<std::tuple<double, int, int>> pairs;
  for (std::size_t i = 0; i < centres.size(); ++i)
    for (std::size_t j = i + 1; j < centres.size(); ++j) {
      const double d = (centres[i] - centres[j]).norm();
      if (d <= max_distance) pairs.emplace_back(d, int(i), int(j));
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> partner(centres.size(), -1);
  for (const auto& [d, i, j] : pairs)
    if (partner[i] < 0 && partner[j] < 0) {
      partner[i] = j;
      partner[j] = i;
    }
  return partner;
}

}  // namespace pedtrack::seg
