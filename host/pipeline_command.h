#pragma once
// What `pedtrack run` and `pedtrack ros` share: the pipeline file, its overrides and the run
// options on the command line, and running the pipeline to its summary and exit code.
#include <string>
#include <vector>

#include "options.h"
#include "pedtrack/pipeline.h"

namespace pedtrack::cli {

struct PipelineCommand {
  std::string pipeline_file;
  PipelineOverrides overrides;
  RunOptions run;
  std::vector<std::string> plugin_path;
};

/// The pipeline (first positional argument), --topic and --set, whose meanings for the command
/// `topic_help` and `set_help` say, then the run options (addRunOptions).
po::options_description pipelineOptions(PipelineCommand& c, const std::string& topic_help,
                                        const std::string& set_help);
/// Parses `args` into `c` (false on --help) with the positional pipeline file.
bool parsePipelineCommand(const std::string& command, const po::options_description& options,
                          const std::vector<std::string>& args, PipelineCommand& c);

/// How a command reports the end of its run.
struct RunReport {
  const char* frames_word = "read";  ///< "read" (a file, a device) or "received" (topics)
  /// The summary also without progress output when the run ended other than "ok" (run: an
  /// interrupted replay is worth a line); else only when it failed (ros: SIGINT is its end).
  bool unless_ok = true;
};

/// Runs `pipeline` until its source ends or SIGINT/SIGTERM, prints the summary line (with
/// progress output, and as `report` says without) and returns the exit code: 1 when the source
/// failed.
int runToEnd(Pipeline& pipeline, const RunOptions& run, const RunReport& report = {});

}  // namespace pedtrack::cli
