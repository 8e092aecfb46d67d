// `pedtrack ros PIPELINE.ini`: a pipeline run as a ROS1 node. Its source is replaced by the
// ros_topic plugin (scans from topics, poses from /tf) and a ros_publish stage is appended
// (tracks, people and rviz markers), then it runs like `pedtrack run` (outputs and run.json
// included) until SIGINT/SIGTERM or, with source.end_on_idle, until the topics go quiet.
#include <algorithm>
#include <iostream>

#include "commands.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/text.h"
#include "pipeline_command.h"

namespace pedtrack::cli {

int rosCommand(const std::vector<std::string>& args) {
  PipelineCommand c;
  const po::options_description opts = pipelineOptions(
      c,
      "LaserScan / PointCloud2 topic(s) to subscribe to (comma list; a detector's PoseArray "
      "topics with --set source.detections=true), instead of the source's "
      "`topic` (default /scan)",
      "override a key: section.key=value (repeatable; the source is `ros_topic`, the appended "
      "publisher section `publish`)");
  if (!parsePipelineCommand("ros", opts, args, c)) return 0;

  PluginRegistry registry(PluginRegistry::defaultSearchPath(c.plugin_path));
  const std::vector<std::string> names = registry.names();
  for (const char* needed : {"ros_topic", "ros_publish"})
    if (std::find(names.begin(), names.end(), needed) == names.end())
      throw ConfigError(std::string("pedtrack ros: no plugin '") + needed +
                        "' (a build without ROS: configure with -DPEDTRACK_WITH_ROS=ON, roscpp "
                        "installed, or add its directory with --plugin-path)");
  // ros_topic in place of the source (keeping the keys they share, a bag's topic and frames),
  // ros_publish appended unless the pipeline has a publisher.
  c.overrides.source_plugin = "ros_topic";
  c.overrides.append_stage = {"publish", "ros_publish"};
  const PipelineConfig config = PipelineConfig::load(c.pipeline_file, c.overrides, registry);
  Pipeline pipeline(config);  // subscribes and advertises: the node is up from here

  if (c.run.progress) {
    const StageConfig& src = config.stages.front();
    std::cerr << "pedtrack ros: [" << src.section << "] subscribed to "
              << src.params.getString("topic") << "; publishing";
    for (const StageConfig& s : config.stages)
      if (s.descriptor->name == "ros_publish")
        for (const char* k : {"tracks_topic", "people_topic", "markers_topic"})
          if (!s.params.getString(k).empty()) std::cerr << " " << s.params.getString(k);
    std::cerr << " (SIGINT/SIGTERM ends the run)\n";
  }
  return runToEnd(pipeline, c.run, {"received", false});
}

}  // namespace pedtrack::cli
