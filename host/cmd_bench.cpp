// `pedtrack bench`: replay throughput of the host plus the rawlog reader, on a synthetic log of
// 2D scans (or on --input), with no processing stages. Meaningful in a Release build only.
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "bench_suite.h"
#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"

namespace pedtrack::cli {
namespace {

// A UTM-30LX-like scanner (270°, 0.25°, 40 Hz) in a 10 m x 6 m room with a person-sized
// obstacle walking across it, so ranges change from scan to scan as in a real log.
void writeSyntheticLog(const std::string& path, long scans, int beams) {
  mrpt::io::CFileGZOutputStream file;
  if (!file.open(path)) throw DataError(path + ": cannot write");
  auto ar = mrpt::serialization::archiveFrom(file);
  mrpt::obs::CObservation2DRangeScan scan;
  scan.sensorLabel = "LASER";
  scan.aperture = static_cast<float>(270.0 * M_PI / 180.0);
  scan.maxRange = 30.f;
  scan.resizeScan(beams);
  const double t0 = 1.7e9;
  for (long k = 0; k < scans; ++k) {
    const double px = -4 + std::fmod(k * 0.025 * 1.2, 8.0), py = 1.5;  // walker at 1.2 m/s
    for (int i = 0; i < beams; ++i) {
      const double a = -scan.aperture / 2 + scan.aperture * i / (beams - 1);
      const double c = std::cos(a), s = std::sin(a);
      double r = 30;
      if (std::abs(c) > 1e-9) r = std::min(r, (c > 0 ? 5.0 : -5.0) / c);
      if (std::abs(s) > 1e-9) r = std::min(r, (s > 0 ? 3.0 : -3.0) / s);
      // Ray/circle (radius 0.25 m) intersection for the walker.
      const double b = c * px + s * py, disc = b * b - (px * px + py * py - 0.0625);
      if (disc >= 0 && b - std::sqrt(disc) > 0) r = std::min(r, b - std::sqrt(disc));
      scan.setScanRange(i, static_cast<float>(r));
      scan.setScanRangeValidity(i, true);
    }
    scan.timestamp = mrpt::Clock::fromDouble(t0 + k * 0.025);
    ar << scan;
  }
}

// Runs a source-only pipeline without progress output and prints its throughput: `what`
// names the measurement, `unit` what a frame is ("scans", "frames").
int runAndReport(const PipelineConfig& config, const std::string& out, const char* what,
                 const char* unit) {
  Pipeline pipeline(config);
  RunOptions run;
  run.out_dir = out;
  run.progress = false;
  const RunSummary s = pipeline.run(run);
  if (s.status == "error") throw DataError(s.error);
  const StageStats& src = s.stages.front();
  std::printf("build: %s, %u hardware threads\n", PEDTRACK_BUILD_TYPE,
              std::thread::hardware_concurrency());
  std::printf("%s: %zu %s in %.3f s = %.0f %s/s\n", what, s.frames_read, unit, s.wall_time_s,
              s.frames_read / s.wall_time_s, unit);
  std::printf("source next(): mean %.4f ms, p50 %.4f ms, p99 %.4f ms, max %.4f ms\n", src.mean(),
              src.percentile(50), src.percentile(99), src.max());
  return exit_code::kOk;
}

// The `sim` source alone: ray casting plus building the MRPT observations, one thread.
int benchScenario(const std::string& scenario, const std::string& out,
                  const std::vector<std::string>& plugin_path) {
  if (!std::filesystem::is_regular_file(scenario))
    throw ConfigError("--scenario '" + scenario + "': no such file");
  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  const PipelineConfig config =
      PipelineConfig::fromText("[pipeline]\nstages = source\n[source]\nplugin = sim\nscenario = " +
                                   std::filesystem::absolute(scenario).string() + "\n",
                               "pedtrack bench", {}, registry);
  return runAndReport(config, out, "simulation (sim source, one thread, no stages)", "frames");
}

}  // namespace

int benchCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  long scans = 100000;
  int beams = 1081;
  std::string input, out, scenario, pipeline, topic;
  long frames = 200, repeat = 5;
  std::vector<std::string> plugin_path, sets;
  std::string model, samples;
  long batch = 100, points = 0;
  std::string csv;
  SuiteOptions suite;
  opts.add_options()("scans", po::value(&scans)->default_value(100000),
                     "synthetic 2D scans to replay")(
      "beams", po::value(&beams)->default_value(1081), "beams per synthetic scan")(
      "input", po::value(&input), "bench this rawlog instead of a synthetic one")(
      "scenario", po::value(&scenario),
      "bench the simulator on this scenario instead (frames simulated per second)")(
      "out", po::value(&out), "directory for run.json")(
      "pipeline", po::value(&pipeline),
      "bench this pipeline's stages instead, each timed on frames decoded beforehand")(
      "frames", po::value(&frames)->default_value(200), "--pipeline: frames to read and cache")(
      "repeat", po::value(&repeat)->default_value(5), "--pipeline: passes over the cached frames")(
      "topic", po::value(&topic), "--pipeline with a bag --input: its topics")(
      "set", po::value(&sets)->composing(), "--pipeline: override a key, section.key=value")(
      "points", po::value(&points)->default_value(0),
      "--pipeline: resample every frame's cloud to this many points first (0: as read)")(
      "csv", po::value(&csv), "--pipeline: also write the figures to this CSV")(
      "suite", "run the whole benchmark suite and write --report (BENCHMARKS.md)")(
      "report", po::value(&suite.out)->default_value("BENCHMARKS.md"), "--suite: the report")(
      "work", po::value(&suite.work)->default_value("out/bench"),
      "--suite: directory for its runs and logs")(
      "source", po::value(&suite.source_dir),
      "--suite: the checkout whose configs/ it runs (default: found from here)")(
      "quick", "--suite: tiny sizes, a minute or two, to check the suite itself")(
      "soak-seconds", po::value(&suite.soak_seconds)->default_value(3600),
      "--suite: simulated seconds of each soak run")(
      "jobs", po::value(&suite.jobs)->default_value(2), "--suite: accuracy runs at once")(
      "model", po::value(&model), "bench this classifier model instead (with --samples)")(
      "samples", po::value(&samples), "--model: labelled samples CSV whose vectors are scored")(
      "batch", po::value(&batch)->default_value(100), "--model: clusters scored per call")(
      "plugin-path", po::value(&plugin_path)->composing(), "extra plugin directory (repeatable)");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!parseOptions("bench", "[options]", opts, pos, args, vm)) return 0;
  if (scans < 1 || beams < 2)
    throw ConfigError("pedtrack bench: --scans must be >= 1 and --beams >= 2");

  if (vm.count("suite")) {
    if (!(suite.soak_seconds >= 1 && suite.soak_seconds <= 36000))
      throw ConfigError("pedtrack bench: --soak-seconds must be within [1, 36000]");
    if (suite.jobs < 1) throw ConfigError("pedtrack bench: --jobs must be >= 1");
    suite.quick = vm.count("quick") > 0;
    suite.plugin_path = plugin_path;
    return benchSuite(suite);
  }
  if (!model.empty()) return benchModel(model, samples, batch, repeat);
  if (!pipeline.empty()) {
    if (frames < 1 || repeat < 1)
      throw ConfigError("pedtrack bench: --frames and --repeat must be >= 1");
    if (points < 0) throw ConfigError("pedtrack bench: --points must be >= 0");
    StageBenchOptions o;
    o.pipeline = pipeline;
    o.input = input;
    o.topic = topic;
    o.sets = sets;
    o.plugin_path = plugin_path;
    o.frames = frames;
    o.repeat = repeat;
    o.points = points;
    o.csv = csv;
    return benchStages(o);
  }
  if (!scenario.empty()) return benchScenario(scenario, out, plugin_path);
  std::string log = input;
  if (log.empty()) {
    log = (std::filesystem::temp_directory_path() /
           ("pedtrack-bench-" + std::to_string(getpid()) + ".rawlog"))
              .string();
    std::fprintf(stderr, "writing %ld synthetic scans of %d beams to %s\n", scans, beams,
                 log.c_str());
    writeSyntheticLog(log, scans, beams);
  }
  struct Cleanup {
    std::string path;
    ~Cleanup() {
      if (!path.empty()) std::filesystem::remove(path);
    }
  } cleanup{input.empty() ? log : std::string()};

  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  PipelineOverrides ov;
  ov.input = log;
  ov.sets = {"source.rate=max"};
  const PipelineConfig config = PipelineConfig::fromText(
      "[pipeline]\nstages = source\n[source]\nplugin = rawlog\n", "pedtrack bench", ov, registry);
  return runAndReport(config, out, "replay (host + rawlog reader, no stages)", "scans");
}

}  // namespace pedtrack::cli
