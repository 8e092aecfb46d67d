#pragma once
// Frames of a rawlog, read through the project's own `rawlog` sensor plugin (found on the plugin
// search path like any pipeline's source), so render sees exactly the clouds and poses a
// `pedtrack run` of the same file sees.
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/plugin_registry.h"

namespace pedtrack::render {

class FrameSource {
 public:
  /// Throws ConfigError when the plugin cannot be found or rejects the file.
  FrameSource(const std::string& rawlog, const std::vector<std::string>& plugin_path);
  FrameSource(const FrameSource&) = delete;  // the pipeline refers to config_
  FrameSource& operator=(const FrameSource&) = delete;
  ~FrameSource();

  /// The next frame (index set), or false at the end. Throws DataError for a corrupt entry.
  bool next(Frame& frame);
  /// Fraction of the file read, for progress reporting.
  double progress() const;

 private:
  PluginRegistry registry_;
  PipelineConfig config_;
  std::unique_ptr<Pipeline> pipeline_;
  std::size_t count_ = 0;
};

/// What one cheap pass over the frames (no point clouds) tells the renderer.
struct StreamSummary {
  std::size_t frames = 0;
  double t_first = 0, t_last = 0;
  std::vector<cv::Point2d> sensor_path;  ///< sensor position (fixed frame) of every frame
  /// Frames per second from the timestamps, clamped to [1, 60]; 10 when unknown.
  double rate() const;
};

}  // namespace pedtrack::render
