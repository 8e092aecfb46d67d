#include "pedtrack/plugin_registry.h"

#include <algorithm>
#include <boost/dll/runtime_symbol_info.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "pedtrack/errors.h"

namespace fs = std::filesystem;

namespace pedtrack {

PluginRegistry::PluginRegistry(std::vector<std::string> search_path)
    : search_path_(std::move(search_path)) {
  for (const auto& dir : search_path_) scanDirectory(dir);
}

std::vector<std::string> PluginRegistry::defaultSearchPath(const std::vector<std::string>& extra) {
  std::vector<std::string> dirs(extra.begin(), extra.end());
  if (const char* env = std::getenv("PEDTRACK_PLUGIN_PATH")) {
    std::string s = env, cur;
    for (char c : s + ":") {
      if (c == ':') {
        if (!cur.empty()) dirs.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
  }
  // bin/../lib/pedtrack/plugins works for the build tree and for any install prefix.
  boost::system::error_code ec;
  const auto exe = boost::dll::program_location(ec);
  if (!ec)
    dirs.push_back(
        (fs::path(exe.string()).parent_path().parent_path() / PEDTRACK_PLUGIN_SUBDIR).string());
  dirs.push_back(PEDTRACK_INSTALL_PLUGIN_DIR);
  // Drop duplicates (the same directory reached two ways), keeping the first.
  std::vector<std::string> unique;
  std::vector<fs::path> seen;
  for (const auto& d : dirs) {
    std::error_code e;
    fs::path canon = fs::weakly_canonical(d, e);
    if (e) canon = d;
    if (std::find(seen.begin(), seen.end(), canon) != seen.end()) continue;
    seen.push_back(canon);
    unique.push_back(d);
  }
  return unique;
}

void PluginRegistry::scanDirectory(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".so") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    boost::dll::shared_library lib;
    boost::system::error_code lec;
    lib.load(file.string(), boost::dll::load_mode::rtld_lazy | boost::dll::load_mode::rtld_local,
             lec);
    if (lec) {
      std::cerr << "warning: " << file.string() << ": cannot load plugin: " << lec.message()
                << "\n";
      continue;
    }
    if (!lib.has("pedtrack_plugin_api_version") || !lib.has("pedtrack_plugin_name")) continue;
    PluginEntry entry;
    entry.path = file.string();
    entry.api_version = lib.get<int()>("pedtrack_plugin_api_version")();
    entry.name = lib.get<const char*()>("pedtrack_plugin_name")();
    const bool shadowed = std::any_of(entries_.begin(), entries_.end(),
                                      [&](const PluginEntry& e) { return e.name == entry.name; });
    if (shadowed) continue;  // an earlier directory of the search path wins
    if (entry.api_version != kApiVersion) {
      entry.refusal = "plugin '" + entry.name + "' (" + entry.path +
                      ") was built against pedtrack plugin API version " +
                      std::to_string(entry.api_version) + ", but this pedtrack has API version " +
                      std::to_string(kApiVersion) + "; rebuild the plugin against this pedtrack";
    } else if (lib.has("pedtrack_plugin_descriptor")) {
      entry.descriptor = lib.get<const PluginDescriptor*()>("pedtrack_plugin_descriptor")();
    } else {
      entry.refusal = "plugin '" + entry.name + "' (" + entry.path + ") exports no descriptor";
    }
    entries_.push_back(entry);
    libraries_.push_back(std::move(lib));
  }
}

std::vector<std::string> PluginRegistry::names() const {
  std::vector<std::string> n;
  for (const auto& e : entries_) n.push_back(e.name);
  return n;
}

const PluginDescriptor& PluginRegistry::get(const std::string& name) const {
  for (const auto& e : entries_) {
    if (e.name != name) continue;
    if (!e.descriptor) throw ConfigError(e.refusal);
    return *e.descriptor;
  }
  const std::string hint = closestMatch(name, names());
  std::string msg = "unknown plugin '" + name + "'";
  msg += hint.empty() ? " (`pedtrack plugins` lists the available ones)"
                      : " (did you mean '" + hint + "'?)";
  throw ConfigError(msg);
}

}  // namespace pedtrack
