#include "options.h"

#include <iostream>

#include "pedtrack/errors.h"

namespace pedtrack::cli {

bool parseOptions(const std::string& command, const std::string& synopsis,
                  const po::options_description& options,
                  const po::positional_options_description& positional,
                  const std::vector<std::string>& args, po::variables_map& vm) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help");
  try {
    po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
    if (vm.count("help")) {
      std::cout << "usage: pedtrack " << command << " " << synopsis << "\n\n" << all << "\n";
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
}

}  // namespace pedtrack::cli
