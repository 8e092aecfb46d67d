#pragma once
// Runs a validated pipeline: source → stages → outputs, with per-stage timing.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "pedtrack/outputs.h"
#include "pedtrack/pipeline_config.h"

namespace pedtrack {

struct RunOptions {
  std::string out_dir;  ///< empty: no files written
  bool progress = true;
  long max_frames = -1;  ///< stop after this many frames (<0: all)
  /// Write point_labels.bin (every point's label, each frame) when the pipeline has a segmenter.
  bool point_labels = true;
  /// Non-empty: every frame the source produced is also written to this MRPT rawlog (--record).
  std::string record;
  /// Frames a live source may have waiting for the stages; beyond it the oldest is dropped.
  std::size_t live_queue = 2;
};

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
  static std::atomic<bool>& stopRequested();

 private:
  const PipelineConfig& config_;
  std::unique_ptr<Sensor> source_;
  std::vector<std::unique_ptr<Stage>> stages_;
};

}  // namespace pedtrack
