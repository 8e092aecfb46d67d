// The pipeline INI loader: preprocessing (${VAR}, comments), MRPT's INI parser, section and key
// validation against every built plugin's declaration. Any input must end in a config or a
// ConfigError, never a crash.
#include <cstdint>
#include <string>

#include "pedtrack/errors.h"
#include "pedtrack/pipeline_config.h"
#include "pedtrack/plugin_registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pedtrack::PluginRegistry registry({PEDTRACK_FUZZ_PLUGIN_DIR});
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    pedtrack::PipelineConfig::fromText(text, "fuzz.ini", {}, registry);
  } catch (const std::exception&) {
  }
  return 0;
}
