#include "irls_ground/irls_ground_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "irls_ground/plane.h"

namespace pedtrack::seg {

double irlsWeight(double x, const IrlsParams& p) {
  const double e = p.B * (x - p.C);
  if (e > 700) return p.D;  // A·e^e overflows; the logistic term is 0 long before
  return 1.0 / (1.0 + p.A * std::exp(e)) + p.D;
}

GroundPlane irlsIteration(const std::vector<Eigen::Vector3d>& pts, const GroundPlane& prior,
                          const IrlsParams& p, std::vector<double>* weights) {
  if (weights) weights->resize(pts.size());
  fit::PlaneMoments m;  // weights and moments in one pass
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double w = irlsWeight(std::abs(prior.height(pts[i].x(), pts[i].y(), pts[i].z())), p);
    if (weights) (*weights)[i] = w;
    m.add(pts[i], w);
  }
  return m.plane();
}

GroundPlane levelPlane(double z) {
  GroundPlane g;
  g.valid = true;
  g.d = -z;
  return g;
}

void IrlsGround::binLowest(const float* xs, const float* ys, const float* zs, std::size_t n,
                           const std::vector<PointLabel>* labels, double sx, double sy) {
  // A dense grid of cells over the square around the sensor; only cells within max_range hold.
  const int half = static_cast<int>(std::ceil(p_.max_range / p_.bin));
  const int side = 2 * half;
  cell_z_.assign(static_cast<std::size_t>(side) * side, std::numeric_limits<float>::infinity());
  cell_i_.assign(cell_z_.size(), -1);
  const double r2 = p_.max_range * p_.max_range, inv = 1.0 / p_.bin;
  for (std::size_t i = 0; i < n; ++i) {
    if (labels && (*labels)[i] != PointLabel::Kept) continue;
    const double dx = xs[i] - sx, dy = ys[i] - sy;
    if (!(dx * dx + dy * dy <= r2) || !std::isfinite(zs[i])) continue;
    const int cx = static_cast<int>(std::floor(dx * inv)) + half;
    const int cy = static_cast<int>(std::floor(dy * inv)) + half;
    if (cx < 0 || cy < 0 || cx >= side || cy >= side) continue;
    const std::size_t c = static_cast<std::size_t>(cy) * side + cx;
    if (zs[i] < cell_z_[c]) {
      cell_z_[c] = zs[i];
      cell_i_[c] = static_cast<int>(i);
    }
  }
  binned_.clear();
  for (int i : cell_i_)
    if (i >= 0) binned_.emplace_back(xs[i], ys[i], zs[i]);
}

// The lowest well-populated level of the binned points: 5 cm histogram of their heights, the
// lowest bin holding at least a tenth of the fullest one (stray points below the floor are few).
double IrlsGround::findDefaultHeight() const {
  std::map<long, int> hist;
  int best = 0;
  for (const auto& q : binned_)
    best = std::max(best, ++hist[std::lround(std::floor(q.z() / 0.05))]);
  for (const auto& [k, count] : hist)
    if (count >= std::max(3, best / 10)) {
      // Refine: the median height of the points of that bin and its neighbours.
      std::vector<double> z;
      for (const auto& q : binned_)
        if (std::abs(q.z() - (k + 0.5) * 0.05) <= 0.075) z.push_back(q.z());
      std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
      return z[z.size() / 2];
    }
  return p_.default_height;
}

GroundPlane IrlsGround::update(const float* xs, const float* ys, const float* zs, std::size_t n,
                               const std::vector<PointLabel>* labels, double sx, double sy) {
  binLowest(xs, ys, zs, n, labels, sx, sy);
  if (!started_) {
    // The ground is the lowest extensive surface: with auto_height its level in the first frame
    // that has cells replaces the configured height (a log whose robot frame is the sensor's
    // own). Frames before that use the configured height and do not settle it.
    const bool found = p_.auto_height && !binned_.empty();
    default_ = levelPlane(found ? findDefaultHeight() : p_.default_height);
    prior_ = default_;
    started_ = found || !p_.auto_height;
  }
  // The data: the cells' lowest points plus the seed mesh on the default plane (P2: a
  // regulariser that holds the plane when the ground is occluded).
  data_ = binned_;
  for (int r = 0; r < p_.seed_rows; ++r)
    for (int c = 0; c < p_.seed_cols; ++c) {
      const double x =
          sx + (p_.seed_cols > 1 ? -1 + 2.0 * c / (p_.seed_cols - 1) : 0) * p_.seed_extent;
      const double y =
          sy + (p_.seed_rows > 1 ? -1 + 2.0 * r / (p_.seed_rows - 1) : 0) * p_.seed_extent;
      data_.emplace_back(x, y, -(default_.nx * x + default_.ny * y + default_.d) / default_.nz);
    }
  GroundPlane plane = prior_;
  for (int it = 0; it < p_.iterations; ++it) {
    const GroundPlane next = irlsIteration(data_, plane, p_);
    if (!next.valid) break;
    const double moved = std::abs(next.d - plane.d) + std::abs(next.nx - plane.nx) +
                         std::abs(next.ny - plane.ny) + std::abs(next.nz - plane.nz);
    plane = next;
    if (moved < p_.tolerance) break;
  }
  if (plane.valid && p_.refine_band > 0) {
    fit::PlaneMoments inliers;
    for (const Eigen::Vector3d& q : data_)
      if (std::abs(plane.height(q.x(), q.y(), q.z())) <= p_.refine_band) inliers.add(q, 1.0);
    const GroundPlane refined = inliers.plane();
    if (refined.valid) plane = refined;
  }
  if (!plane.valid || plane.angleTo(default_) > p_.max_tilt) {
    ++refused_;
    return prior_;
  }
  prior_ = plane;
  return plane;
}

}  // namespace pedtrack::seg
