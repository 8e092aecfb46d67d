#pragma once
// `pedtrack montecarlo`: a pipeline run on N simulations of one scenario, each with its own
// seed and output directory, several at a time on threads.
#include <string>
#include <vector>

#include "pedtrack/pipeline_config.h"

namespace pedtrack::cli {

struct MonteCarloSetup {
  std::string pipeline, scenario, out_dir;
  std::size_t runs = 50;
  unsigned long seed_base = 1;
  std::size_t jobs = 1;
  std::vector<std::string> sets;  ///< the user's --set overrides
  bool progress = true;
};

struct RunOutcome {
  std::size_t index = 0;
  unsigned long seed = 0;
  std::string dir;            ///< out_dir/run_NNN
  std::string status = "ok";  ///< ok | error
  std::string error;          ///< when status is error
  std::size_t frames = 0;     ///< frames processed
  double wall_time_s = 0;
};

/// The pipeline's source section (the first stage) once `scenario` replaces its source.
std::string sourceSection(const MonteCarloSetup& setup, const PluginRegistry& registry);

/// The overrides of run `index`: the scenario as input, no per-point truth, the user's --set
/// overrides, then the run's seed (`seed_base + index`) on `source`.
PipelineOverrides runOverrides(const MonteCarloSetup& setup, const std::string& source,
                               std::size_t index);

/// `out_dir/run_NNN` (at least three digits).
std::string runDir(const MonteCarloSetup& setup, std::size_t index);

/// Loads and creates the pipeline of run 0 and drops it: throws ConfigError (exit 2) for bad
/// configuration before any run starts.
void validateMonteCarlo(const MonteCarloSetup& setup, const std::string& source,
                        const PluginRegistry& registry);

/// Runs every seed, `setup.jobs` at a time, each thread with its own PipelineConfig and Pipeline
/// (the registry is only read). A run that throws or ends with status error is reported in its
/// outcome; the others go on. Outcomes are in run order.
std::vector<RunOutcome> runMonteCarlo(const MonteCarloSetup& setup, const std::string& source,
                                      const PluginRegistry& registry);

}  // namespace pedtrack::cli
