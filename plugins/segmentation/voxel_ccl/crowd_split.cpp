#include "voxel_ccl/crowd_split.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::voxelccl {
namespace {

struct Peak {
  double x, y, h;
};

// The component's highest return per cell of a horizontal grid (-1: no return).
struct HeightMap {
  double x0, y0, cell;
  int nx, ny;
  std::vector<double> top;

  int ix(double x) const { return std::clamp(int((x - x0) / cell), 0, nx - 1); }
  int iy(double y) const { return std::clamp(int((y - y0) / cell), 0, ny - 1); }
};

}  // namespace

int splitCrowd(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& sensor,
               const CrowdSplitParams& p, std::vector<int>& part) {
  part.assign(pts.size(), 0);
  if (pts.empty()) return 1;
  double x0 = pts[0].x(), x1 = x0, y0 = pts[0].y(), y1 = y0;
  for (const auto& q : pts) {
    if (!q.allFinite()) return 1;  // voxel_ccl passes none; a direct caller may
    x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
    y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
  }
  // The bounding box's diagonal; the map is capped at 2000 cells a side whatever the options.
  const double extent = std::hypot(x1 - x0, y1 - y0);
  if (!(extent >= p.min_extent && extent <= p.max_extent) || !(p.cell > 0) ||
      extent / p.cell > 2000)
    return 1;

  HeightMap m{x0, y0, p.cell, int((x1 - x0) / p.cell) + 1, int((y1 - y0) / p.cell) + 1, {}};
  m.top.assign(std::size_t(m.nx) * m.ny, -1.0);
  // Where each cell's highest return lies: a head's position, finer than the cell.
  std::vector<std::size_t> top_point(m.top.size(), 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::size_t c = std::size_t(m.iy(pts[i].y())) * m.nx + m.ix(pts[i].x());
    if (pts[i].z() > m.top[c]) m.top[c] = pts[i].z(), top_point[c] = i;
  }

  // Heads by topographic prominence: the cells are flooded from the highest down, and where
  // the regions of two peaks meet (the pass between them), the lower peak is a head of its own
  // when it stands head_dip of its height or more above the pass. A shoulder, a raised arm, a
  // pram's handle or a bag meets its person's head at or near its own height. Cells with no return
  // are never crossed: people apart are their own heads whatever their height.
  std::vector<std::size_t> cells;
  for (std::size_t c = 0; c < m.top.size(); ++c)
    if (m.top[c] >= 0) cells.push_back(c);
  std::sort(cells.begin(), cells.end(),
            [&](std::size_t a, std::size_t b) { return m.top[a] > m.top[b]; });
  std::vector<long> root(m.top.size(), -1);     // union-find parent; -1: not flooded yet
  std::vector<std::size_t> peak(m.top.size());  // a region's highest cell, at its root
  auto find = [&](std::size_t c) {
    while (std::size_t(root[c]) != c) c = std::size_t(root[c] = root[std::size_t(root[c])]);
    return c;
  };
  std::vector<Peak> heads;
  auto headAt = [&](std::size_t c) {
    const auto& q = pts[top_point[c]];
    return Peak{q.x(), q.y(), m.top[c]};
  };
  for (std::size_t c : cells) {
    root[c] = long(c);
    peak[c] = c;
    const int i = int(c % m.nx), j = int(c / m.nx);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= m.nx || b >= m.ny) continue;
        const std::size_t n = std::size_t(b) * m.nx + a;
        if (root[n] < 0) continue;
        std::size_t ra = find(c), rb = find(n);
        if (ra == rb) continue;
        // The region with the lower peak ends here, at the pass m.top[c].
        if (m.top[peak[ra]] > m.top[peak[rb]]) std::swap(ra, rb);
        const double h = m.top[peak[ra]];
        if (h >= p.min_head && h > 0 && h - m.top[c] >= p.head_dip * h)
          heads.push_back(headAt(peak[ra]));
        root[ra] = long(rb);
      }
  }
  for (std::size_t c : cells)  // the highest peak of every region left
    if (find(c) == c && m.top[peak[c]] >= p.min_head && m.top[peak[c]] > 0)
      heads.push_back(headAt(peak[c]));
  // A head is where the returns near its top are (the top return itself lies anywhere on the
  // crown's ring), so that spacing and the torso centres start from the head's centre.
  for (Peak& h : heads) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
    for (const auto& q : pts)
      if (q.z() >= (1 - p.head_dip) * h.h && std::hypot(q.x() - h.x, q.y() - h.y) < 0.15)
        sum += q.head<2>(), ++n;
    h.x = sum.x() / n, h.y = sum.y() / n;  // n >= 1: the top return itself
  }
  // Peaks the sensor's top beam cut are not heads.
  if (p.top_elevation > 0) {
    const double limit = (p.top_elevation - 0.5) * M_PI / 180;
    heads.erase(std::remove_if(heads.begin(), heads.end(),
                               [&](const Peak& h) {
                                 const double r = std::hypot(h.x - sensor.x(), h.y - sensor.y());
                                 return std::atan2(h.h - sensor.z(), r) >= limit;
                               }),
                heads.end());
  }
  // Two heads closer than min_spacing are one person's: the higher stays.
  std::sort(heads.begin(), heads.end(), [](const Peak& a, const Peak& b) { return a.h > b.h; });
  std::vector<Peak> kept;
  for (const Peak& h : heads)
    if (std::none_of(kept.begin(), kept.end(), [&](const Peak& o) {
          return std::hypot(h.x - o.x, h.y - o.y) < p.min_spacing;
        }))
      kept.push_back(h);
  heads.swap(kept);
  // Centres from the heads to the torsos: k-means over the points above half the lowest head
  // (seen from above, a person's legs and bag lie under their torso).
  // A head left with under min_share of the points is a raised arm, a bag or a lone return at
  // head height, not a person: it is dropped and the rest shared again.
  while (heads.size() >= 2) {
    const int k = int(heads.size());
    std::vector<Eigen::Vector2d> centre(k);
    double torso = heads[0].h;
    for (int c = 0; c < k; ++c) {
      centre[c] = {heads[c].x, heads[c].y};
      torso = std::min(torso, 0.5 * heads[c].h);
    }
    auto nearest = [&](const Eigen::Vector3d& q) {
      int best = 0;
      double bd = 1e300;
      for (int c = 0; c < k; ++c) {
        const double d = (q.head<2>() - centre[c]).squaredNorm();
        if (d < bd) bd = d, best = c;
      }
      return best;
    };
    std::vector<Eigen::Vector2d> sum(k);
    std::vector<std::size_t> count(k);
    for (int iter = 0; iter < 3; ++iter) {
      std::fill(sum.begin(), sum.end(), Eigen::Vector2d::Zero());
      std::fill(count.begin(), count.end(), 0);
      for (const auto& q : pts)
        if (q.z() >= torso) {
          const int c = nearest(q);
          sum[c] += q.head<2>();
          ++count[c];
        }
      for (int c = 0; c < k; ++c)
        if (count[c] > 0) centre[c] = sum[c] / double(count[c]);
    }
    std::fill(count.begin(), count.end(), 0);
    for (std::size_t i = 0; i < pts.size(); ++i) ++count[part[i] = nearest(pts[i])];
    const auto smallest = std::min_element(count.begin(), count.end());
    if (double(*smallest) >= p.min_share * double(pts.size())) return k;
    heads.erase(heads.begin() + (smallest - count.begin()));
  }
  part.assign(pts.size(), 0);
  return 1;
}

}  // namespace pedtrack::voxelccl
