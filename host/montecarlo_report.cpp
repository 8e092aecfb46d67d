#include "montecarlo_report.h"

#include <mrpt/core/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "eval_report.h"
#include "pedtrack/errors.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using mrpt::format;

std::string fileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

EvalSetup evalSetup(const MonteCarloInfo& info) {
  EvalSetup s;
  s.threshold = info.threshold;
  s.hota_distance = info.threshold;
  return s;
}

std::size_t failed(const MonteCarloInfo& info) {
  return std::count_if(info.outcomes.begin(), info.outcomes.end(),
                       [](const RunOutcome& o) { return o.status != "ok"; });
}

struct SwitchStats {
  std::size_t min = 0, max = 0;
  double mean = NAN;
};

SwitchStats switchStats(const MonteCarloScore& s) {
  SwitchStats st;
  if (s.runs.empty()) return st;
  st.min = st.max = s.runs[0].id_switches;
  double sum = 0;
  for (const auto& r : s.runs) {
    st.min = std::min(st.min, r.id_switches);
    st.max = std::max(st.max, r.id_switches);
    sum += r.id_switches;
  }
  st.mean = sum / s.runs.size();
  return st;
}

std::string percent(double fraction) {
  return std::isfinite(fraction) ? fixed(100 * fraction, 1) + " %" : std::string("-");
}

std::string perTruthText(const MonteCarloScore& s) {
  std::string o = format(
      "\nPer truth id (frame index k; NEES and NIS averaged over the runs "
      "that matched it at k)\n  %-7s %7s %8s %12s %8s %11s %8s %11s %10s %17s %16s\n",
      "truth", "frames", "matched", "NEES frames", "inside", "NIS frames", "inside", "RMSE mean",
      "RMSE max", "heading RMSE mean", "heading RMSE max");
  for (const auto& t : s.truths)
    o += format("  %-7ld %7zu %8zu %12zu %8s %11zu %8s %9s m %8s m %13s rad %12s rad\n", t.id,
                t.frames, t.matched_frames, t.nees_frames, percent(t.nees_inside).c_str(),
                t.nis_frames, percent(t.nis_inside).c_str(), fixed(t.rmse_mean).c_str(),
                fixed(t.rmse_max).c_str(), fixed(t.heading_rmse_mean).c_str(),
                fixed(t.heading_rmse_max).c_str());
  return o;
}

std::string switchesText(const MonteCarloScore& s) {
  std::string o = "\nID switches per run:";
  for (std::size_t i = 0; i < s.runs.size(); ++i)
    o += (i && i % 25 == 0 ? "\n    " : " ") + std::to_string(s.runs[i].id_switches);
  const SwitchStats st = switchStats(s);
  o += format("\n  min %zu, mean %s, max %zu\n", st.min, fixed(st.mean, 2).c_str(), st.max);
  o += format("identity survived in %zu of %zu runs (no ID switch)\n", s.runsWithoutSwitch(),
              s.runs.size());
  return o;
}

std::string truthJson(const TruthSummary& t) {
  Json j;
  j.raw("id", std::to_string(t.id))
      .count("frames", t.frames)
      .count("matched_frames", t.matched_frames)
      .count("nees_frames", t.nees_frames)
      .num("nees_fraction_inside", t.nees_inside)
      .count("nis_frames", t.nis_frames)
      .num("nis_fraction_inside", t.nis_inside)
      .num("rmse_mean_m", t.rmse_mean)
      .num("rmse_max_m", t.rmse_max)
      .count("heading_frames", t.heading_frames)
      .num("heading_rmse_mean_rad", t.heading_rmse_mean)
      .num("heading_rmse_max_rad", t.heading_rmse_max);
  return j.str();
}

std::string runsJson(const MonteCarloInfo& info, const MonteCarloScore* s) {
  std::string out = "[";
  std::size_t scored = 0;
  for (const auto& o : info.outcomes) {
    Json j;
    j.count("run", o.index)
        .count("seed", o.seed)
        .text("dir", o.dir)
        .text("status", o.status)
        .count("frames", o.frames)
        .num("wall_time_s", o.wall_time_s);
    if (o.status != "ok") {
      j.text("error", o.error);
    } else if (s && scored < s->runs.size()) {
      const RunScore& r = s->runs[scored++];
      j.count("track_rows", r.track_rows);
      if (s->tracking) j.count("id_switches", r.id_switches).num("mota", r.mota);
    }
    out += std::string(out.size() > 1 ? ",\n    " : "\n    ") + j.str();
  }
  return out + (out.size() > 1 ? "\n  ]" : "]");
}

std::string csvNumber(double v, int decimals = 6) {
  return std::isfinite(v) ? format("%.*f", decimals, v) : std::string();
}

/// mean,lower,upper,inside; empty fields without a value.
std::string csvConsistency(const std::optional<eval::ConsistencyPoint>& c) {
  if (!c) return ",,,";
  return csvNumber(c->mean) + "," + csvNumber(c->bounds.lower) + "," + csvNumber(c->bounds.upper) +
         "," + (c->inside ? "1" : "0");
}

/// The files by name; the per-truth plots counted by kind ("nees_<id>.png × 20").
std::string filesText(const std::vector<std::string>& files) {
  std::string o;
  std::vector<std::pair<std::string, std::size_t>> kinds;  // prefix, count; in order of first
  for (const auto& f : files) {
    const auto u = f.find('_');
    if (u == std::string::npos || f.size() < 4 || f.compare(f.size() - 4, 4, ".png") != 0) {
      o += (o.empty() ? "" : ", ") + f;
      continue;
    }
    const std::string kind = f.substr(0, u);
    auto it =
        std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == kind; });
    if (it == kinds.end()) {
      kinds.emplace_back(kind, 1);
      o += (o.empty() ? "" : ", ") + kind + "_<truth id>.png";
    } else {
      ++it->second;
    }
  }
  for (const auto& [kind, n] : kinds) {
    const std::string name = kind + "_<truth id>.png";
    o.replace(o.find(name), name.size(), name + format(" (%zu)", n));
  }
  return o;
}

}  // namespace

std::string monteCarloText(const MonteCarloInfo& info, const MonteCarloScore* s) {
  const auto& su = info.setup;
  std::string o = format(
      "pedtrack montecarlo: %zu run%s of %s through %s (seeds %lu-%lu), %zu scored; outputs in "
      "%s\n",
      su.runs, su.runs == 1 ? "" : "s", fileName(su.scenario).c_str(),
      fileName(su.pipeline).c_str(), su.seed_base, su.seed_base + su.runs - 1,
      s ? s->runs.size() : 0, su.out_dir.c_str());
  if (failed(info)) {
    o += "\nfailed runs (not scored):\n";
    for (const auto& r : info.outcomes)
      if (r.status != "ok")
        o += format("  run %zu (seed %lu): %s\n", r.index, r.seed, r.error.c_str());
  }
  if (!s) return o + "\nno run to score\n";
  if (!s->tracking) {
    o += "\nno tracks to score: the pipeline wrote no track rows in any run (has it a tracker "
         "stage?)\n";
  } else {
    // eval's table, headed as what it is here.
    std::string table = trackingText(*s->tracking, evalSetup(info));
    const std::string eval_head = "pedtrack eval: ";
    if (table.rfind(eval_head, 0) == 0)
      table = "All runs pooled: " + table.substr(eval_head.size());
    o += "\n" + table;
    o += perTruthText(*s);
    o += switchesText(*s);
  }
  if (!info.files.empty()) o += "\nfiles: " + filesText(info.files) + "\n";
  return o;
}

std::string monteCarloJson(const MonteCarloInfo& info, const MonteCarloScore* s) {
  const auto& su = info.setup;
  Json top(true);
  top.text("mode", "montecarlo")
      .text("pipeline", su.pipeline)
      .text("scenario", su.scenario)
      .text("out", su.out_dir)
      .count("runs", su.runs)
      .count("runs_scored", s ? s->runs.size() : 0)
      .count("runs_failed", failed(info))
      .count("seed_base", su.seed_base)
      .count("jobs", su.jobs)
      .num("threshold_m", info.threshold)
      .count("track_rows", s ? s->track_rows : 0)
      .raw("no_tracks", !s || !s->tracking ? "true" : "false");
  std::string tracking = "null", switches = "null", truths = "[]";
  if (s && s->tracking) {
    tracking = trackingJson(*s->tracking, evalSetup(info));
    while (!tracking.empty() && tracking.back() == '\n') tracking.pop_back();
    const SwitchStats st = switchStats(*s);
    std::string per = "[";
    for (std::size_t i = 0; i < s->runs.size(); ++i)
      per += (i ? ", " : "") + std::to_string(s->runs[i].id_switches);
    Json j;
    j.raw("per_run", per + "]")
        .count("min", st.min)
        .num("mean", st.mean)
        .count("max", st.max)
        .count("runs_without_switch", s->runsWithoutSwitch());
    switches = j.str();
    truths = "[";
    for (std::size_t i = 0; i < s->truths.size(); ++i)
      truths += (i ? ",\n    " : "\n    ") + truthJson(s->truths[i]);
    truths += s->truths.empty() ? "]" : "\n  ]";
  }
  std::string files = "[";
  for (std::size_t i = 0; i < info.files.size(); ++i)
    files += (i ? ", \"" : "\"") + jsonEscape(info.files[i]) + "\"";
  top.raw("tracking", tracking)
      .raw("id_switches", switches)
      .raw("per_truth", truths)
      .raw("run_list", runsJson(info, s))
      .raw("files", files + "]")
      .raw("t0", s ? format("%.6f", s->t0) : std::string("null"));
  return top.str() + "\n";
}

void writeConsistencyCsv(const std::string& path, const MonteCarloScore& s) {
  std::ofstream f(path);
  if (!f) throw DataError("cannot write '" + path + "'");
  f << "truth_id,frame,t,n,nees_mean,nees_lower,nees_upper,nees_inside,nis_mean,nis_lower,"
       "nis_upper,nis_inside,rmse_x,rmse_y,rmse,heading_n,heading_rmse\n";
  for (const auto& p : s.points)
    f << p.truth_id << "," << p.frame << "," << csvNumber(p.t) << "," << p.n << ","
      << csvConsistency(p.nees) << "," << csvConsistency(p.nis) << "," << csvNumber(p.rmse_x) << ","
      << csvNumber(p.rmse_y) << "," << csvNumber(p.rmse) << "," << p.heading_n << ","
      << csvNumber(p.heading_rmse) << "\n";
  if (!f) throw DataError("cannot write '" + path + "'");
}

}  // namespace pedtrack::cli
