#pragma once
#include <string>
#include <vector>

namespace pedtrack {
class PluginRegistry;
}  // namespace pedtrack

namespace pedtrack::cli {

// Each subcommand takes the arguments after its name and returns the process exit code.
int runCommand(const std::vector<std::string>& args);
/// `pedtrack ros`: the pipeline as a ROS1 node (ros_topic source, ros_publish stage).
int rosCommand(const std::vector<std::string>& args);
int pluginsCommand(const std::vector<std::string>& args);
int importCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int evalCommand(const std::vector<std::string>& args);
int simCommand(const std::vector<std::string>& args);
int renderCommand(const std::vector<std::string>& args);
int trainCommand(const std::vector<std::string>& args);
int monteCarloCommand(const std::vector<std::string>& args);
/// `pedtrack eval --model`: classifier models scored on labelled clusters.
int evalClassifierCommand(const std::vector<std::string>& args);
/// `pedtrack eval --decisions`: a run's person / non-person decisions against simulated truth.
int evalDecisionsCommand(const std::vector<std::string>& args);
/// `pedtrack eval --kitti`: a run on KITTI object benchmark scans against their labels.
int evalKittiCommand(const std::vector<std::string>& args);
int evalKittiMotCommand(const std::vector<std::string>& args);

struct StageBenchOptions {
  std::string pipeline, input, topic;
  std::vector<std::string> sets, plugin_path;
  long frames = 200, repeat = 5;
  long points = 0;  ///< > 0: every cached cloud resampled to this many points
  std::string csv;  ///< non-empty: the figures also go to this CSV (read by `bench --suite`)
};

/// `pedtrack bench --pipeline`: the stages of a pipeline timed on frames read (and decoded)
/// beforehand, so the figures are the stages' own.
int benchStages(const StageBenchOptions& options);

/// `pedtrack bench --model`: a classifier model timed on batches of a samples file's vectors.
int benchModel(const std::string& model, const std::string& samples, long batch, long repeat);

/// `pedtrack docs`: writes the generated documents (docs/plugins.md, cli.md, scenarios.md).
int docsCommand(const std::vector<std::string>& args);
/// The text `pedtrack --help` prints.
const char* usageText();
/// docs/plugins.md's text: every plugin of `reg`, by category, from its declarations.
std::string pluginsMarkdown(const PluginRegistry& reg);
/// Every scenario section's keys as markdown tables (`pedtrack sim --keys`).
std::string scenarioKeysMarkdown();

/// Installs SIGINT/SIGTERM handlers that ask a running pipeline to stop after the current frame.
void installStopHandlers();

}  // namespace pedtrack::cli
