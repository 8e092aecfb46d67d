#pragma once
// Per-stage wall-time statistics for run.json, in bounded memory: a live pipeline runs for
// hours (a 40 Hz scanner adds 144,000 samples an hour per stage). Calls, mean and max are exact;
// percentiles are exact (nearest rank) over the first kExactSamples samples and from then on
// read from a histogram of logarithmic bins 0.5 % wide (a relative error of at most 0.25 %).
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pedtrack {

class StageStats {
 public:
  static constexpr std::size_t kExactSamples = 1 << 16;

  StageStats(std::string name, std::string plugin)
      : name_(std::move(name)), plugin_(std::move(plugin)) {}
  void add(double ms);
  std::size_t calls() const { return calls_; }
  double mean() const { return calls_ ? sum_ / double(calls_) : 0; }
  double percentile(double p) const;  ///< p in [0, 100], nearest-rank
  double max() const { return calls_ ? max_ : 0; }
  const std::string& name() const { return name_; }
  const std::string& plugin() const { return plugin_; }
  /// The plugin's counters (Plugin::counters) at the end of the run.
  std::vector<std::pair<std::string, long>> counters;

 private:
  std::string name_, plugin_;
  std::size_t calls_ = 0;
  double sum_ = 0, max_ = 0;
  std::vector<double> samples_;           // the first kExactSamples
  std::vector<std::uint64_t> histogram_;  // every sample, once past kExactSamples
};

}  // namespace pedtrack
