#include "montecarlo_run.h"

#include <mrpt/core/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "pedtrack/pipeline.h"

namespace pedtrack::cli {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// "runs done / N" on stderr: a redrawn bar on a terminal, a line per run otherwise.
class RunProgress {
 public:
  RunProgress(std::size_t total, bool enabled)
      : total_(total), enabled_(enabled), tty_(isatty(fileno(stderr)) != 0) {}

  void runDone() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    if (!enabled_) return;
    const double t = secondsSince(start_);
    if (tty_) {
      const int width = 30, filled = int(double(done_) / total_ * width + 0.5);
      std::fprintf(stderr, "\rmontecarlo [%.*s%*s] %zu/%zu runs %.1fs", filled,
                   "##############################", width - filled, "", done_, total_, t);
    } else {
      std::fprintf(stderr, "montecarlo: %zu/%zu runs, %.1fs\n", done_, total_, t);
    }
    std::fflush(stderr);
  }

  void finish() {
    if (!enabled_) return;
    std::fprintf(stderr, "%smontecarlo: %zu runs in %.2fs\n", tty_ ? "\r\033[K" : "", done_,
                 secondsSince(start_));
  }

 private:
  std::size_t total_, done_ = 0;
  bool enabled_, tty_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
};

RunOutcome runOne(const MonteCarloSetup& setup, const std::string& source,
                  const PluginRegistry& registry, std::size_t index) {
  RunOutcome o;
  o.index = index;
  o.seed = setup.seed_base + index;
  o.dir = runDir(setup, index);
  const auto t0 = Clock::now();
  try {
    // The tracker's side file of an earlier run in this directory would be read as this run's.
    std::error_code ec;
    std::filesystem::remove(o.dir + "/existence.csv", ec);
    const PipelineConfig config =
        PipelineConfig::load(setup.pipeline, runOverrides(setup, source, index), registry);
    Pipeline pipeline(config);
    RunOptions run;
    run.out_dir = o.dir;
    run.progress = false;
    run.point_labels = false;
    const RunSummary s = pipeline.run(run);
    o.frames = s.frames_processed;
    if (s.status != "ok") {
      o.status = "error";
      o.error = s.error.empty() ? "run " + s.status : s.error;
    }
  } catch (const std::exception& e) {
    o.status = "error";
    o.error = e.what();
  }
  o.wall_time_s = secondsSince(t0);
  return o;
}

}  // namespace

std::string sourceSection(const MonteCarloSetup& setup, const PluginRegistry& registry) {
  PipelineOverrides ov;
  ov.input = setup.scenario;
  ov.sets = setup.sets;
  return PipelineConfig::load(setup.pipeline, ov, registry).stages.at(0).section;
}

PipelineOverrides runOverrides(const MonteCarloSetup& setup, const std::string& source,
                               std::size_t index) {
  PipelineOverrides ov;
  ov.input = setup.scenario;
  ov.sets.push_back(source + ".point_truth=false");
  ov.sets.insert(ov.sets.end(), setup.sets.begin(), setup.sets.end());
  ov.sets.push_back(source + ".seed=" + std::to_string(setup.seed_base + index));
  return ov;
}

std::string runDir(const MonteCarloSetup& setup, std::size_t index) {
  return setup.out_dir + mrpt::format("/run_%03zu", index);
}

void validateMonteCarlo(const MonteCarloSetup& setup, const std::string& source,
                        const PluginRegistry& registry) {
  const PipelineConfig config =
      PipelineConfig::load(setup.pipeline, runOverrides(setup, source, 0), registry);
  Pipeline pipeline(config);
}

std::vector<RunOutcome> runMonteCarlo(const MonteCarloSetup& setup, const std::string& source,
                                      const PluginRegistry& registry) {
  std::vector<RunOutcome> outcomes(setup.runs);
  std::atomic<std::size_t> next{0};
  RunProgress progress(setup.runs, setup.progress);
  auto worker = [&] {
    for (std::size_t i = next++; i < setup.runs; i = next++) {
      outcomes[i] = runOne(setup, source, registry, i);
      progress.runDone();
    }
  };
  const std::size_t jobs = std::max<std::size_t>(1, std::min(setup.jobs, setup.runs));
  if (jobs == 1) {
    worker();
  } else {
    std::vector<std::thread> threads;
    for (std::size_t j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
  }
  progress.finish();
  return outcomes;
}

}  // namespace pedtrack::cli
