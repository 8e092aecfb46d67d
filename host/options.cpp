#include "options.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <typeinfo>

#include "pedtrack/errors.h"

namespace pedtrack::cli {

namespace {

// An unsigned option takes no negative number: Boost converts "-1" to the type's maximum (an
// unbounded queue, 2^64 threads), so a '-' in front of such a value is refused here.
bool isUnsigned(const boost::any& v) {
  const std::type_info& t = v.type();
  return t == typeid(unsigned char) || t == typeid(unsigned short) || t == typeid(unsigned int) ||
         t == typeid(unsigned long) || t == typeid(unsigned long long);
}

void refuseNegativeCounts(const std::string& command, const po::parsed_options& parsed,
                          const po::variables_map& vm) {
  for (const po::option& o : parsed.options) {
    const auto it = vm.find(o.string_key);
    if (it == vm.end() || !isUnsigned(it->second.value())) continue;
    for (const std::string& v : o.value)
      if (v.find('-') != std::string::npos)
        throw ConfigError("pedtrack " + command + ": --" + o.string_key + " " + v +
                          ": expected a whole number of at least 0");
  }
}

}  // namespace

bool parseOptions(const std::string& command, const std::string& synopsis,
                  const po::options_description& options,
                  const po::positional_options_description& positional,
                  const std::vector<std::string>& args, po::variables_map& vm,
                  const std::string& about_key) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help");
  try {
    const po::parsed_options parsed =
        po::command_line_parser(args).options(all).positional(positional).run();
    po::store(parsed, vm);
    refuseNegativeCounts(command, parsed, vm);
    if (vm.count("help")) {
      const std::string about = commandAbout(about_key.empty() ? command : about_key);
      std::cout << "usage: pedtrack " << command << " " << synopsis << "\n\n"
                << (about.empty() ? "" : about + "\n") << all << "\n";
      return false;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    throw ConfigError("pedtrack " + command + ": " + e.what() + " (see `pedtrack " + command +
                      " --help`)");
  }
  return true;
}

void addRunOptions(po::options_description& options, RunOptions& run,
                   std::vector<std::string>& plugin_path) {
  options.add_options()("out", po::value(&run.out_dir),
                        "directory for tracks.csv, run.json and the stages' side outputs "
                        "(detections.csv, clusters.csv, point_labels.bin)")(
      "no-point-labels", "with --out: do not write point_labels.bin (every point's label)")(
      "plugin-path", po::value(&plugin_path)->composing(),
      "extra plugin directory (repeatable, searched first)")(
      "max-frames", po::value(&run.max_frames)->default_value(-1), "stop after N frames (-1: all)")(
      "record", po::value(&run.record),
      "also write every frame the source produces to this MRPT rawlog (a live session, kept to "
      "replay bit for bit with --input)")(
      "live-queue", po::value(&run.live_queue)->default_value(2),
      "live sources: frames that may wait for the stages; when they fall behind, the oldest is "
      "dropped (counted in run.json)")("quiet,q", "no progress output");
}

void readRunOptions(const po::variables_map& vm, RunOptions& run) {
  run.progress = !vm.count("quiet");
  run.point_labels = !vm.count("no-point-labels");
  if (run.live_queue < 1) throw ConfigError("--live-queue: must be at least 1");
  if (!run.record.empty()) checkWritableFile(run.record, "--record", run.out_dir);
}

void checkWritableFile(const std::string& path, const std::string& option,
                       const std::string& created_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec))
    throw ConfigError(option + " " + path + ": is a directory, not a file");
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  // A folder the run creates itself (--out) need not exist yet: its nearest existing ancestor
  // must take it.
  if (!created_dir.empty() &&
      fs::absolute(dir).lexically_normal() == fs::absolute(created_dir).lexically_normal())
    while (!fs::exists(dir, ec) && dir.has_parent_path() && dir != dir.parent_path())
      dir = dir.parent_path();
  if (!fs::is_directory(dir, ec))
    throw ConfigError(option + " " + path + ": no directory " + dir.string());
  if (::access(dir.c_str(), W_OK) != 0 || (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0))
    throw ConfigError(option + " " + path + ": cannot be written");
}

}  // namespace pedtrack::cli
