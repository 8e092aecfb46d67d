// `pedtrack ros PIPELINE.ini`: a pipeline run as a ROS1 node. Its source is replaced by the
// ros_topic plugin (scans from topics, poses from /tf) and a ros_publish stage is appended
// (tracks, people and rviz markers), then it runs like `pedtrack run` (outputs and run.json
// included) until SIGINT/SIGTERM or, with source.end_on_idle, until the topics go quiet.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/text.h"

namespace pedtrack::cli {

int rosCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string pipeline_file;
  PipelineOverrides ov;
  RunOptions run;
  std::vector<std::string> plugin_path;
  opts.add_options()("pipeline", po::value(&pipeline_file)->required(), "pipeline file (INI)")(
      "topic", po::value(&ov.topic),
      "LaserScan / PointCloud2 topic(s) to subscribe to (comma list), instead of the source's "
      "`topic` (default /scan)")(
      "set", po::value(&ov.sets)->composing(),
      "override a key: section.key=value (repeatable; the source is `ros_topic`, the appended "
      "publisher section `publish`)");
  addRunOptions(opts, run, plugin_path);
  po::positional_options_description pos;
  pos.add("pipeline", 1);
  po::variables_map vm;
  if (!parseOptions("ros", "PIPELINE.ini [options]", opts, pos, args, vm)) return 0;
  readRunOptions(vm, run);

  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  const std::vector<std::string> names = registry.names();
  for (const char* needed : {"ros_topic", "ros_publish"})
    if (std::find(names.begin(), names.end(), needed) == names.end())
      throw ConfigError(std::string("pedtrack ros: no plugin '") + needed +
                        "' (a build without ROS: configure with -DPEDTRACK_WITH_ROS=ON, roscpp "
                        "installed, or add its directory with --plugin-path)");
  // ros_topic in place of the source (keeping the keys they share, a bag's topic and frames),
  // ros_publish appended unless the pipeline has a publisher.
  ov.source_plugin = "ros_topic";
  ov.append_stage = {"publish", "ros_publish"};
  const PipelineConfig config = PipelineConfig::load(pipeline_file, ov, registry);
  Pipeline pipeline(config);  // subscribes and advertises: the node is up from here

  if (run.progress) {
    const StageConfig& src = config.stages.front();
    std::cerr << "pedtrack ros: [" << src.section << "] subscribed to "
              << src.params.getString("topic") << "; publishing";
    for (const StageConfig& s : config.stages)
      if (s.descriptor->name == "ros_publish")
        for (const char* k : {"tracks_topic", "people_topic", "markers_topic"})
          if (!s.params.getString(k).empty()) std::cerr << " " << s.params.getString(k);
    std::cerr << " (SIGINT/SIGTERM ends the run)\n";
  }
  installStopHandlers();
  const RunSummary s = pipeline.run(run);
  if (run.progress || s.status == "error") {
    std::fprintf(stderr,
                 "%zu frames received, %zu processed, %zu dropped, %zu failed in %.3f s%s%s\n",
                 s.frames_read, s.frames_processed, s.frames_dropped, s.frames_failed,
                 s.wall_time_s, run.out_dir.empty() ? "" : "; outputs in ", run.out_dir.c_str());
  }
  if (s.status == "error") {
    std::cerr << "error: " << s.error << "\n";
    return exit_code::kFailure;
  }
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
