// `bench --suite`: speed per pipeline and stage against the targets, and cost against
// points and people per frame (tables and PNG plots).
#include <mrpt/core/format.h>

#include <cmath>

#include "bench_suite.h"
#include "plot.h"

namespace pedtrack::cli {
namespace {

std::string ms(double v) {
  return mrpt::format(v < 10 ? "%.2f" : "%.1f", v);
}
std::string mb(long kb) {
  return mrpt::format("%.0f MB", kb / 1024.0);
}
std::string yesNo(bool met) {
  return met ? "**met**" : "**not met**";
}

struct PipelineRun {
  std::string label, config, input, load;
  std::vector<std::string> sets;
  long frames, repeat;
};

std::string stageTable(const PipelineFigures& f) {
  std::string t =
      "| stage | plugin | p50 ms | p99 ms | mean ms | max ms |\n|---|---|---:|---:|---:|---:|\n";
  for (const auto& s : f.stages)
    t += "| " + s.stage + " | " + (s.plugin.empty() ? "" : "`" + s.plugin + "`") + " | " +
         ms(s.p50) + " | " + ms(s.p99) + " | " + ms(s.mean) + " | " + ms(s.max) + " |\n";
  return t;
}

}  // namespace

std::string speedSection(const SuiteContext& ctx) {
  const bool q = ctx.options.quick;
  const std::string legs5 = ctx.crowdScenario("legs_crowd_10.ini", 5);
  const std::string crowd10 = ctx.crowdScenario("crowd.ini", 10);
  const std::vector<PipelineRun> runs{
      {"2D leg",
       "people_2d_legs.ini",
       legs5,
       "5 walkers, 768-beam scans (`legs_crowd_10.ini`, count 5)",
       {},
       q ? 10 : 300,
       q ? 1 : 5},
      {"2D torso, `imm_pdaf`",
       "people_2d_torso.ini",
       ctx.scenario("torso_crowd_20.ini"),
       "20 people, UTM-30LX at torso height (`torso_crowd_20.ini`)",
       {},
       q ? 10 : 200,
       q ? 1 : 5},
      {"3D VLP-16, `imm_shape`",
       "people_3d_vlp16.ini",
       crowd10,
       "10 people (`crowd.ini`, count 10)",
       {},
       q ? 10 : 200,
       q ? 1 : 3},
      {"3D VLP-16, `mhe_mlesac`",
       "people_3d_mhe.ini",
       crowd10,
       "10 people (`crowd.ini`, count 10)",
       {},
       q ? 5 : 100,
       1},
  };
  std::vector<PipelineFigures> figs;
  for (const auto& r : runs)
    figs.push_back(benchPipeline(ctx, "speed: " + r.label, ctx.config(r.config), r.input, r.sets,
                                 r.frames, r.repeat));

  std::string md = "## Speed per pipeline\n\n";
  md +=
      "`pedtrack bench --pipeline configs/PIPELINE --input SCENARIO --frames F --repeat R` for "
      "each row (the suite writes the scenarios with other crowd sizes to its work "
      "directory). Per frame, all stages:\n\n";
  md +=
      "| pipeline | load | points / frame | tracks / frame | frames/s | p50 ms | p99 ms | max ms | "
      "peak RSS |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& f = figs[i];
    // Frames a stage threw on are left out of the timings: say so where it happened.
    const std::string failed =
        f.failed ? mrpt::format(" (**%ld frames failed**, not timed)", f.failed) : "";
    md += "| " + runs[i].label + " (`" + runs[i].config + "`) | " + runs[i].load + failed +
          mrpt::format(" | %.0f | %.1f | %.0f | ", f.points, f.tracks, f.framesPerSecond()) +
          ms(f.total().p50) + " | " + ms(f.total().p99) + " | " + ms(f.total().max) + " | " +
          mb(f.peak_rss_kb) + " |\n";
  }
  const auto& legs = figs[0];
  const auto& vlp = figs[2];
  const auto& mhe = figs[3];
  const StageFigures* mhe_stage = mhe.stage("mhe_mlesac");
  const double per_person = mhe_stage && mhe.tracks > 0 ? mhe_stage->mean / mhe.tracks : NAN;
  md += "\n**Targets** (one core):\n\n| target | measured | |\n|---|---|---|\n";
  md += mrpt::format("| 2D leg pipeline ≥ 2,000 scans/s | %.0f scans/s (mean %s ms) | %s |\n",
                     legs.framesPerSecond(), ms(legs.total().mean).c_str(),
                     yesNo(legs.framesPerSecond() >= 2000).c_str());
  md += "| 3D VLP-16 with 10 people ≤ 10 ms p50, ≤ 25 ms p99 | p50 " + ms(vlp.total().p50) +
        " ms, p99 " + ms(vlp.total().p99) + " ms | " +
        yesNo(vlp.total().p50 <= 10 && vlp.total().p99 <= 25) + " |\n";
  md += "| `mhe_mlesac` ≤ 100 ms per person per frame | " + ms(per_person) +
        mrpt::format(" ms (stage mean %s ms / %.1f tracks) | ",
                     ms(mhe_stage ? mhe_stage->mean : NAN).c_str(), mhe.tracks) +
        yesNo(per_person <= 100) + " |\n";
  md +=
      "\nThe papers' own figures: P1's tracker (ellipse/box/COG IMM on a VLP-16) averaged "
      "16.9 ms per frame with a peak of 204.9 ms on an i9-14900HX (5.8 GHz); the ICRA 2015 "
      "leg_tracker ran at 25 Hz; P0 does not claim real time.\n\n";
  for (std::size_t i = 0; i < runs.size(); ++i)
    md += "### " + runs[i].label +
          mrpt::format(" (%.0f frames × %ld pass%s)\n\n", figs[i].frames, runs[i].repeat,
                       runs[i].repeat == 1 ? "" : "es") +
          stageTable(figs[i]) + "\n";
  return md;
}

std::string scalingSection(const SuiteContext& ctx) {
  const bool q = ctx.options.quick;
  const std::string crowd10 = ctx.crowdScenario("crowd.ini", 10);
  std::string md = "## Cost against points and people per frame\n\n";

  // Points: the VLP-16 crowd's clouds resampled (bench --points).
  const std::vector<long> sizes =
      q ? std::vector<long>{1000, 10000}
        : std::vector<long>{1000, 3000, 10000, 30000, 100000, 300000, 1000000};
  std::vector<PipelineFigures> pf;
  for (long n : sizes)
    pf.push_back(benchPipeline(ctx, mrpt::format("points: %ld", n),
                               ctx.config("people_3d_vlp16.ini"), crowd10, {}, q ? 3 : 20, 1, n));
  md +=
      "`pedtrack bench --pipeline configs/people_3d_vlp16.ini --input crowd-with-10-people "
      "--points N --frames 20 --repeat 1`: every frame's cloud resampled to N points (evenly "
      "thinned below the VLP-16's ~28k, each return repeated with 2 cm of jitter above, as a "
      "denser sensor would see the same scene). p50 ms per frame:\n\n| points |";
  const auto& stages0 = pf.front().stages;
  for (const auto& s : stages0) md += " " + s.stage + " |";
  md += " p99 all | peak RSS |\n|---:|";
  for (std::size_t i = 0; i < stages0.size() + 2; ++i) md += "---:|";
  md += "\n";
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    md += mrpt::format("| %ld |", sizes[k]);
    for (const auto& s : pf[k].stages) md += " " + ms(s.p50) + " |";
    md += " " + ms(pf[k].total().p99) + " | " + mb(pf[k].peak_rss_kb) + " |\n";
  }
  {
    std::vector<double> x(sizes.begin(), sizes.end()), all;
    for (const auto& f : pf) all.push_back(f.total().p50);
    std::vector<double> ys = all;
    for (const auto& f : pf)
      for (const auto& s : f.stages) ys.push_back(s.p50);
    plot::Plot p(900, 560, plot::fitAxis("points per frame", x, true),
                 plot::fitAxis("ms per frame (p50)", ys, true),
                 "3D VLP-16 pipeline: cost against points per frame (one core)");
    for (std::size_t i = 0; i < stages0.size(); ++i) {
      std::vector<double> y;
      for (const auto& f : pf) y.push_back(f.stages[i].p50);
      const bool total = i + 1 == stages0.size();
      p.line(x, y, total ? plot::kBlack : plot::colour(i), total ? 3 : 2, false,
             stages0[i].stage + (stages0[i].plugin.empty() ? "" : " (" + stages0[i].plugin + ")"));
    }
    p.legend(plot::Corner::TopLeft);
    p.write(ctx.plots_dir + "/cost_vs_points.png");
    md += "\n![cost against points](" + ctx.plots_rel + "/cost_vs_points.png)\n\n";
  }

  // People: the 3D crowd and the 2D leg crowd with 1 … 50 walkers.
  const std::vector<int> people =
      q ? std::vector<int>{1, 5} : std::vector<int>{1, 2, 5, 10, 20, 50};
  struct Sweep {
    std::string label, config, scenario, tracker;
    long frames, repeat;
  };
  const std::vector<Sweep> sweeps{
      {"3D VLP-16, `imm_shape`", "people_3d_vlp16.ini", "crowd.ini", "imm_shape", q ? 5 : 100, 1},
      {"2D leg", "people_2d_legs.ini", "legs_crowd_10.ini", "leg_people", q ? 5 : 300, q ? 1 : 2}};
  md +=
      "People per frame: `crowd.ini` (VLP-16) and `legs_crowd_10.ini` (768-beam leg-height "
      "scanner) with their `[crowd] count` set to N (the same area, so 50 walkers is a dense "
      "crowd that hides itself). p50 / p99 ms per frame of all stages, and the tracker's "
      "p50:\n\n| people |";
  for (const auto& s : sweeps) md += " " + s.label + " all | tracks | tracker |";
  md += "\n|---:|";
  for (std::size_t i = 0; i < sweeps.size(); ++i) md += "---:|---:|---:|";
  md += "\n";
  std::vector<std::vector<PipelineFigures>> res(sweeps.size());
  for (int n : people)
    for (std::size_t s = 0; s < sweeps.size(); ++s)
      res[s].push_back(
          benchPipeline(ctx, mrpt::format("people: %s, %d", sweeps[s].config.c_str(), n),
                        ctx.config(sweeps[s].config), ctx.crowdScenario(sweeps[s].scenario, n), {},
                        sweeps[s].frames, sweeps[s].repeat));
  for (std::size_t k = 0; k < people.size(); ++k) {
    md += mrpt::format("| %d |", people[k]);
    for (std::size_t s = 0; s < sweeps.size(); ++s) {
      const auto& f = res[s][k];
      const StageFigures* t = f.stage(sweeps[s].tracker);
      md += " " + ms(f.total().p50) + " / " + ms(f.total().p99) +
            mrpt::format(" | %.1f | ", f.tracks) + (t ? ms(t->p50) : "—") + " |";
    }
    md += "\n";
  }
  {
    std::vector<double> x(people.begin(), people.end()), ys;
    for (const auto& r : res)
      for (const auto& f : r) ys.push_back(f.total().p50), ys.push_back(f.total().p99);
    plot::Plot p(900, 560, plot::fitAxis("people in the scene", x, false, true),
                 plot::fitAxis("ms per frame", ys, true),
                 "Cost against people per frame (one core)");
    for (std::size_t s = 0; s < sweeps.size(); ++s) {
      std::vector<double> p50, p99, tr;
      for (const auto& f : res[s]) {
        p50.push_back(f.total().p50);
        p99.push_back(f.total().p99);
        const StageFigures* t = f.stage(sweeps[s].tracker);
        tr.push_back(t ? t->p50 : NAN);
      }
      std::string name = sweeps[s].label;
      name.erase(std::remove(name.begin(), name.end(), '`'), name.end());
      p.line(x, p50, plot::colour(s), 2, false, name + ": all stages p50");
      p.line(x, p99, plot::colour(s), 1, true, name + ": all stages p99");
      p.line(x, tr, plot::colour(s + 2), 2, false, name + ": tracker p50");
    }
    p.legend(plot::Corner::BottomRight);
    p.write(ctx.plots_dir + "/cost_vs_people.png");
    md += "\n![cost against people](" + ctx.plots_rel + "/cost_vs_people.png)\n\n";
  }
  return md;
}

}  // namespace pedtrack::cli
