#include "frame_source.h"

#include <algorithm>

namespace pedtrack::render {
namespace {

PipelineConfig sourceOnly(const std::string& rawlog, const PluginRegistry& registry) {
  // The file goes in as --input does for `pedtrack run`: paths with spaces, ';' or '#' survive
  // (they would not as INI text), and a .bag replays through the rosbag source.
  PipelineOverrides ov;
  ov.input = rawlog;
  return PipelineConfig::fromText("[pipeline]\nstages = source\n[source]\nplugin = rawlog\n",
                                  "pedtrack render", ov, registry);
}

}  // namespace

FrameSource::FrameSource(const std::string& rawlog, const std::vector<std::string>& plugin_path)
    : registry_(PluginRegistry::defaultSearchPath(plugin_path)),
      config_(sourceOnly(rawlog, registry_)),
      pipeline_(std::make_unique<Pipeline>(config_)) {}

FrameSource::~FrameSource() = default;

bool FrameSource::next(Frame& frame) {
  frame = Frame();
  frame.index = count_;
  if (!pipeline_->source().next(frame)) return false;
  ++count_;
  return true;
}

double FrameSource::progress() const {
  return pipeline_->source().progress();
}

double StreamSummary::rate() const {
  if (frames < 2 || !(t_last > t_first)) return 10;
  return std::clamp((frames - 1) / (t_last - t_first), 1.0, 60.0);
}

}  // namespace pedtrack::render
