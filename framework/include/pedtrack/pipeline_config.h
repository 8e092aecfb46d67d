#pragma once
// A pipeline file (MRPT CConfigFile syntax) read, overridden from the command line and validated
// against the plugins' declarations before anything runs.
#include <mrpt/config/CConfigFileMemory.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pedtrack/plugin_registry.h"

namespace pedtrack {

struct PipelineOverrides {
  std::string input;              ///< --input: replaces the source with a replay of this file
  std::string topic;              ///< --topic: bag topic for --input
  std::vector<std::string> sets;  ///< --set section.key=value
  /// Replaces the source's plugin (`pedtrack ros`: ros_topic), keeping the keys of its section
  /// that the new plugin declares (a bag pipeline's topic and frames); `topic` then sets its
  /// `topic`. Not with `input`.
  std::string source_plugin;
  /// A stage appended as {section, plugin} (`pedtrack ros`: its publisher), unless a stage
  /// already runs that plugin; the section gets a fresh name if the file uses this one.
  std::pair<std::string, std::string> append_stage;
};

struct StageConfig {
  std::string section;
  const PluginDescriptor* descriptor = nullptr;
  ParamSet params;
};

class PipelineConfig {
 public:
  /// Throws ConfigError with one line naming file, section and key on any problem.
  static PipelineConfig load(const std::string& file, const PipelineOverrides& overrides,
                             const PluginRegistry& registry);
  /// Same, from text (tests, built-in pipelines); `file` names it in messages and anchors
  /// relative paths.
  static PipelineConfig fromText(const std::string& text, const std::string& file,
                                 const PipelineOverrides& overrides,
                                 const PluginRegistry& registry);

  std::string file;
  std::vector<StageConfig> stages;  ///< stages[0] is the source
  /// The `[faults]` section, when the pipeline has one: its source is wrapped by the fault
  /// injector (fault_injection.h).
  std::optional<ParamSet> faults;
  std::shared_ptr<mrpt::config::CConfigFileMemory> ini;
};

}  // namespace pedtrack
