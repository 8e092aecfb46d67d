#pragma once
// Finds plugins on a search path and loads them with Boost.DLL.
#include <boost/dll/shared_library.hpp>
#include <string>
#include <vector>

#include "pedtrack/plugin.h"

namespace pedtrack {

struct PluginEntry {
  std::string name;
  std::string path;
  int api_version = 0;
  const PluginDescriptor* descriptor = nullptr;  ///< null when refused
  std::string refusal;                           ///< why it was refused (API version)
};

class PluginRegistry {
 public:
  /// Scans every directory of `search_path` (earlier directories win on duplicate names).
  explicit PluginRegistry(std::vector<std::string> search_path);

  /// `extra` (from --plugin-path) first, then $PEDTRACK_PLUGIN_PATH (':'-separated), then the
  /// plugin directory next to the running executable (build tree or install prefix), then the
  /// install prefix configured at build time.
  static std::vector<std::string> defaultSearchPath(const std::vector<std::string>& extra);

  const std::vector<PluginEntry>& entries() const { return entries_; }
  const std::vector<std::string>& searchPath() const { return search_path_; }
  /// The descriptor of `name`; throws ConfigError for an unknown name (with a suggestion) or a
  /// plugin built against another API version (naming both versions).
  const PluginDescriptor& get(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  void scanDirectory(const std::string& dir);
  std::vector<std::string> search_path_;
  std::vector<PluginEntry> entries_;
  std::vector<boost::dll::shared_library> libraries_;  // kept loaded for the process lifetime
};

}  // namespace pedtrack
