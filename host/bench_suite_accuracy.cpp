// `bench --suite`: every tracker on every shipped scenario it applies to, one run each (seed 1),
// scored as `pedtrack eval` scores it (CLEAR MOT at 0.75 m, IDF1, HOTA, position and heading
// errors, the NEES inside-fraction), in one leaderboard, with the papers' figures where the
// scenario reproduces theirs.
#include <mrpt/core/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include "bench_suite.h"
#include "montecarlo_run.h"
#include "montecarlo_score.h"
#include "pedtrack/plugin_registry.h"
#include "pedtrack/sim/scenario.h"

namespace fs = std::filesystem;

namespace pedtrack::cli {
namespace {

// What a scenario's sensor is: a VLP-16 (3D), a 2D scanner at leg height (below 0.7 m, the
// simulator's own leg-height rule) or at torso height.
enum class Kind { ThreeD, Legs, Torso };

struct Tracker {
  std::string name, config;
  std::vector<std::string> sets;
  Kind kind;
  bool one_person = false;  ///< a single-person tracker (leg_pose): scenarios with one person
};

const std::vector<Tracker>& trackers() {
  static const std::vector<Tracker> t{
      {"imm_shape", "people_3d_vlp16.ini", {}, Kind::ThreeD},
      {"kf_bb", "people_3d_vlp16.ini", {"track.plugin=kf_bb"}, Kind::ThreeD},
      {"kf_circle", "people_3d_vlp16.ini", {"track.plugin=kf_circle"}, Kind::ThreeD},
      {"mhe_mlesac", "people_3d_mhe.ini", {}, Kind::ThreeD},
      {"ekf_motion", "people_3d_motion.ini", {}, Kind::ThreeD},
      {"imm_pdaf", "people_2d_torso.ini", {}, Kind::Torso},
      {"imm_pdaf, P4 preset", "people_2d_torso_p4.ini", {}, Kind::Torso},
      {"leg_people", "people_2d_legs.ini", {}, Kind::Legs},
      {"leg_pose", "leg_pose_p3.ini", {}, Kind::Legs, true},
  };
  return t;
}

// The papers' figures for a (tracker, scenario) our scenario reproduces.
std::string paperFigure(const std::string& tracker, const std::string& scenario) {
  static const std::map<std::pair<std::string, std::string>, std::string> figures{
      {{"kf_bb", "p0_c_path"}, "P0 Table I: 75.8 mm, 0.426 rad (24.4°) axis RMSE"},
      {{"kf_circle", "p0_c_path"}, "P0 Table I: 135.6 mm"},
      {{"mhe_mlesac", "p0_c_path"}, "P0 Table I: 78.0 mm, 0.307 rad (17.6°) axis RMSE"},
      {{"leg_pose", "p3_s1_straight_turn_back"}, "P3 Table 1: orientation MAE 2.3°"},
      {{"leg_pose", "p3_s2_sidestep_turn"}, "P3 Table 1: orientation MAE 3.2°"},
      {{"leg_pose", "p3_s3_turn_straight"}, "P3 Table 1: orientation MAE 4.1°"},
      {{"leg_pose", "p3_s4_random"}, "P3 Table 1: orientation MAE 11.5°"},
  };
  const auto it = figures.find({tracker, scenario});
  return it == figures.end() ? "" : it->second;
}

struct Job {
  const Tracker* tracker;
  std::string scenario, name;  // path, stem
  std::string error;
  std::optional<eval::TrackingReport> report;
  std::size_t frames = 0;
  double wall_s = 0;
};

std::string num(double v, const char* f) {
  return std::isfinite(v) ? mrpt::format(f, v) : "—";
}
double deg(double rad) {
  return rad * 180.0 / M_PI;
}

}  // namespace

std::string accuracySection(const SuiteContext& ctx) {
  const bool q = ctx.options.quick;
  std::vector<Job> jobs;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(ctx.source_dir + "/configs/scenarios"))
    if (e.path().extension() == ".ini") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const sim::Scenario s = sim::loadScenario(f.string());
    const bool two_d = s.sensor.model != "vlp16";
    const Kind kind = !two_d ? Kind::ThreeD : (s.sensor.mount.z() < 0.7 ? Kind::Legs : Kind::Torso);
    if (s.people.empty()) continue;
    for (const auto& t : trackers())
      if (t.kind == kind && (!t.one_person || s.people.size() == 1))
        jobs.push_back({&t, f.string(), f.stem().string(), "", std::nullopt, 0, 0});
  }

  PluginRegistry registry(PluginRegistry::defaultSearchPath(ctx.options.plugin_path));
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      Job& j = jobs[i];
      MonteCarloSetup setup;
      setup.pipeline = ctx.config(j.tracker->config);
      setup.scenario = j.scenario;
      setup.out_dir = ctx.work + "/accuracy/" + j.name + "/" + j.tracker->config + "_" +
                      std::to_string(&*j.tracker - &trackers()[0]);
      setup.runs = 1;
      setup.jobs = 1;
      setup.progress = false;
      setup.sets = j.tracker->sets;
      try {
        const std::string source = sourceSection(setup, registry);
        if (q) setup.sets.push_back(source + ".duration=2");
        const RunOutcome o = runMonteCarlo(setup, source, registry).front();
        j.frames = o.frames;
        j.wall_s = o.wall_time_s;
        if (o.status != "ok") throw std::runtime_error(o.error);
        const std::string dir = runDir(setup, 0);
        const MonteCarloScore score =
            scoreMonteCarlo({dir + "/truth.csv"}, {dir + "/tracks.csv"}, eval::TrackingOptions());
        j.report = score.tracking;

      } catch (const std::exception& e) {
        j.error = e.what();
      }
      std::lock_guard<std::mutex> lock(mutex);
      ctx.progress(mrpt::format("accuracy %zu/%zu: %s on %s%s", ++done, jobs.size(),
                                j.tracker->name.c_str(), j.name.c_str(),
                                j.error.empty() ? "" : (" — " + j.error).c_str()));
    }
  };
  {
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < std::max<std::size_t>(1, ctx.options.jobs); ++k)
      threads.emplace_back(worker);
    for (auto& t : threads) t.join();
  }

  // Best MOTA and HOTA of each scenario in bold.
  std::map<std::string, double> best_mota, best_hota;
  for (const auto& j : jobs)
    if (j.report) {
      const double m = j.report->clear.mota();
      const double h = j.report->hota ? j.report->hota->hota() : NAN;
      if (std::isfinite(m))
        best_mota[j.name] = std::max(best_mota.count(j.name) ? best_mota[j.name] : -1e9, m);
      if (std::isfinite(h))
        best_hota[j.name] = std::max(best_hota.count(j.name) ? best_hota[j.name] : -1e9, h);
    }
  const auto bold = [](const std::string& s, bool b) { return b ? "**" + s + "**" : s; };

  std::string md = "## Accuracy of every tracker on every scenario\n\n";
  md +=
      "Each tracker's shipped pipeline on every scenario in `configs/scenarios/` whose sensor "
      "it is made for (VLP-16; a 2D scanner below 0.7 m: legs; above: torso) and that has "
      "people; `leg_pose` tracks one person, so only one-person scenarios. One run each, seed "
      "1, the whole scenario";
  md += q ? " (quick: its first 2 s)" : "";
  md +=
      "; the same as `pedtrack montecarlo configs/PIPELINE configs/scenarios/SCENARIO --runs 1` "
      "then its scores. CLEAR MOT with a 0.75 m match distance (MOTP in m), IDF1, HOTA "
      "(α-averaged), RMSE of the matched positions and headings, and the share of "
      "matched frames whose NEES lies in the 95 % χ² region (a consistent filter: ~95 %). "
      "Best MOTA and HOTA per scenario in bold.\n\n";
  md +=
      "| scenario | tracker | MOTA | MOTP | ID sw. | IDF1 | HOTA | pos. RMSE | heading RMSE | "
      "heading MAE | NEES inside | paper "
      "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  struct Sum {
    std::size_t n = 0;
    double mota = 0, idf1 = 0, hota = 0, rmse = 0;
    std::size_t rmse_n = 0;  ///< runs with matched positions
  };
  std::map<std::string, Sum> sums;
  std::vector<std::string> order;
  for (const auto& j : jobs) {
    const std::string& t = j.tracker->name;
    if (!sums.count(t)) order.push_back(t);
    auto& s = sums[t];
    md += "| `" + j.name + "` | `" + t + "` | ";
    if (!j.error.empty()) {
      md += "error: " + j.error + " | | | | | | | | | |\n";
      continue;
    }
    if (!j.report) {  // no track at all: every truth missed
      ++s.n;
      md += "0.000 | — | 0 | 0.000 | 0.000 | — | — | — | — | no track reported |\n";
      continue;
    }
    const auto& r = *j.report;
    const double mota = r.clear.mota(), hota = r.hota ? r.hota->hota() : NAN,
                 idf1 = r.identity ? r.identity->idf1() : NAN;
    ++s.n, s.mota += mota, s.idf1 += idf1, s.hota += hota;
    if (std::isfinite(r.errors.rmse())) s.rmse += r.errors.rmse(), ++s.rmse_n;
    md += bold(num(mota, "%.3f"), mota == best_mota[j.name]) + " | " + num(r.clear.motp(), "%.3f") +
          mrpt::format(" | %zu | ", r.clear.id_switches) + num(idf1, "%.3f") + " | " +
          bold(num(hota, "%.3f"), hota == best_hota[j.name]) + " | " +
          num(r.errors.rmse(), "%.3f m") + " | " + num(deg(r.errors.headingRmse()), "%.1f°") +
          " | " + num(deg(r.errors.headingMae()), "%.1f°") + " | " +
          (r.nees ? num(100 * r.nees->fraction_inside, "%.0f %%") : "—") + " | ";
    const std::string paper = paperFigure(t, j.name);
    if (!paper.empty())
      md += paper + (j.name == "p0_c_path"
                         ? "; ours " + num(1000 * r.errors.rmse(), "%.1f mm") + ", " +
                               num(deg(r.errors.axisRmse()), "%.1f°") + " axis"
                         : "");
    md += " |\n";
  }
  md +=
      "\nMean over the scenarios each tracker ran (unweighted; scenarios differ by tracker "
      "kind, so compare within a kind):\n\n| tracker | scenarios | MOTA | IDF1 | HOTA | pos. "
      "RMSE |\n|---|---:|---:|---:|---:|---:|\n";
  for (const auto& t : order) {
    const Sum& s = sums[t];
    if (!s.n) continue;
    md += "| `" + t + "` | " + std::to_string(s.n) + " | " + num(s.mota / s.n, "%.3f") + " | " +
          num(s.idf1 / s.n, "%.3f") + " | " + num(s.hota / s.n, "%.3f") + " | " +
          num(s.rmse_n ? s.rmse / s.rmse_n : NAN, "%.3f m") + " |\n";
  }
  return md + "\n";
}

}  // namespace pedtrack::cli
