#pragma once
// Runs a validated pipeline: source → stages → outputs, with per-stage timing.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/outputs.h"
#include "pedtrack/pipeline_config.h"
#include "pedtrack/run_options.h"
#include "pedtrack/stop_request.h"

namespace pedtrack {

class Pipeline {
 public:
  /// Creates every plugin; throws ConfigError when a plugin rejects its configuration.
  explicit Pipeline(const PipelineConfig& config);
  ~Pipeline();
  /// Runs to the end of the source. Returns the summary; status "error" when the source failed.
  /// Outputs are complete for every frame processed before a failure.
  RunSummary run(const RunOptions& options);
  Sensor& source() { return *source_; }
  /// The processing stages in run order (benchmarks drive them on cached frames).
  std::vector<Stage*> stages() const;

  /// Set by SIGINT/SIGTERM handlers: the run stops after the current frame and writes outputs.
  static std::atomic<bool>& stopRequested() { return pedtrack::stopRequested(); }

 private:
  const PipelineConfig& config_;
  std::unique_ptr<Sensor> source_;
  std::vector<std::unique_ptr<Stage>> stages_;
};

}  // namespace pedtrack
