#include "pipeline_command.h"

#include <csignal>
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "pedtrack/errors.h"

namespace pedtrack::cli {

void installStopHandlers() {
  auto handler = [](int) { stopRequested() = true; };
  std::signal(SIGINT, handler);
  std::signal(SIGTERM, handler);
}

po::options_description pipelineOptions(PipelineCommand& c, const std::string& topic_help,
                                        const std::string& set_help) {
  po::options_description opts("options");
  opts.add_options()("pipeline", po::value(&c.pipeline_file)->required(), "pipeline file (INI)")(
      "topic", po::value(&c.overrides.topic), topic_help.c_str())(
      "set", po::value(&c.overrides.sets)->composing(), set_help.c_str());
  return opts;
}

bool parsePipelineCommand(const std::string& command, const po::options_description& options,
                          const std::vector<std::string>& args, PipelineCommand& c) {
  po::options_description all(options);
  addRunOptions(all, c.run, c.plugin_path);
  po::positional_options_description pos;
  pos.add("pipeline", 1);
  po::variables_map vm;
  if (!parseOptions(command, "PIPELINE.ini [options]", all, pos, args, vm)) return false;
  readRunOptions(vm, c.run);
  return true;
}

int runToEnd(Pipeline& pipeline, const RunOptions& run, const RunReport& report) {
  installStopHandlers();
  const RunSummary s = pipeline.run(run);
  if (run.progress || s.status == "error" || (report.unless_ok && s.status != "ok")) {
    std::fprintf(stderr,
                 "%zu frames %s, %zu processed, %zu dropped, %zu failed in %.3f s (%.0f "
                 "frames/s)%s%s\n",
                 s.frames_read, report.frames_word, s.frames_processed, s.frames_dropped,
                 s.frames_failed, s.wall_time_s,
                 s.wall_time_s > 0 ? s.frames_processed / s.wall_time_s : 0.0,
                 run.out_dir.empty() ? "" : "; outputs in ", run.out_dir.c_str());
  }
  if (s.status == "error") {
    std::cerr << "error: " << s.error << "\n";
    return exit_code::kFailure;
  }
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
