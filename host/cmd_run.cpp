// `pedtrack run PIPELINE.ini`: validate, create every plugin, then run and write outputs.
#include "commands.h"
#include "pipeline_command.h"

namespace pedtrack::cli {

int runCommand(const std::vector<std::string>& args) {
  PipelineCommand c;
  po::options_description opts =
      pipelineOptions(c, "bag topic(s) to replay with --input (comma list)",
                      "override a key: section.key=value (repeatable)");
  opts.add_options()("input", po::value(&c.overrides.input),
                     "replay this .rawlog or .bag, or simulate this scenario .ini, instead of the "
                     "pipeline's source");
  if (!parsePipelineCommand("run", opts, args, c)) return 0;
  PluginRegistry registry(PluginRegistry::defaultSearchPath(c.plugin_path));
  const PipelineConfig config = PipelineConfig::load(c.pipeline_file, c.overrides, registry);
  Pipeline pipeline(config);  // every plugin configured before anything is written
  return runToEnd(pipeline, c.run);
}

}  // namespace pedtrack::cli
