#include "pedtrack/stage_stats.h"

#include <algorithm>
#include <cmath>

namespace pedtrack {
namespace {

// Bins 0.5 % wide (their geometric centre is reported: within 0.25 %) from 1 ns to
// 1000 s; durations outside are clamped into the end bins.
constexpr double kLowMs = 1e-6, kRatio = 1.005;
const double kLogRatio = std::log(kRatio);
const std::size_t kBins = std::size_t(std::ceil(std::log(1e6 / kLowMs) / kLogRatio)) + 1;

std::size_t binOf(double ms) {
  if (!(ms > kLowMs)) return 0;
  return std::min(kBins - 1, std::size_t(std::log(ms / kLowMs) / kLogRatio));
}

double binValue(std::size_t b) {
  return kLowMs * std::exp((double(b) + 0.5) * kLogRatio);
}

}  // namespace

void StageStats::add(double ms) {
  ++calls_;
  sum_ += ms;
  max_ = calls_ == 1 ? ms : std::max(max_, ms);
  if (histogram_.empty() && samples_.size() < kExactSamples) {
    samples_.push_back(ms);
    return;
  }
  if (histogram_.empty()) {  // past the exact window: from now on every sample is binned
    histogram_.assign(kBins, 0);
    for (double s : samples_) ++histogram_[binOf(s)];
    samples_.clear();
    samples_.shrink_to_fit();
  }
  ++histogram_[binOf(ms)];
}

double StageStats::percentile(double p) const {
  if (calls_ == 0) return 0;
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * double(calls_)));
  const std::size_t k = std::min(calls_ - 1, rank == 0 ? 0 : rank - 1);
  if (histogram_.empty()) {
    std::vector<double> v = samples_;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
  }
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < histogram_.size(); ++b) {
    seen += histogram_[b];
    if (seen > k) return std::min(max_, binValue(b));
  }
  return max_;
}

}  // namespace pedtrack
