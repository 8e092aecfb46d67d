// `pedtrack run PIPELINE.ini`: validate, create every plugin, then run and write outputs.
#include <csignal>
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"

namespace pedtrack::cli {

void installStopHandlers() {
  auto handler = [](int) { Pipeline::stopRequested() = true; };
  std::signal(SIGINT, handler);
  std::signal(SIGTERM, handler);
}

int runCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string pipeline_file;
  PipelineOverrides ov;
  RunOptions run;
  std::vector<std::string> plugin_path;
  opts.add_options()("pipeline", po::value(&pipeline_file)->required(), "pipeline file (INI)")(
      "input", po::value(&ov.input),
      "replay this .rawlog or .bag, or simulate this scenario .ini, instead of the pipeline's "
      "source")("topic", po::value(&ov.topic), "bag topic(s) to replay with --input (comma list)")(
      "set", po::value(&ov.sets)->composing(), "override a key: section.key=value (repeatable)");
  addRunOptions(opts, run, plugin_path);
  po::positional_options_description pos;
  pos.add("pipeline", 1);
  po::variables_map vm;
  if (!parseOptions("run", "PIPELINE.ini [options]", opts, pos, args, vm)) return 0;
  readRunOptions(vm, run);

  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  const PipelineConfig config = PipelineConfig::load(pipeline_file, ov, registry);
  Pipeline pipeline(config);  // every plugin configured before anything is written

  installStopHandlers();
  const RunSummary s = pipeline.run(run);
  if (run.progress || s.status != "ok") {
    std::fprintf(stderr,
                 "%zu frames read, %zu processed, %zu failed in %.3f s (%.0f frames/s)%s%s\n",
                 s.frames_read, s.frames_processed, s.frames_failed, s.wall_time_s,
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
