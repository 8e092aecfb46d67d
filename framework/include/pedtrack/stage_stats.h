#pragma once
// Per-stage wall-time statistics for run.json.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pedtrack {

class StageStats {
 public:
  StageStats(std::string name, std::string plugin)
      : name_(std::move(name)), plugin_(std::move(plugin)) {}
  void add(double ms) { samples_.push_back(ms); }
  std::size_t calls() const { return samples_.size(); }
  double mean() const;
  double percentile(double p) const;  ///< p in [0, 100], nearest-rank
  double max() const;
  const std::string& name() const { return name_; }
  const std::string& plugin() const { return plugin_; }
  /// The plugin's counters (Plugin::counters) at the end of the run.
  std::vector<std::pair<std::string, long>> counters;

 private:
  std::string name_, plugin_;
  std::vector<double> samples_;
};

}  // namespace pedtrack
