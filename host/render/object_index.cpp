#include "object_index.h"

#include <algorithm>

namespace pedtrack::render {

ObjectIndex::ObjectIndex(std::vector<ObjectRow> rows) : rows_(std::move(rows)) {
  for (const auto& r : rows_) {
    by_time_.push_back(&r);
    if (r.frame >= 0) by_frame_.emplace(r.frame, &r);
  }
  auto earlier = [](const ObjectRow* a, const ObjectRow* b) { return a->t < b->t; };
  std::stable_sort(by_time_.begin(), by_time_.end(), earlier);
  for (const ObjectRow* r : by_time_) paths_[r->id].push_back(r);
}

FrameRows ObjectIndex::at(double t, long frame, double tolerance) const {
  FrameRows out;
  auto it = std::lower_bound(by_time_.begin(), by_time_.end(), t - tolerance,
                             [](const ObjectRow* r, double v) { return r->t < v; });
  for (; it != by_time_.end() && (*it)->t <= t + tolerance; ++it) out.rows.push_back(*it);
  if (out.rows.empty()) {
    auto [lo, hi] = by_frame_.equal_range(frame);
    for (; lo != hi; ++lo) out.rows.push_back(lo->second);
  }
  if (!out.rows.empty()) out.t = out.rows.front()->t;
  return out;
}

std::vector<const ObjectRow*> ObjectIndex::window(const std::vector<const ObjectRow*>& path,
                                                  double t0, double t1) {
  auto lo = std::lower_bound(path.begin(), path.end(), t0,
                             [](const ObjectRow* r, double v) { return r->t < v; });
  auto hi =
      std::upper_bound(lo, path.end(), t1, [](double v, const ObjectRow* r) { return v < r->t; });
  return {lo, hi};
}

}  // namespace pedtrack::render
