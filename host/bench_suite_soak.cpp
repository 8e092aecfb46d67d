// `bench --suite`: the soak. One hour (soak_seconds) of simulated crowd at full speed through
// the 3D and the 2D leg pipelines, each a child `pedtrack run` whose resident memory is sampled
// from /proc; the target is less than 5 MB of growth after the first minute.
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "bench_suite.h"
#include "plot.h"

namespace pedtrack::cli {
namespace {

// A number field of a run.json ("frames_processed", "wall_time_s"), 0 when absent.
double runJsonNumber(const std::string& run_json, const std::string& key) {
  std::ifstream in(run_json);
  std::stringstream ss;
  ss << in.rdbuf();
  std::smatch m;
  const std::string text = ss.str();
  return std::regex_search(text, m, std::regex("\"" + key + "\":\\s*([0-9.eE+-]+)"))
             ? std::stod(m[1])
             : 0;
}

}  // namespace

std::string soakSection(const SuiteContext& ctx) {
  const double secs = ctx.options.quick ? 120 : ctx.options.soak_seconds;
  struct Soak {
    std::string label, config, scenario;
  };
  const std::vector<Soak> soaks{
      {"3D VLP-16, `imm_shape`", "people_3d_vlp16.ini", "`crowd.ini` (20 walkers)"},
      {"2D leg", "people_2d_legs.ini", "`legs_crowd_10.ini` (10 walkers)"}};
  std::string md = "## Soak\n\n";
  md += mrpt::format(
      "`pedtrack run configs/PIPELINE --set source.duration=%.0f --set source.truth=none --out "
      "DIR -q` (the pipeline's own scenario, %.0f simulated minutes at full speed, every output "
      "written); resident memory (VmRSS) sampled from `/proc/PID/status` every 0.1 s. \"After "
      "the first minute\" is the first sample after the first simulated minute: the process's "
      "start-up (its wall time less run.json's `wall_time_s`) plus `wall_time_s` × 60 s / %.0f "
      "s, as the frame rate is steady. Target: less than 5 MB of growth after it.\n\n",
      secs, secs / 60, secs);
  md +=
      "| pipeline | scenario | frames/s | wall | RSS after the first minute | RSS at the end | "
      "largest after the first minute | growth | |\n|---|---|---:|---:|---:|---:|---:|---:|---|\n";
  std::vector<std::vector<std::pair<double, long>>> traces;
  std::vector<double> walls, starts;  // frame-processing span and start-up of each run, s
  for (const auto& s : soaks) {
    const std::string out = ctx.work + "/soak_" + std::filesystem::path(s.config).stem().string();
    ctx.progress(mrpt::format("soak: %s, %.0f s simulated", s.config.c_str(), secs));
    const ChildResult r =
        ctx.run({"run", ctx.config(s.config), "--set", mrpt::format("source.duration=%g", secs),
                 "--set", "source.truth=none", "--out", out, "-q"},
                "soak " + s.config, 0.1);
    std::filesystem::remove(out + "/tracks.csv");  // an hour of rows: hundreds of MB
    if (r.rss.size() < 2) {
      md += "| " + s.label + " | " + s.scenario + " | too short to sample | | | | | | |\n";
      traces.emplace_back();
      walls.push_back(r.wall_s);
      starts.push_back(0);
      continue;
    }
    // Frames run for run.json's wall_time_s after the start-up (plugins, models, scenario).
    const double run_s = runJsonNumber(out + "/run.json", "wall_time_s");
    const double startup = run_s > 0 ? std::max(0.0, r.wall_s - run_s) : 0;
    const double span = run_s > 0 ? run_s : r.wall_s;
    const double minute_at = startup + span * std::min(1.0, 60.0 / secs);
    auto first = std::find_if(r.rss.begin(), r.rss.end(),
                              [&](const auto& p) { return p.first >= minute_at; });
    if (first == r.rss.end()) first = std::prev(r.rss.end());
    long largest = 0;
    for (auto it = first; it != r.rss.end(); ++it) largest = std::max(largest, it->second);
    const long start_kb = first->second, end_kb = r.rss.back().second;
    const double growth = (end_kb - start_kb) / 1024.0, peak_growth = (largest - start_kb) / 1024.0;
    md += "| " + s.label + " (`" + s.config + "`) | " + s.scenario + " | " +
          mrpt::format("%.0f | %.0f s | %.1f MB | %.1f MB | %.1f MB | %+.1f MB | %s |\n",
                       runJsonNumber(out + "/run.json", "frames_processed") / span, r.wall_s,
                       start_kb / 1024.0, end_kb / 1024.0, largest / 1024.0, growth,
                       std::max(growth, peak_growth) < 5 ? "**met**" : "**not met**");
    traces.push_back(r.rss);
    walls.push_back(span);
    starts.push_back(startup);
  }
  std::vector<double> ys, xs{0, secs / 60};
  for (const auto& t : traces)
    for (const auto& p : t) ys.push_back(p.second / 1024.0);
  plot::Plot p(900, 480, plot::fitAxis("simulated minutes", xs, false, true),
               plot::fitAxis("resident memory (MB)", ys, false, true), "Soak: resident memory");
  for (std::size_t i = 0; i < traces.size(); ++i) {
    std::vector<double> x, y;
    for (const auto& [t, kb] : traces[i]) {
      x.push_back(walls[i] > 0 ? std::max(0.0, t - starts[i]) / walls[i] * secs / 60 : 0);
      y.push_back(kb / 1024.0);
    }
    std::string name = soaks[i].label;
    name.erase(std::remove(name.begin(), name.end(), '`'), name.end());
    p.line(x, y, plot::colour(i), 2, false, name);
  }
  p.legend(plot::Corner::BottomRight);
  p.write(ctx.plots_dir + "/soak_rss.png");
  md += "\n![resident memory during the soak](" + ctx.plots_rel + "/soak_rss.png)\n\n";
  return md;
}

}  // namespace pedtrack::cli
