// pedtrack: the host program. Subcommands load plugins and run pipelines.
#include <mrpt/core/exceptions.h>

#include <cstring>
#include <iostream>

#include "commands.h"
#include "pedtrack/errors.h"
#include "pedtrack/text.h"
#include "pedtrack/version.h"

namespace pedtrack::cli {

const char* usageText() {
  return "pedtrack — find and track pedestrians in LiDAR data\n"
         "\n"
         "usage: pedtrack <command> [options]\n"
         "\n"
         "commands:\n"
         "  run PIPELINE.ini   run a pipeline (--input FILE replays a rawlog or bag through it)\n"
         "  ros PIPELINE.ini   run a pipeline as a ROS1 node: scans from topics, tracks published\n"
         "  plugins [NAME]     list plugins, or show every parameter of one\n"
         "  import INPUT       convert a ROS1 bag or rawlog to a rawlog (--topic selects topics)\n"
         "  sim SCENARIO.ini   simulate a scene into a rawlog plus truth.csv\n"
         "  bench              measure replay or simulation throughput (Release build)\n"
         "  eval               score tracks (MOTA, IDF1, HOTA, NEES), detections or classifiers\n"
         "  montecarlo P S     run pipeline P on N simulations of scenario S; score them together\n"
         "  train KIND         build a person classifier (knn, svm, forest) from labelled "
         "clusters\n"
         "  render             draw a run's tracks over its rawlog: a PNG or an MP4 video\n"
         "  docs               write the generated documents: plugins.md, cli.md, scenarios.md\n"
         "\n"
         "`pedtrack <command> --help` shows a command's options. Exit codes: 0 success, 1 failure\n"
         "while running, 2 bad input (pipeline file, option, missing file).\n";
}

}  // namespace pedtrack::cli

int main(int argc, char** argv) {
  using namespace pedtrack;
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::cout << cli::usageText();
    return argc < 2 ? exit_code::kBadInput : exit_code::kOk;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::cout << "pedtrack " << versionString() << " (plugin API " << kApiVersion << ")\n";
    return 0;
  }
  const std::string cmd = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (cmd == "run") return cli::runCommand(args);
    if (cmd == "ros") return cli::rosCommand(args);
    if (cmd == "plugins") return cli::pluginsCommand(args);
    if (cmd == "import") return cli::importCommand(args);
    if (cmd == "bench") return cli::benchCommand(args);
    if (cmd == "eval") return cli::evalCommand(args);
    if (cmd == "sim") return cli::simCommand(args);
    if (cmd == "render") return cli::renderCommand(args);
    if (cmd == "train") return cli::trainCommand(args);
    if (cmd == "montecarlo") return cli::monteCarloCommand(args);
    if (cmd == "docs") return cli::docsCommand(args);
    std::cerr << "error: unknown command '" << cmd << "' (see `pedtrack --help`)\n";
    return exit_code::kBadInput;
  } catch (const ConfigError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << oneLine(e.what()) << "\n";
    return exit_code::kFailure;
  }
}
