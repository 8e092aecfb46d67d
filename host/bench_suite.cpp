#include "bench_suite.h"

#include <mrpt/core/format.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "machine_info.h"
#include "pedtrack/errors.h"

namespace fs = std::filesystem;

namespace pedtrack::cli {
namespace {

const auto kSuiteStart = std::chrono::steady_clock::now();

// The checkout whose configs/ the suite runs: the given one, else the working directory, else
// the one this binary was built in (build/bin/pedtrack → ../../).
std::string findSourceDir(const std::string& given, const std::string& exe) {
  const auto has = [](const fs::path& d) { return fs::exists(d / "configs/people_3d_vlp16.ini"); };
  if (!given.empty()) {
    if (!has(given))
      throw ConfigError("--source '" + given + "': no configs/people_3d_vlp16.ini under it");
    return fs::absolute(given).lexically_normal().string();
  }
  for (const fs::path& d : {fs::current_path(), fs::path(exe).parent_path() / "../.."})
    if (has(d)) return fs::weakly_canonical(d).string();
  throw ConfigError(
      "pedtrack bench --suite: cannot find configs/ (run it from the source tree or pass "
      "--source DIR)");
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
  return cells;
}

}  // namespace

std::string SuiteContext::config(const std::string& name) const {
  return source_dir + "/configs/" + name;
}
std::string SuiteContext::scenario(const std::string& name) const {
  return source_dir + "/configs/scenarios/" + name;
}

void SuiteContext::progress(const std::string& what) const {
  const double s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - kSuiteStart).count();
  std::fprintf(stderr, "bench: %s (%.0f s)\n", what.c_str(), s);
}

ChildResult SuiteContext::run(const std::vector<std::string>& args, const std::string& what,
                              double sample_every_s) const {
  std::vector<std::string> argv{exe};
  argv.insert(argv.end(), args.begin(), args.end());
  for (const auto& p : options.plugin_path) argv.insert(argv.end(), {"--plugin-path", p});
  {
    std::ofstream l(log, std::ios::app);
    l << "\n$";
    for (const auto& a : argv) l << ' ' << a;
    l << '\n';
  }
  ChildResult r = runChild(argv, log, sample_every_s);
  if (r.exit_code != 0)
    throw DataError(what + ": exit " + std::to_string(r.exit_code) + ": " + tailOf(log) +
                    " (whole output in " + log + ")");
  return r;
}

std::string SuiteContext::crowdScenario(const std::string& name, int people) const {
  std::ifstream in(scenario(name));
  if (!in) throw ConfigError(scenario(name) + ": cannot read");
  std::string text, line, section;
  bool replaced = false;
  const std::regex count_key(R"(^\s*count\s*=.*)");
  while (std::getline(in, line)) {
    if (const auto b = line.find('['); b != std::string::npos && line.find_first_not_of(" \t") == b)
      section = line.substr(b + 1, line.find(']') - b - 1);
    if (section == "crowd" && std::regex_match(line, count_key)) {
      line = "count = " + std::to_string(people);
      replaced = true;
    }
    text += line + '\n';
  }
  if (!replaced) throw ConfigError(scenario(name) + ": [crowd] count: not found");
  fs::create_directories(work + "/scenarios");
  const std::string path =
      work + "/scenarios/" + fs::path(name).stem().string() + mrpt::format("_%d.ini", people);
  std::ofstream(path) << text;
  return path;
}

const StageFigures* PipelineFigures::stage(const std::string& plugin) const {
  for (const auto& s : stages)
    if (s.plugin == plugin) return &s;
  return nullptr;
}

PipelineFigures benchPipeline(const SuiteContext& ctx, const std::string& label,
                              const std::string& pipeline, const std::string& input,
                              const std::vector<std::string>& sets, long frames, long repeat,
                              long points) {
  const std::string csv = ctx.work + "/stages.csv";
  std::vector<std::string> args{
      "bench",    "--pipeline",           pipeline, "--frames", std::to_string(frames),
      "--repeat", std::to_string(repeat), "--csv",  csv};
  if (!input.empty()) args.insert(args.end(), {"--input", input});
  if (points > 0) args.insert(args.end(), {"--points", std::to_string(points)});
  for (const auto& s : sets) args.insert(args.end(), {"--set", s});
  ctx.progress(label);
  const ChildResult child = ctx.run(args, label);
  PipelineFigures f;
  f.peak_rss_kb = child.peak_rss_kb;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const auto c = splitCsvLine(line);
    if (c.size() < 11) continue;
    f.stages.push_back(
        {c[0], c[1], std::stod(c[2]), std::stod(c[3]), std::stod(c[4]), std::stod(c[5])});
    f.frames = std::stod(c[6]);
    f.points = std::stod(c[7]);
    f.clusters = std::stod(c[8]);
    f.tracks = std::stod(c[9]);
    f.failed = std::stol(c[10]);
  }
  if (f.stages.empty()) throw DataError(label + ": " + csv + ": no figures written");
  return f;
}

// The part of the report measured by hand (real data, Monte Carlo sets, the commands given
// there): everything from the marker line on in the existing report, kept as it is.
static std::string handMeasuredPart(const fs::path& report) {
  std::ifstream in(report);
  if (!in) return std::string();
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t at = s.find(kHandMeasuredMarker);
  return at == std::string::npos ? std::string() : "\n" + s.substr(at);
}

int benchSuite(const SuiteOptions& options) {
  SuiteContext ctx;
  ctx.options = options;
  ctx.exe = selfExecutable();
  ctx.source_dir = findSourceDir(options.source_dir, ctx.exe);
  ctx.work = fs::absolute(options.work).lexically_normal().string();
  fs::create_directories(ctx.work);
  const fs::path out = fs::absolute(options.out).lexically_normal();
  ctx.plots_rel = "docs/bench";
  ctx.plots_dir = (out.parent_path() / ctx.plots_rel).string();
  fs::create_directories(ctx.plots_dir);
  ctx.log = ctx.work + "/suite.log";
  fs::remove(ctx.log);
  if (std::string(PEDTRACK_BUILD_TYPE) != "Release")
    std::fprintf(stderr,
                 "warning: this is a '%s' build; the timings are meaningful in Release only\n",
                 PEDTRACK_BUILD_TYPE);

  const MachineInfo m = machineInfo(ctx.source_dir, PEDTRACK_BUILD_TYPE);
  const auto t0 = std::chrono::steady_clock::now();
  // One after the other, in the report's order (the operands of + run in any order).
  std::string body = speedSection(ctx);
  body += scalingSection(ctx);
  body += accuracySection(ctx);
  body += soakSection(ctx);
  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 60;

  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::string md = "# pedtrack benchmarks\n\n";
  md += "Written by `pedtrack bench --suite" + std::string(options.quick ? " --quick" : "") +
        "` (" + mrpt::format("%.0f", minutes) +
        " min); do not edit this part by hand, run it again.\n"
        "Every timing is one core (one thread, OpenCV on one thread) in a child process of "
        "its own, on frames read and decoded before timing; peak RSS is that process's.\n\n";
  md += "| | |\n|---|---|\n";
  md += "| date | " + std::string(date) + " |\n";
  md += "| commit | " + m.commit + " |\n";
  md += "| CPU | " + m.cpu + mrpt::format(" (%u hardware threads)", m.threads) + " |\n";
  md += mrpt::format("| memory | %.1f GB |\n", m.memory_gb);
  md += "| kernel | " + m.kernel + " |\n";
  md += "| compiler | " + m.compiler + " |\n";
  md += "| build | " + m.build_type + " |\n\n";
  if (options.quick)
    md +=
        "**Quick run** (`--quick`): tiny sizes to check the suite works; the figures are not "
        "the benchmark.\n\n";
  md += body;
  md += handMeasuredPart(out);
  std::ofstream file(out);
  file << md;
  if (!file) throw ConfigError("--out '" + out.string() + "': cannot write");
  std::fprintf(stderr, "bench: wrote %s (plots in %s)\n", out.c_str(), ctx.plots_dir.c_str());
  return 0;
}

}  // namespace pedtrack::cli
