// `pedtrack sim SCENARIO.ini --out DIR`: simulates a scenario into DIR/sim.rawlog (what the
// real sensor and odometry would have logged), DIR/truth.csv (where everyone really was) and
// DIR/truth_points.bin (what each return hit).
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/progress.h"
#include "pedtrack/sim/simulator.h"

namespace pedtrack::cli {

// Markdown tables, one per section: readable in a terminal and the body of docs/scenarios.md.
std::string scenarioKeysMarkdown() {
  std::ostringstream o;
  for (const auto& [section, specs] : sim::scenarioKeys()) {
    o << "\n## `[" << section << "]`\n\n| key | type | unit | default | range | meaning |\n"
      << "|---|---|---|---|---|---|\n";
    for (const auto& p : specs) {
      std::string def = p.default_value ? *p.default_value : "(required)";
      if (def.empty()) def = "\"\"";
      o << "| `" << p.name << "` | " << toString(p.type) << " | " << p.unit << " | " << def << " | "
        << p.rangeText() << " | " << p.doc << " |\n";
    }
  }
  return o.str();
}

int simCommand(const std::vector<std::string>& args) {
  po::options_description opts("options");
  std::string scenario, out;
  long seed = -1;
  double duration = -1;
  opts.add_options()("scenario", po::value(&scenario), "scenario file (configs/scenarios/*.ini)")(
      "out,o", po::value(&out), "directory for sim.rawlog and truth.csv")(
      "seed", po::value(&seed)->default_value(-1), "random seed (-1: the scenario's own)")(
      "duration", po::value(&duration),
      "simulate only the first S seconds (a quick look at a long scenario)")(
      "keys", "list every scenario section and key (markdown tables)")(
      "no-point-truth", "do not write truth_points.bin (what each return hit)")(
      "quiet,q", "no progress output");
  po::positional_options_description pos;
  pos.add("scenario", 1);
  po::variables_map vm;
  if (!parseOptions("sim", "SCENARIO.ini --out DIR [options]", opts, pos, args, vm)) return 0;
  if (vm.count("keys")) {
    std::cout << scenarioKeysMarkdown();
    return 0;
  }
  if (scenario.empty()) throw ConfigError("pedtrack sim: missing SCENARIO.ini");
  if (seed < -1 || seed > 4294967295L)
    throw ConfigError("--seed " + std::to_string(seed) +
                      ": expected 0..4294967295 (-1: the "
                      "scenario's own)");
  if (out.empty()) throw ConfigError("pedtrack sim: missing --out DIR");

  if (vm.count("duration") && !(duration > 0))
    throw ConfigError("--duration " + std::to_string(duration) + ": expected seconds > 0");
  sim::Scenario loaded = sim::loadScenario(scenario, seed);
  if (duration > 0) loaded.duration = std::min(loaded.duration, duration);
  sim::Simulator simulator(std::move(loaded));
  simulator.setPointTruth(!vm.count("no-point-truth"));
  std::filesystem::create_directories(out);
  const std::string rawlog = out + "/sim.rawlog", truth = out + "/truth.csv",
                    points = out + "/truth_points.bin";
  mrpt::io::CFileOutputStream file;
  if (!file.open(rawlog)) throw ConfigError("--out: cannot write '" + rawlog + "'");
  auto archive = mrpt::serialization::archiveFrom(file);
  std::unique_ptr<sim::TruthCsvWriter> truth_out;
  std::unique_ptr<LabelFileWriter> points_out;
  try {
    truth_out = std::make_unique<sim::TruthCsvWriter>(truth);
    if (!vm.count("no-point-truth"))
      points_out = std::make_unique<LabelFileWriter>(points, LabelKind::Truth);
  } catch (const DataError&) {
    throw ConfigError("--out: cannot write '" + (truth_out ? points : truth) + "'");
  }

  Progress progress("sim", !vm.count("quiet"));
  installStopHandlers();
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t frames = 0, person_points = 0;
  sim::SimFrame f;
  while (!Pipeline::stopRequested() && simulator.next(f)) {
    for (const auto& o : f.observations) archive << *o;
    truth_out->write(f);
    if (points_out) points_out->write(sim::pointTruth(f));
    for (const auto& r : f.truth) person_points += r.visible_points;
    ++frames;
    progress.update(frames, double(frames) / simulator.frameCount());
  }
  progress.done(frames);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& sc = simulator.scenario();
  if (!sc.description.empty()) std::printf("%s: %s\n", sc.name.c_str(), sc.description.c_str());
  std::printf(
      "%s: %zu frames of %s at %.0f Hz, %zu people, %zu person returns; %.2f s (%.0f frames/s)\n"
      "wrote %s, %s%s%s\n",
      sc.name.c_str(), frames, sc.sensor.model.c_str(), sc.sensor.rate, sc.people.size(),
      person_points, secs, frames / std::max(secs, 1e-9), rawlog.c_str(), truth.c_str(),
      points_out ? " and " : "", points_out ? points.c_str() : "");
  if (points_out) points_out->close();
  return Pipeline::stopRequested() ? exit_code::kFailure : exit_code::kOk;
}

}  // namespace pedtrack::cli
