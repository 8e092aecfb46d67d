// `pedtrack montecarlo PIPELINE.ini SCENARIO.ini --runs N --out DIR`: the pipeline run on N
// simulations of the scenario (seeds seed_base … seed_base + N − 1), the runs scored together
// (`pedtrack eval`'s figures pooled, NEES/NIS per truth and frame against χ² bounds, RMSE per
// frame, ID switches per run), the report written to DIR/montecarlo.json with consistency.csv
// and the plots.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <thread>

#include "commands.h"
#include "montecarlo_compare.h"
#include "montecarlo_plots.h"
#include "montecarlo_report.h"
#include "montecarlo_run.h"
#include "options.h"
#include "pedtrack/errors.h"

namespace pedtrack::cli {
namespace {

namespace fs = std::filesystem;

void check(bool ok, const std::string& message) {
  if (!ok)
    throw ConfigError("pedtrack montecarlo: " + message + " (see `pedtrack montecarlo --help`)");
}

/// Plots of an earlier run in DIR would be taken for this one's.
void removeStalePlots(const std::string& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    const bool plot = e.path().extension() == ".png" &&
                      (n.rfind("nees_", 0) == 0 || n.rfind("nis_", 0) == 0 ||
                       n.rfind("rmse_", 0) == 0 || n.rfind("heading_", 0) == 0 || n == "llr.png");
    if (plot) fs::remove(e.path(), ec);
  }
}

std::vector<std::string> splitLabels(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text + ",") {
    if (c != ',') {
      cur += c;
      continue;
    }
    out.push_back(cur);
    cur.clear();
  }
  return out;
}

/// `pedtrack montecarlo --compare DIR... [--labels A,B,...] --out DIR`: no simulation.
int compareCommand(const std::vector<std::string>& args) {
  std::vector<std::string> dirs;
  std::string labels, out;
  po::options_description opts("options");
  opts.add_options()("compare", po::value(&dirs)->multitoken()->zero_tokens()->required(),
                     "montecarlo output directories to put side by side (each with "
                     "montecarlo.json and consistency.csv)")(
      "labels", po::value(&labels),
      "comma-separated names of the directories, in order (default: the directory names)")(
      "out", po::value(&out)->required(), "directory for compare.md and errors_<truth id>.png");
  po::variables_map vm;
  if (!parseOptions("montecarlo",
                    "--compare DIR1 DIR2 ... [--labels A,B,...] --out DIR (no simulation)", opts,
                    po::positional_options_description(), args, vm, "montecarlo --compare"))
    return exit_code::kOk;
  auto fail = [](const std::string& m) {
    throw ConfigError("pedtrack montecarlo --compare: " + m +
                      " (see `pedtrack montecarlo --compare --help`)");
  };
  if (dirs.empty()) fail("give the directories to compare after --compare");
  std::vector<std::string> names =
      labels.empty() ? std::vector<std::string>() : splitLabels(labels);
  if (!vm.count("labels"))
    for (const auto& d : dirs)
      names.push_back(fs::path(d).lexically_normal().filename().empty()
                          ? fs::path(d).lexically_normal().parent_path().filename().string()
                          : fs::path(d).lexically_normal().filename().string());
  if (names.size() != dirs.size())
    fail("--labels names " + std::to_string(names.size()) + " label" +
         (names.size() == 1 ? "" : "s") + " for " + std::to_string(dirs.size()) + " director" +
         (dirs.size() == 1 ? "y" : "ies"));
  for (const auto& n : names)
    if (n.empty()) fail("--labels: empty label in '" + labels + "'");
  // Every directory is read (and rejected) before anything is written.
  std::vector<CompareEntry> entries;
  for (std::size_t i = 0; i < dirs.size(); ++i)
    entries.push_back(readMonteCarloDir(dirs[i], names[i]));
  fs::create_directories(out);
  const std::string table = compareMarkdown(entries);
  {
    std::ofstream f(out + "/compare.md");
    if (!(f << table)) throw DataError("cannot write '" + out + "/compare.md'");
  }
  for (const auto& f : fs::directory_iterator(out))
    if (f.path().extension() == ".png" && f.path().filename().string().rfind("errors_", 0) == 0)
      fs::remove(f.path());
  const std::vector<std::string> plots = drawCompareErrors(out, entries);
  std::cout << table << "\nwritten to " << out << ": compare.md";
  for (const auto& p : plots) std::cout << ", " << p;
  std::cout << "\n";
  return exit_code::kOk;
}

}  // namespace

int monteCarloCommand(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--compare" || a.rfind("--compare=", 0) == 0) return compareCommand(args);
  MonteCarloSetup setup;
  std::vector<std::string> plugin_path;
  long runs = 50, seed_base = 1, jobs = 0;
  double threshold = 0.75;
  po::options_description opts("options");
  opts.add_options()("pipeline", po::value(&setup.pipeline)->required(),
                     "pipeline file (INI); its source is replaced by the scenario")(
      "scenario", po::value(&setup.scenario)->required(),
      "simulation scenario (configs/scenarios/*.ini)")("runs", po::value(&runs)->default_value(50),
                                                       "number of runs (seeds)")(
      "seed-base", po::value(&seed_base)->default_value(1),
      "seed of run 0; run i uses seed-base + i")(
      "out", po::value(&setup.out_dir)->required(),
      "directory for run_NNN/ (each run's outputs), montecarlo.json, consistency.csv, plots")(
      "jobs,j", po::value(&jobs),
      "runs at a time, each on its own thread (default: the number of cores)")(
      "set", po::value(&setup.sets)->composing(),
      "override a pipeline key: section.key=value (repeatable)")(
      "plugin-path", po::value(&plugin_path)->composing(),
      "extra plugin directory (repeatable, searched first)")(
      "threshold", po::value(&threshold)->default_value(0.75), "largest match distance, m")(
      "json", "print the report as JSON (as montecarlo.json) instead of the table")(
      "quiet,q", "no progress output");
  po::positional_options_description pos;
  pos.add("pipeline", 1).add("scenario", 1);
  po::variables_map vm;
  if (!parseOptions("montecarlo",
                    "PIPELINE.ini SCENARIO.ini --out DIR [--runs N] [options] | --compare DIR1 "
                    "DIR2 ... [--labels A,B,...] --out DIR (`pedtrack montecarlo --compare "
                    "--help`)",
                    opts, pos, args, vm))
    return exit_code::kOk;
  check(runs >= 1, "--runs: must be >= 1");
  check(seed_base >= 0 && seed_base + runs - 1 <= 4294967295L,
        "--seed-base: the seeds must be within [0, 4294967295]");
  check(!vm.count("jobs") || jobs >= 1, "--jobs: must be >= 1");
  check(threshold > 0, "--threshold: must be > 0 m");
  check(fs::path(setup.scenario).extension() == ".ini",
        "SCENARIO '" + setup.scenario + "': a scenario file (.ini) is expected");
  check(fs::is_regular_file(setup.scenario), "SCENARIO '" + setup.scenario + "': no such file");
  setup.runs = std::size_t(runs);
  setup.seed_base = static_cast<unsigned long>(seed_base);
  setup.jobs =
      vm.count("jobs") ? std::size_t(jobs) : std::max(1u, std::thread::hardware_concurrency());
  setup.progress = !vm.count("quiet");

  // Every configuration error stops here, before a run starts or anything is written.
  const PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  const std::string source = sourceSection(setup, registry);
  for (const auto& s : setup.sets) {
    check(s.rfind(source + ".seed=", 0) != 0,
          "--set " + s + ": each run has its own seed; use --seed-base");
    check(s.rfind(source + ".truth=", 0) != 0,
          "--set " + s + ": each run's truth.csv is written to and read from its run_NNN/");
  }
  validateMonteCarlo(setup, source, registry);

  fs::create_directories(setup.out_dir);
  MonteCarloInfo info;
  info.setup = setup;
  info.threshold = threshold;
  info.outcomes = runMonteCarlo(setup, source, registry);

  std::vector<std::string> truth, tracks;
  for (const auto& o : info.outcomes) {
    if (o.status != "ok") {
      std::cerr << "error: run " << o.index << " (seed " << o.seed << ") failed: " << o.error
                << "\n";
      continue;
    }
    truth.push_back(o.dir + "/truth.csv");
    tracks.push_back(o.dir + "/tracks.csv");
  }
  std::optional<MonteCarloScore> score;
  removeStalePlots(setup.out_dir);
  if (!truth.empty()) {
    eval::TrackingOptions opt;
    opt.threshold = threshold;
    opt.hota_distance = threshold;
    score = scoreMonteCarlo(truth, tracks, opt);
    writeConsistencyCsv(setup.out_dir + "/consistency.csv", *score);
    info.files.push_back("consistency.csv");
    const std::string name = fs::path(setup.scenario).stem().string();
    for (const auto& f : drawConsistencyPlots(setup.out_dir, *score, name)) info.files.push_back(f);
    const RunOutcome& first = info.outcomes[0];
    if (first.status == "ok" &&
        drawLlrPlot(
            first.dir + "/existence.csv", setup.out_dir + "/llr.png",
            name + ": track log-likelihood ratio, run 0 (seed " + std::to_string(first.seed) + ")"))
      info.files.push_back("llr.png");
  }
  info.files.insert(info.files.begin(), "montecarlo.json");
  const MonteCarloScore* s = score ? &*score : nullptr;
  const std::string json = monteCarloJson(info, s);
  {
    std::ofstream f(setup.out_dir + "/montecarlo.json");
    if (!(f << json)) throw DataError("cannot write '" + setup.out_dir + "/montecarlo.json'");
  }
  std::cout << (vm.count("json") ? json : monteCarloText(info, s));
  return truth.size() == info.outcomes.size() ? exit_code::kOk : exit_code::kFailure;
}

}  // namespace pedtrack::cli
