// `pedtrack plugins [NAME]`: what is installed, and every parameter of one plugin.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/plugin_registry.h"

namespace pedtrack::cli {
namespace {

void printList(const PluginRegistry& reg) {
  std::vector<const PluginEntry*> entries;
  for (const auto& e : reg.entries()) entries.push_back(&e);
  std::sort(entries.begin(), entries.end(), [](const PluginEntry* a, const PluginEntry* b) {
    const int ca = a->descriptor ? static_cast<int>(a->descriptor->category) : 9;
    const int cb = b->descriptor ? static_cast<int>(b->descriptor->category) : 9;
    return ca != cb ? ca < cb : a->name < b->name;
  });
  if (entries.empty()) {
    std::cout << "no plugins found; searched:\n";
    for (const auto& d : reg.searchPath()) std::cout << "  " << d << "\n";
    return;
  }
  std::printf("%-14s %-11s %s\n", "PLUGIN", "CATEGORY", "DESCRIPTION");
  for (const PluginEntry* e : entries) {
    if (e->descriptor)
      std::printf("%-14s %-11s %s\n", e->name.c_str(), toString(e->descriptor->category),
                  e->descriptor->doc.c_str());
    else
      std::printf("%-14s %-11s REFUSED: %s\n", e->name.c_str(), "-", e->refusal.c_str());
  }
  std::cout << "\n`pedtrack plugins NAME` shows a plugin's parameters.\n";
}

void printPlugin(const PluginRegistry& reg, const std::string& name) {
  const PluginDescriptor& d = reg.get(name);
  std::string path;
  for (const auto& e : reg.entries())
    if (e.name == name) path = e.path;
  std::cout << d.name << " (" << toString(d.category) << "): " << d.doc << "\n" << path << "\n\n";
  std::cout << "[section]\nplugin = " << d.name << "\n";
  std::printf("\n%-16s %-7s %-6s %-14s %-18s %s\n", "KEY", "TYPE", "UNIT", "DEFAULT", "RANGE",
              "DESCRIPTION");
  for (const auto& p : d.params) {
    std::printf("%-16s %-7s %-6s %-14s %-18s %s\n", p.name.c_str(), toString(p.type),
                p.unit.empty() ? "-" : p.unit.c_str(),
                p.required() ? "(required)"
                             : (p.default_value->empty() ? "\"\"" : p.default_value->c_str()),
                p.rangeText().empty() ? "-" : p.rangeText().c_str(), p.doc.c_str());
  }
  if (d.accepts_other_keys)
    std::cout << "\nOther keys of the section are passed to the plugin unchecked (see its doc).\n";
}

}  // namespace

int pluginsCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string name;
  std::vector<std::string> plugin_path;
  opts.add_options()("name", po::value(&name), "plugin to describe")(
      "plugin-path", po::value(&plugin_path)->composing(), "extra plugin directory (repeatable)");
  po::positional_options_description pos;
  pos.add("name", 1);
  po::variables_map vm;
  if (!parseOptions("plugins", "[NAME] [options]", opts, pos, args, vm)) return 0;
  PluginRegistry reg(PluginRegistry::defaultSearchPath(plugin_path));
  if (name.empty())
    printList(reg);
  else
    printPlugin(reg, name);
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
