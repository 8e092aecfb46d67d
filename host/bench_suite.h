#pragma once
// `pedtrack bench --suite`: one command that measures every shipped pipeline's speed, its cost
// against points and people per frame, every tracker's accuracy on every shipped scenario it
// applies to, and an hour-long soak, and writes BENCHMARKS.md with its PNG plots. Each timing
// runs in a child `pedtrack bench --pipeline` process of its own (its own peak RSS, one core);
// the accuracy runs go on `jobs` threads.
#include <string>
#include <vector>

#include "child_process.h"

namespace pedtrack::cli {

struct SuiteOptions {
  std::string out = "BENCHMARKS.md";  ///< the report; its PNGs go to docs/bench/ beside it
  std::string work = "out/bench";     ///< runs, scenarios made for the sweeps, logs
  std::string source_dir;             ///< the checkout with configs/ ("" : found from here)
  bool quick = false;                 ///< seconds instead of minutes: every part, tiny sizes
  double soak_seconds = 3600;         ///< simulated time of each soak run
  std::size_t jobs = 2;               ///< accuracy runs at once
  std::vector<std::string> plugin_path;
};

/// What every part of the suite needs: paths, the child-process runner, progress lines.
struct SuiteContext {
  SuiteOptions options;
  std::string exe;         ///< this pedtrack
  std::string source_dir;  ///< absolute; configs/ is under it
  std::string work;        ///< absolute
  std::string plots_dir;   ///< absolute docs/bench beside the report
  std::string plots_rel;   ///< the same, relative to the report ("docs/bench")
  std::string log;         ///< every child's output, appended

  std::string config(const std::string& name) const;    ///< source_dir/configs/NAME
  std::string scenario(const std::string& name) const;  ///< source_dir/configs/scenarios/NAME
  /// Prints "bench: WHAT (elapsed)" on stderr: the suite runs for many minutes.
  void progress(const std::string& what) const;
  /// The `pedtrack` arguments run as a child, logged; throws DataError naming `what` and the
  /// log's last lines when it does not exit 0.
  ChildResult run(const std::vector<std::string>& args, const std::string& what,
                  double sample_every_s = 0) const;
  /// A copy of scenario `name` with its [crowd] count set to `people`, in work/scenarios/.
  std::string crowdScenario(const std::string& name, int people) const;
};

/// One pipeline timed by a child `pedtrack bench --pipeline … --csv`.
struct StageFigures {
  std::string stage, plugin;
  double p50 = 0, p99 = 0, mean = 0, max = 0;  ///< ms per frame
};
struct PipelineFigures {
  std::vector<StageFigures> stages;  ///< in pipeline order, then "all stages"
  double frames = 0, points = 0, clusters = 0, tracks = 0;  ///< per frame (frames: cached)
  long failed = 0;
  long peak_rss_kb = 0;
  const StageFigures& total() const { return stages.back(); }
  const StageFigures* stage(const std::string& plugin) const;  ///< by plugin name; null if none
  double framesPerSecond() const { return total().mean > 0 ? 1000.0 / total().mean : 0; }
};
PipelineFigures benchPipeline(const SuiteContext& ctx, const std::string& label,
                              const std::string& pipeline, const std::string& input,
                              const std::vector<std::string>& sets, long frames, long repeat,
                              long points = 0);

/// The parts, each returning its Markdown section.
std::string speedSection(const SuiteContext& ctx);
std::string scalingSection(const SuiteContext& ctx);
std::string accuracySection(const SuiteContext& ctx);
std::string soakSection(const SuiteContext& ctx);

/// BENCHMARKS.md from this line on is measured by hand (real data, Monte Carlo sets): the suite
/// writes its own part above it and keeps this part as it is.
constexpr const char* kHandMeasuredMarker =
    "<!-- Measured by the commands given below; pedtrack bench --suite keeps this part as it is. "
    "-->";

int benchSuite(const SuiteOptions& options);

}  // namespace pedtrack::cli
