// `pedtrack sim SCENARIO.ini --out DIR`: simulates a scenario into DIR/sim.rawlog (what the
// real sensor and odometry would have logged) and DIR/truth.csv (where everyone really was).
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/progress.h"
#include "pedtrack/sim/simulator.h"

namespace pedtrack::cli {
namespace {

void printKeys() {
  for (const auto& [section, specs] : sim::scenarioKeys()) {
    std::cout << "[" << section << "]\n";
    for (const auto& p : specs) {
      std::string def = p.default_value ? *p.default_value : "(required)";
      if (def.empty()) def = "\"\"";
      std::printf("  %-12s %-8s %-10s %-14s %s\n", p.name.c_str(), toString(p.type), p.unit.c_str(),
                  def.c_str(), p.doc.c_str());
    }
  }
}

}  // namespace

int simCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string scenario, out;
  long seed = -1;
  opts.add_options()("scenario", po::value(&scenario), "scenario file (configs/scenarios/*.ini)")(
      "out,o", po::value(&out), "directory for sim.rawlog and truth.csv")(
      "seed", po::value(&seed)->default_value(-1), "random seed (-1: the scenario's own)")(
      "keys", "list every scenario section and key with type, unit, default and meaning")(
      "quiet,q", "no progress output");
  po::positional_options_description pos;
  pos.add("scenario", 1);
  po::variables_map vm;
  if (!parseOptions("sim", "SCENARIO.ini --out DIR [options]", opts, pos, args, vm)) return 0;
  if (vm.count("keys")) {
    printKeys();
    return 0;
  }
  if (scenario.empty()) throw ConfigError("pedtrack sim: missing SCENARIO.ini");
  if (out.empty()) throw ConfigError("pedtrack sim: missing --out DIR");

  sim::Simulator simulator(sim::loadScenario(scenario, seed));
  std::filesystem::create_directories(out);
  const std::string rawlog = out + "/sim.rawlog", truth = out + "/truth.csv";
  mrpt::io::CFileOutputStream file;
  if (!file.open(rawlog)) throw ConfigError("--out: cannot write '" + rawlog + "'");
  auto archive = mrpt::serialization::archiveFrom(file);
  std::ofstream truth_out(truth);
  if (!truth_out) throw ConfigError("--out: cannot write '" + truth + "'");
  truth_out << sim::truthCsvHeader() << '\n';

  Progress progress("sim", !vm.count("quiet"));
  installStopHandlers();
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t frames = 0, person_points = 0;
  sim::SimFrame f;
  while (!Pipeline::stopRequested() && simulator.next(f)) {
    for (const auto& o : f.observations) archive << *o;
    sim::writeTruthRows(truth_out, f);
    for (const auto& r : f.truth) person_points += r.visible_points;
    ++frames;
    progress.update(frames, double(frames) / simulator.frameCount());
  }
  progress.done(frames);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& sc = simulator.scenario();
  std::printf(
      "%s: %zu frames of %s at %.0f Hz, %zu people, %zu person returns; %.2f s (%.0f frames/s)\n"
      "wrote %s and %s\n",
      sc.name.c_str(), frames, sc.sensor.model.c_str(), sc.sensor.rate, sc.people.size(),
      person_points, secs, frames / std::max(secs, 1e-9), rawlog.c_str(), truth.c_str());
  return Pipeline::stopRequested() ? exit_code::kFailure : exit_code::kOk;
}

}  // namespace pedtrack::cli
