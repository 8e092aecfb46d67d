// `pedtrack ros PIPELINE.ini`: a pipeline run as a ROS1 node. Its source is replaced by the
// ros_topic plugin (scans from topics, poses from /tf) and a ros_publish stage is appended
// (tracks, people and rviz markers), then it runs like `pedtrack run` (outputs and run.json
// included) until SIGINT/SIGTERM or, with source.end_on_idle, until the topics go quiet.
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/text.h"

namespace pedtrack::cli {
namespace {

// The pipeline file's sections and keys, in order, after comments, ${VAR} and @define are
// resolved: the text handed back to PipelineConfig::fromText is plain.
struct Ini {
  std::vector<std::string> sections;
  std::vector<std::vector<std::pair<std::string, std::string>>> keys;

  std::size_t section(const std::string& name) {
    const auto it = std::find(sections.begin(), sections.end(), name);
    if (it != sections.end()) return it - sections.begin();
    sections.push_back(name);
    keys.emplace_back();
    return sections.size() - 1;
  }
  std::string get(const std::string& s, const std::string& key) {
    for (const auto& [k, v] : keys[section(s)])
      if (k == key) return v;
    return {};
  }
  void set(const std::string& s, const std::string& key, const std::string& value) {
    auto& kv = keys[section(s)];
    for (auto& p : kv)
      if (p.first == key) {
        p.second = value;
        return;
      }
    kv.emplace_back(key, value);
  }
  std::string text() const {
    std::ostringstream os;
    for (std::size_t i = 0; i < sections.size(); ++i) {
      os << "[" << sections[i] << "]\n";
      for (const auto& [k, v] : keys[i]) os << k << " = " << v << "\n";
    }
    return os.str();
  }
};

Ini readIni(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw ConfigError(file + ": pipeline file not found");
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  Ini ini;
  try {
    mrpt::config::CConfigFileMemory raw(preprocessPipelineText(ss.str(), file));
    std::vector<std::string> sections;
    raw.getAllSections(sections);
    for (const auto& s : sections) {
      std::vector<std::string> keys;
      raw.getAllKeys(s, keys);
      for (const auto& k : keys) ini.set(s, k, trim(raw.read_string(s, k, "")));
    }
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(file + ": " + oneLine(e.what()));
  }
  return ini;
}

// The pipeline made a node: ros_topic as the source (keeping the keys it shares with the
// original source, a rosbag's topic and frames for one), ros_publish appended unless present.
std::string nodePipelineText(const std::string& file, const std::string& topic,
                             std::vector<std::string>& sets, const PluginRegistry& registry) {
  const PluginDescriptor& source_plugin = registry.get("ros_topic");
  Ini ini = readIni(file);
  // `--set pipeline.stages=...` chooses the stages the publisher is appended to.
  for (auto it = sets.begin(); it != sets.end();) {
    const auto eq = it->find('=');
    if (it->rfind("pipeline.", 0) == 0 && eq != std::string::npos) {
      ini.set("pipeline", trim(it->substr(9, eq - 9)), trim(it->substr(eq + 1)));
      it = sets.erase(it);
    } else {
      ++it;
    }
  }
  std::vector<std::string> stages = splitList(ini.get("pipeline", "stages"));
  if (stages.empty())
    throw ConfigError(file +
                      ": [pipeline] stages: missing required key (the stage sections in "
                      "run order)");
  const std::string source = stages.front();
  if (ini.get(source, "plugin") != "ros_topic") {
    std::vector<std::pair<std::string, std::string>> kept{{"plugin", "ros_topic"}};
    for (const auto& [k, v] : ini.keys[ini.section(source)])
      for (const ParamSpec& p : source_plugin.params)
        if (p.name == k) kept.emplace_back(k, v);
    ini.keys[ini.section(source)] = kept;
  }
  if (!topic.empty()) ini.set(source, "topic", topic);
  const bool has_publisher = std::any_of(stages.begin(), stages.end(), [&](const std::string& s) {
    return ini.get(s, "plugin") == "ros_publish";
  });
  if (!has_publisher) {
    std::string name = "publish";
    while (std::find(ini.sections.begin(), ini.sections.end(), name) != ini.sections.end())
      name += "_ros";
    ini.set(name, "plugin", "ros_publish");
    stages.push_back(name);
  }
  std::string list;
  for (const auto& s : stages) list += (list.empty() ? "" : " ") + s;
  ini.set("pipeline", "stages", list);
  return ini.text();
}

}  // namespace

int rosCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string pipeline_file, topic;
  PipelineOverrides ov;
  RunOptions run;
  std::vector<std::string> plugin_path;
  opts.add_options()("pipeline", po::value(&pipeline_file)->required(), "pipeline file (INI)")(
      "topic", po::value(&topic),
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
  const std::string text = nodePipelineText(pipeline_file, topic, ov.sets, registry);
  // Relative paths of the file (a classifier's model) still resolve against its directory.
  const PipelineConfig config = PipelineConfig::fromText(text, pipeline_file, ov, registry);
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
