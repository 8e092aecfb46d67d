#pragma once
#include "pedtrack/frame.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/plugin_registry.h"
// Helpers shared by the test files: paths, running the host binary, temporary directories.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pedtrack::test {

/// A sanitizer build (scripts/check.sh, PEDTRACK_SANITIZED): there the longest simulations and
/// pipelines run 5-40 times slower, so those tests run shorter versions of the same code paths
/// (fewer frames, smaller clouds) to keep the suite inside CI's time.
#ifdef PEDTRACK_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

struct CommandResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs `pedtrack ARGS` (arguments shell-quoted) and captures its output.
CommandResult runHost(const std::vector<std::string>& args);
/// Runs a shell command line and captures its output.
CommandResult runShell(const std::string& command_line);
/// Live-device tests measured on a quiet core (scripts/live_latency.sh runs them under `taskset`):
/// a loopback device's thread calls this to move to the CPU named by $PEDTRACK_DEVICE_CPU, off
/// the core the reader and the stages are pinned to. Without it, nothing changes.
void pinToDeviceCpu();
/// $PEDTRACK_LIVE_FRAMES when set (a longer latency measurement), else `fallback`.
std::size_t liveFrames(std::size_t fallback);
/// A fresh empty directory named after `tag`: under the build tree's Testing/work, or under
/// $PEDTRACK_TEST_WORK when set (copies of a test run side by side).
std::string freshDir(const std::string& tag);
/// ../shared/data (or $PEDTRACK_DATA): empty when absent.
std::string sharedDataDir();
std::string mrptDataset(const std::string& name);
std::string readFile(const std::string& path);
void writeFile(const std::string& path, const std::string& text);
std::vector<std::string> lines(const std::string& text);
/// The columns of a CSV file with a header line, by name (an empty field: NaN).
std::map<std::string, std::vector<double>> readCsv(const std::string& path);
/// A number field of run.json (flat, written by writeRunJson).
/// The first `"key": <number>` of a JSON text, skipping keys whose value is not a number.
double jsonValue(const std::string& json, const std::string& key);
double jsonNumber(const std::string& json, const std::string& key);
/// `pedtrack eval --json` of a run directory's truth.csv and tracks.csv (and `extra` options);
/// fails the test when eval does.
std::string evalRunJson(const std::string& dir, const std::vector<std::string>& extra = {});

}  // namespace pedtrack::test

namespace pedtrack::test {
/// Ends the test process as skipped (CTest SKIP_RETURN_CODE 77), naming the missing path, when
/// `path` does not exist: a user's fresh clone has no ../shared/data.
void requireData(const std::string& path);
/// The shared data file at `relative` (under ../shared/data or $PEDTRACK_DATA), or the process
/// ends as skipped when it is absent (requireData).
std::string requiredDataFile(const std::string& relative);
/// requiredDataFile, with PEDTRACK_DATA set to the shared data folder for what names
/// ${PEDTRACK_DATA}/... (the training datasets in configs/training/).
std::string requiredDataFileExported(const std::string& relative);
}  // namespace pedtrack::test

namespace pedtrack::test {
/// The plugins of this build tree.
const PluginRegistry& testRegistry();
/// Every frame the source of `pipeline_text` yields (`file` names it in messages).
std::vector<Frame> readAllFrames(const std::string& pipeline_text,
                                 const std::string& file = "t.ini");
/// Hands every frame of that source to `each` until its end, or until it throws (a bag cut short
/// fails after its good frames): what it threw, "" at a clean end.
std::string readFramesUntilError(const std::string& pipeline_text,
                                 const std::function<void(const Frame&)>& each);
/// The pipeline of `pipeline_text` with its stages driven by the test on frames of its own, as a
/// run drives them (the source is built but never read).
struct DrivenStages {
  PipelineConfig config;
  std::unique_ptr<Pipeline> pipeline;
  explicit DrivenStages(const std::string& pipeline_text, const std::string& file = "t.ini");
  DrivenStages(const DrivenStages&) = delete;  // the pipeline holds on to `config`
  DrivenStages& operator=(const DrivenStages&) = delete;
  /// Every stage, in order, on f.
  void run(Frame& f);
};
}  // namespace pedtrack::test
