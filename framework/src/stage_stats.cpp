#include "pedtrack/stage_stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pedtrack {

double StageStats::mean() const {
  if (samples_.empty()) return 0;
  return std::accumulate(samples_.begin(), samples_.end(), 0.0) / samples_.size();
}

double StageStats::percentile(double p) const {
  if (samples_.empty()) return 0;
  std::vector<double> v = samples_;
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * v.size()));
  const std::size_t k = std::min(v.size() - 1, rank == 0 ? 0 : rank - 1);
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

double StageStats::max() const {
  return samples_.empty() ? 0 : *std::max_element(samples_.begin(), samples_.end());
}

}  // namespace pedtrack
