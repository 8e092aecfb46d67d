#include "pedtrack/sim/clearance.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace pedtrack::sim {

std::vector<PersonClearance> personClearance(const RangeImage& img, const RayTable& rays,
                                             double cap) {
  struct Hit {
    Eigen::Vector3d p;
    int owner;
  };
  std::vector<Hit> people, others;
  for (int r = 0; r < img.rings; ++r)
    for (int c = 0; c < img.cols; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * img.cols + c;
      const int owner = img.owner[i];
      if (owner == kOwnerGround || !std::isfinite(img.range[i])) continue;
      (owner > 0 ? people : others).push_back({img.range[i] * rays.dir(r, c), owner});
    }
  // Each person's box grown by the cap: only hits inside some box can be closer than the cap.
  std::map<int, std::pair<Eigen::Vector3d, Eigen::Vector3d>> box;
  for (const Hit& h : people) {
    auto it = box.find(h.owner);
    if (it == box.end()) {
      box[h.owner] = {h.p, h.p};
    } else {
      it->second.first = it->second.first.cwiseMin(h.p);
      it->second.second = it->second.second.cwiseMax(h.p);
    }
  }
  std::vector<PersonClearance> out;
  for (const auto& [id, b] : box) {
    const Eigen::Vector3d lo = b.first.array() - cap, hi = b.second.array() + cap;
    auto inside = [&](const Eigen::Vector3d& p) {
      return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    };
    std::vector<const Eigen::Vector3d*> near, mine;
    for (const Hit& h : people) (h.owner == id ? mine : near).push_back(&h.p);
    near.erase(std::remove_if(near.begin(), near.end(),
                              [&](const Eigen::Vector3d* p) { return !inside(*p); }),
               near.end());
    for (const Hit& h : others)
      if (inside(h.p)) near.push_back(&h.p);
    // Sorted by x, each of the person's hits scans only the others within the best distance so
    // far along x.
    std::sort(near.begin(), near.end(),
              [](const Eigen::Vector3d* a, const Eigen::Vector3d* b) { return a->x() < b->x(); });
    double best2 = cap * cap;
    for (const Eigen::Vector3d* a : mine) {
      auto it = std::lower_bound(near.begin(), near.end(), a->x() - std::sqrt(best2),
                                 [](const Eigen::Vector3d* p, double x) { return p->x() < x; });
      for (; it != near.end() && (*it)->x() <= a->x() + std::sqrt(best2); ++it)
        best2 = std::min(best2, (*a - **it).squaredNorm());
    }
    out.push_back({id, static_cast<float>(std::sqrt(best2))});
  }
  return out;
}

}  // namespace pedtrack::sim
