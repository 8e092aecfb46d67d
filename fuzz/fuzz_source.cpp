// Log replay sources (`rawlog`, `rosbag`; the plugin is chosen at build time): the input is a
// file the source reads to the end, every frame's points built as a stage would. Any file must
// end in frames, a skipped entry or a DataError, never a crash.
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/pipeline_config.h"
#include "pedtrack/plugin_registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pedtrack::PluginRegistry registry({PEDTRACK_FUZZ_PLUGIN_DIR});
  const std::string path = pedtrack::fuzz::inputFile(data, size, "." PEDTRACK_FUZZ_EXT);
  try {
    const auto cfg = pedtrack::PipelineConfig::fromText(
        "[pipeline]\nstages = source\n[source]\nplugin = " PEDTRACK_FUZZ_SOURCE "\nfile = " + path +
            "\n",
        "fuzz.ini", {}, registry);
    pedtrack::Pipeline pipeline(cfg);
    pedtrack::Frame frame;
    for (int i = 0; i < 1000 && pipeline.source().next(frame); ++i) {
      frame.cloud();
      frame = pedtrack::Frame();
    }
  } catch (const std::exception&) {
  }
  return 0;
}
