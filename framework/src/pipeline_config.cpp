#include "pedtrack/pipeline_config.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/fault_injection.h"
#include "pedtrack/ini_text.h"
#include "pedtrack/text.h"

namespace fs = std::filesystem;

namespace pedtrack {
namespace {

// Sections and keys in file order, edited by --input/--set before MRPT sees them again.
struct IniModel {
  std::vector<std::string> sections;
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> keys;

  bool hasSection(const std::string& s) const { return keys.count(s) != 0; }
  void set(const std::string& section, const std::string& key, const std::string& value) {
    if (!hasSection(section)) sections.push_back(section);
    auto& kv = keys[section];
    for (auto& p : kv)
      if (p.first == key) {
        p.second = value;
        return;
      }
    kv.emplace_back(key, value);
  }
  const std::string* get(const std::string& section, const std::string& key) const {
    auto it = keys.find(section);
    if (it == keys.end()) return nullptr;
    for (const auto& p : it->second)
      if (p.first == key) return &p.second;
    return nullptr;
  }
  std::string text() const {
    std::ostringstream os;
    for (const auto& s : sections) {
      os << "[" << s << "]\n";
      for (const auto& [k, v] : keys.at(s)) os << k << " = " << v << "\n";
    }
    return os.str();
  }
};

IniModel readModel(const mrpt::config::CConfigFileBase& ini) {
  IniModel m;
  std::vector<std::string> sections;
  ini.getAllSections(sections);
  for (const auto& s : sections) {
    m.sections.push_back(s);
    std::vector<std::string> keys;
    ini.getAllKeys(s, keys);
    auto& kv = m.keys[s];
    for (const auto& k : keys) kv.emplace_back(k, trim(ini.read_string(s, k, "")));
  }
  return m;
}

std::string absoluteFromCwd(const std::string& p) {
  return p.empty() ? p : fs::absolute(p).lexically_normal().string();
}

using CliKeys = std::set<std::pair<std::string, std::string>>;

// The validated values of section `name` against `specs`: unknown keys (unless
// `accepts_other_keys`), missing required keys and bad values are ConfigErrors naming file,
// section and key; relative input files are made absolute from the file's directory unless they
// were typed on the command line.
ParamSet sectionParams(const IniModel& model, const std::string& file, const std::string& name,
                       const std::vector<ParamSpec>& specs, bool accepts_other_keys,
                       const std::string& owner, const std::string& otherwise,
                       const fs::path& base_dir, const CliKeys& from_cli,
                       const std::vector<std::pair<std::string, std::string>>& moved = {}) {
  ParamSet params(file, name);
  std::vector<std::string> declared;
  for (const auto& p : specs) declared.push_back(p.name);
  for (const auto& [key, value] : model.keys.at(name)) {
    if (key == "plugin") continue;
    if (std::find(declared.begin(), declared.end(), key) != declared.end()) continue;
    if (accepts_other_keys) continue;
    for (const auto& [old_key, now] : moved)
      if (old_key == key)
        throw ConfigError(file + ": [" + name + "] " + key + ": no longer a key of " + owner +
                          ": " + now);
    const std::string hint = closestMatch(key, declared);
    throw ConfigError(file + ": [" + name + "] " + key + ": unknown key for " + owner +
                      (hint.empty() ? otherwise : " (did you mean '" + hint + "'?)"));
  }
  for (const auto& spec : specs) {
    const std::string* given = model.get(name, spec.name);
    const std::string where = params.where(spec.name);
    if (!given) {
      if (spec.required()) throw ConfigError(where + ": missing required key (" + spec.doc + ")");
      params.setDefault(spec.name, *spec.default_value);
      continue;
    }
    std::string value = *given;
    if (spec.type == ParamType::InputFile && !value.empty() && fs::path(value).is_relative() &&
        !from_cli.count({name, spec.name}))
      value = (base_dir / value).lexically_normal().string();
    params.set(spec.name, validateValue(spec, value, where));
  }
  return params;
}

}  // namespace

PipelineConfig PipelineConfig::load(const std::string& file, const PipelineOverrides& overrides,
                                    const PluginRegistry& registry) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw ConfigError(file + ": pipeline file " +
                      (fs::exists(file, ec) ? "is not a regular file" : "not found"));
  std::ifstream in(file);
  if (!in) throw ConfigError(file + ": cannot read pipeline file");
  std::stringstream ss;
  ss << in.rdbuf();
  return fromText(ss.str(), file, overrides, registry);
}

PipelineConfig PipelineConfig::fromText(const std::string& text, const std::string& file,
                                        const PipelineOverrides& overrides,
                                        const PluginRegistry& registry) {
  PipelineConfig cfg;
  cfg.file = file;
  IniModel model;
  try {
    // --input replaces the source's keys: a variable they use need not be set.
    mrpt::config::CConfigFileMemory raw(preprocessIniText(
        text, file, overrides.input.empty() ? std::string() : firstStageName(text)));
    model = readModel(raw);
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(file + ": " + oneLine(e.what()));
  }

  if (!model.hasSection("pipeline"))
    throw ConfigError(file +
                      ": no [pipeline] section (it lists the stages: `stages = source ...`)");
  // `--set pipeline.stages=...` chooses the stages, so it applies before they are read.
  for (const auto& s : overrides.sets)
    if (s.rfind("pipeline.", 0) == 0 && s.find('=') != std::string::npos)
      model.set("pipeline", trim(s.substr(9, s.find('=') - 9)), trim(s.substr(s.find('=') + 1)));
  for (const auto& [k, v] : model.keys.at("pipeline"))
    if (k != "stages")
      throw ConfigError(file + ": [pipeline] " + k + ": unknown key (the only key is 'stages')");
  const std::string* stages_text = model.get("pipeline", "stages");
  if (!stages_text || trim(*stages_text).empty())
    throw ConfigError(
        file + ": [pipeline] stages: missing required key (the stage sections in run order)");
  std::vector<std::string> stage_names = splitList(*stages_text);
  if (const auto& [section, plugin] = overrides.append_stage; !plugin.empty()) {
    const bool present =
        std::any_of(stage_names.begin(), stage_names.end(), [&, &wanted = plugin](const auto& n) {
          const std::string* p = model.get(n, "plugin");
          return p && *p == wanted;
        });
    if (!present) {
      std::string name = section;
      while (model.hasSection(name)) name += "_" + plugin;
      model.set(name, "plugin", plugin);
      stage_names.push_back(name);
      std::string list;
      for (const auto& n : stage_names) list += (list.empty() ? "" : " ") + n;
      model.set("pipeline", "stages", list);
    }
  }

  // Values typed on the command line are relative to the working directory, not to the file.
  CliKeys from_cli;
  if (!overrides.input.empty()) {
    const std::string source = stage_names.front();
    const std::string ext = fs::path(overrides.input).extension().string();
    model.keys[source].clear();
    if (!model.hasSection(source)) model.sections.push_back(source);
    // A scenario (.ini) is simulated; KITTI Velodyne scans (a .bin, or a folder of them), a
    // detector's output (KITTI's .txt, pedtrack's detections .csv) and anything else (a log) are
    // replayed.
    const std::string key = ext == ".ini" ? "scenario" : "file";
    const bool kitti = ext == ".bin" || fs::is_directory(overrides.input);
    const bool detections = ext == ".txt" || ext == ".csv";
    model.set(source, "plugin",
              ext == ".bag"   ? "rosbag"
              : ext == ".ini" ? "sim"
              : kitti         ? "kitti"
              : detections    ? "detections"
                              : "rawlog");
    model.set(source, key, absoluteFromCwd(overrides.input));
    from_cli.insert({source, key});
    if (!overrides.topic.empty()) {
      if (ext != ".bag")
        throw ConfigError("--topic: only a .bag input has topics ('" + overrides.input + "')");
      model.set(source, "topic", overrides.topic);
    }
  } else if (!overrides.source_plugin.empty()) {
    const std::string source = stage_names.front();
    if (!model.hasSection(source)) model.sections.push_back(source);
    auto& kv = model.keys[source];
    const std::string* current = model.get(source, "plugin");
    if (!current || *current != overrides.source_plugin) {
      const PluginDescriptor& d = registry.get(overrides.source_plugin);
      std::vector<std::pair<std::string, std::string>> kept{{"plugin", overrides.source_plugin}};
      for (const auto& [k, v] : kv)
        if (std::any_of(d.params.begin(), d.params.end(),
                        [&key = k](const ParamSpec& p) { return p.name == key; }))
          kept.emplace_back(k, v);
      kv = kept;
    }
    if (!overrides.topic.empty()) model.set(source, "topic", overrides.topic);
  } else if (!overrides.topic.empty()) {
    throw ConfigError("--topic: goes with --input FILE.bag");
  }
  for (const auto& s : overrides.sets) {
    const auto dot = s.find('.'), eq = s.find('=');
    if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 ||
        eq == dot + 1)
      throw ConfigError("--set '" + s + "': expected section.key=value");
    const std::string section = s.substr(0, dot), key = s.substr(dot + 1, eq - dot - 1);
    model.set(section, trim(key), trim(s.substr(eq + 1)));
    from_cli.insert({section, trim(key)});
  }

  const fs::path base_dir = fs::absolute(file).parent_path();
  std::set<std::string> seen;
  for (std::size_t i = 0; i < stage_names.size(); ++i) {
    const std::string& name = stage_names[i];
    if (!seen.insert(name).second)
      throw ConfigError(file + ": [pipeline] stages: stage '" + name + "' is listed twice");
    if (name == "faults")
      throw ConfigError(file +
                        ": [pipeline] stages: [faults] is not a stage (it configures fault "
                        "injection into the source)");
    if (!model.hasSection(name) || name == "pipeline") {
      std::vector<std::string> candidates;
      for (const auto& s : model.sections)
        if (s != "pipeline") candidates.push_back(s);
      const std::string hint = closestMatch(name, candidates);
      throw ConfigError(file + ": [pipeline] stages: no section [" + name + "]" +
                        (hint.empty() ? "" : " (did you mean [" + hint + "]?)"));
    }
    const std::string* plugin = model.get(name, "plugin");
    if (!plugin || plugin->empty())
      throw ConfigError(file + ": [" + name +
                        "] plugin: missing required key (`pedtrack plugins` lists them)");
    StageConfig sc;
    sc.section = name;
    try {
      sc.descriptor = &registry.get(*plugin);
    } catch (const ConfigError& e) {
      throw ConfigError(file + ": [" + name + "] plugin: " + e.what());
    }
    const PluginDescriptor& d = *sc.descriptor;
    if (i == 0 && d.category != Category::Sensor)
      throw ConfigError(file + ": [" + name + "] plugin: the first stage must be a sensor, '" +
                        d.name + "' is a " + toString(d.category));
    if (i > 0 && d.category == Category::Sensor)
      throw ConfigError(file + ": [" + name + "] plugin: '" + d.name +
                        "' is a sensor; only the first stage may be one");
    if (d.category == Category::Odometry)
      for (const StageConfig& before : cfg.stages)
        if (before.descriptor->category == Category::Classifier ||
            before.descriptor->category == Category::Tracker)
          throw ConfigError(file + ": [" + name + "] plugin: '" + d.name +
                            "' sets the robot's pose and must run before [" + before.section +
                            "] (a " + toString(before.descriptor->category) +
                            ", which places what it finds in the fixed frame)");

    sc.params = sectionParams(
        model, file, name, d.params, d.accepts_other_keys, "plugin '" + d.name + "'",
        " (`pedtrack plugins " + d.name + "` lists its keys)", base_dir, from_cli, d.moved_keys);
    cfg.stages.push_back(std::move(sc));
  }
  if (model.hasSection("faults"))
    cfg.faults = sectionParams(model, file, "faults", faultParams(), false, "fault injection",
                               " (README \"Reliability\" lists them)", base_dir, from_cli);
  cfg.ini = std::make_shared<mrpt::config::CConfigFileMemory>(model.text());
  return cfg;
}

}  // namespace pedtrack
