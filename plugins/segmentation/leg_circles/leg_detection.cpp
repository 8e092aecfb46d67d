#include "leg_circles/leg_detection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
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

std::size_t legSplitPoint(const fit::Points2& pts, double sx, double sy, double min_jump,
                          const LegParams& p, double* step) {
  const std::size_t part = std::size_t(std::max(3, p.min_points));
  if (min_jump <= 0 || pts.size() < 2 * part) return 0;
  const auto range = [&](std::size_t i) { return std::hypot(pts[i].x() - sx, pts[i].y() - sy); };
  std::size_t best = 0;
  double best_jump = min_jump, best_step = 0;
  for (std::size_t i = part; i + part <= pts.size(); ++i) {
    const double signed_step = range(i) - range(i - 1);
    if (std::abs(signed_step) >= best_jump)
      best = i, best_jump = std::abs(signed_step), best_step = signed_step;
  }
  if (step) *step = best_step;
  return best;
}

std::vector<MergedLeg> mergeLegs(const std::vector<ScanLeg>& legs, double merge_distance,
                                 const LegParams& p) {
  const std::size_t n = legs.size();
  // Single linkage, closest pair first, over groups (union-find roots) whose scans are disjoint.
  std::vector<std::size_t> root(n);
  std::iota(root.begin(), root.end(), 0);
  std::vector<std::vector<std::size_t>> scans(n);  // per root: the scans of its group
  for (std::size_t i = 0; i < n; ++i) scans[i] = {legs[i].scan};
  const auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  if (merge_distance > 0) {
    std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        if (legs[i].scan == legs[j].scan) continue;
        const double d = std::hypot(legs[i].leg.circle.x - legs[j].leg.circle.x,
                                    legs[i].leg.circle.y - legs[j].leg.circle.y);
        if (d < merge_distance) pairs.emplace_back(d, i, j);
      }
    std::sort(pairs.begin(), pairs.end());
    for (const auto& [d, i, j] : pairs) {
      const std::size_t a = find(i), b = find(j);
      if (a == b) continue;
      const bool shared = std::any_of(scans[a].begin(), scans[a].end(), [&](std::size_t s) {
        return std::find(scans[b].begin(), scans[b].end(), s) != scans[b].end();
      });
      if (shared) continue;
      const std::size_t keep = std::min(a, b), gone = std::max(a, b);
      root[gone] = keep;
      scans[keep].insert(scans[keep].end(), scans[gone].begin(), scans[gone].end());
    }
  }
  std::vector<MergedLeg> out;
  std::vector<long> slot(n, -1);  // root → index into out
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = find(i);
    if (slot[r] < 0) {
      slot[r] = long(out.size());
      out.push_back({{}, legs[i].leg});
    }
    out[slot[r]].members.push_back(i);
  }
  fit::Points2 all;
  for (MergedLeg& m : out) {
    if (m.members.size() < 2) continue;
    all.clear();
    Leg mean;
    for (std::size_t i : m.members) {
      all.insert(all.end(), legs[i].points.begin(), legs[i].points.end());
      mean.circle.x += legs[i].leg.circle.x / double(m.members.size());
      mean.circle.y += legs[i].leg.circle.y / double(m.members.size());
      mean.circle.r += legs[i].leg.circle.r / double(m.members.size());
    }
    // Arcs from several sides pin the centre down better than any one of them.
    Leg fitted;
    if (fit::fitCircleBounded(all, p.r_min, p.r_max, fitted.circle)) {
      fitted.residual = fit::circleResidual(all, fitted.circle);
      if (fitted.residual <= p.max_residual) {
        m.leg = fitted;
        continue;
      }
    }
    m.leg = mean;
    m.leg.residual = fit::circleResidual(all, mean.circle);
  }
  return out;
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
