#include "pedtrack/eval/leg_coverage.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::eval {

long LegCoverage::tracksOnNoPerson(double lone_share) const {
  long n = 0;
  for (const auto& [id, counts] : per_track)
    n += double(counts.second) <= lone_share * double(counts.first);
  return n;
}

LegCoverage legCoverage(const std::vector<EvalFrame>& frames, double threshold) {
  LegCoverage c;
  const auto near = [&](const Object& a, const Object& b) {
    return std::hypot(a.x - b.x, a.y - b.y) <= threshold;
  };
  for (const EvalFrame& f : frames) {
    for (const Object& leg : f.truths) {
      ++c.legs;
      for (const Object& e : f.estimates)
        if (near(leg, e)) {
          ++c.covered;
          break;
        }
    }
    for (const Object& e : f.estimates) {
      const bool supported = std::any_of(f.truths.begin(), f.truths.end(),
                                         [&](const Object& leg) { return near(leg, e); });
      ++c.rows;
      c.unsupported += !supported;
      auto& [rows, near_rows] = c.per_track[e.id];
      ++rows;
      near_rows += supported;
    }
  }
  return c;
}

}  // namespace pedtrack::eval
