// `pedtrack eval --decisions RUN_DIR`: the person / non-person decisions of a run on simulated
// data against the per-point truth — the appearance classifier alone (P2 Table 1) and appearance
// + motion, a cluster being a person when a confirmed track is on it (P2 Table 2) — per cluster
// and frame, and per object (each person and object once).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/eval/decisions.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using eval::DecisionMatrix;
using eval::DecisionPair;
using eval::DecisionReport;

std::string percent(std::size_t num, std::size_t den) {
  return den ? mrpt::format("%6.2f %% (%zu/%zu)", 100.0 * double(num) / double(den), num, den)
             : std::string("     - (0/0)");
}

/// One matrix in P2's layout, with its rates: lines of equal width.
std::vector<std::string> block(const std::string& title, const DecisionMatrix& m) {
  const std::size_t w = 44;
  std::vector<std::string> l = {
      title,
      "                        decided",
      "                      nonperson   person",
      mrpt::format("  actual  nonperson %11zu %8zu", m.tn, m.fp),
      mrpt::format("          person    %11zu %8zu", m.fn, m.tp),
      "  detection rate  " + percent(m.tp, m.tp + m.fn),
      "  false positives " + percent(m.fp, m.fp + m.tn),
      "  precision       " + percent(m.tp, m.tp + m.fp),
      "  accuracy        " + percent(m.tp + m.tn, m.total()),
  };
  for (auto& s : l)
    if (s.size() < w) s.resize(w, ' ');
  return l;
}

std::string sideBySide(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::string out;
  for (std::size_t i = 0; i < a.size() || i < b.size(); ++i) {
    std::string line = (i < a.size() ? a[i] : std::string(44, ' ')) + "    " +
                       (i < b.size() ? b[i] : std::string());
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  return out;
}

std::string pairText(const DecisionPair& p, const eval::DecisionOptions& o) {
  return sideBySide(block(mrpt::format("appearance (score >= %.2f)", o.q_person), p.appearance),
                    block("appearance + motion (" + o.person_status + " track)", p.complete));
}

std::string text(const DecisionReport& r, const eval::DecisionOptions& o, const std::string& run,
                 const std::string& truth) {
  std::string s = "decisions of " + run + " against " + truth + "\n";
  s += mrpt::format(
      "frames: %zu scored, %zu without a detection; %zu truth frames the run did not process\n",
      r.frames, r.frames_without_detections, r.truth_only_frames);
  s += mrpt::format(
      "clusters: %zu in the scored frames: %zu scored (with a detection), %zu of them ground;\n"
      "          %zu not scored (no detection): %zu person, %zu non-person\n",
      r.clusters, r.clusters_scored, r.scored_ground, r.clusters - r.clusters_scored,
      r.unscored_person, r.unscored_nonperson);
  s += "\n(a) per cluster and frame (a cluster is what most of its points hit)\n";
  s += pairText(r.per_cluster, o);
  const std::size_t persons = r.per_object_any.appearance.tp + r.per_object_any.appearance.fn,
                    objects = r.per_object_any.appearance.tn + r.per_object_any.appearance.fp;
  s += mrpt::format(
      "\n(b) per object: %zu persons and %zu objects, each once (ground clusters left out);\n"
      "never in a scored cluster, so not counted: %zu persons, %zu objects the scans hit\n",
      persons, objects, r.persons_never_scored, r.objects_never_scored);
  s += "a person if decided so in at least one frame (P2 Table 2)\n";
  s += pairText(r.per_object_any, o);
  s += "\na person if decided so in more than half of its frames\n";
  s += pairText(r.per_object_majority, o);
  std::string notes;
  if (r.detections_without_cluster)
    notes += mrpt::format("  %zu detections name no cluster (not scored)\n",
                          r.detections_without_cluster);
  if (r.detections_unknown_cluster)
    notes += mrpt::format("  %zu detections name a cluster without points (not scored)\n",
                          r.detections_unknown_cluster);
  if (r.detections_duplicate)
    notes += mrpt::format(
        "  %zu further detections of an already detected cluster (its highest "
        "score is used)\n",
        r.detections_duplicate);
  if (r.detection_frames_unmatched)
    notes += mrpt::format("  %zu frames of detections.csv are not in both label files\n",
                          r.detection_frames_unmatched);
  if (r.track_clusters_unscored)
    notes += mrpt::format("  %zu %s track rows are on a cluster without a detection\n",
                          r.track_clusters_unscored, o.person_status.c_str());
  if (r.clusters_scored && r.min_score >= o.q_person)
    notes += mrpt::format(
        "  no detection scored below %.2f: the run's classifier probably dropped the non-persons "
        "(run it with q_person = 0 so that every cluster is scored)\n",
        o.q_person);
  if (r.track_rows_person == 0)
    notes += "  no " + o.person_status + " track rows: nothing is decided a person by motion\n";
  if (!notes.empty()) s += "\nnotes:\n" + notes;
  return s;
}

std::string matrixJson(const DecisionMatrix& m) {
  return Json()
      .count("tn", m.tn)
      .count("fp", m.fp)
      .count("fn", m.fn)
      .count("tp", m.tp)
      .num("detection_rate", m.detectionRate())
      .num("false_positive_rate", m.falsePositiveRate())
      .num("precision", m.precision())
      .num("accuracy", m.accuracy())
      .str();
}

std::string pairJson(const DecisionPair& p) {
  return Json()
      .raw("appearance", matrixJson(p.appearance))
      .raw("complete", matrixJson(p.complete))
      .str();
}

std::string json(const DecisionReport& r, const eval::DecisionOptions& o, const std::string& run,
                 const std::string& truth) {
  std::string objects = "[";
  for (std::size_t i = 0; i < r.per_object.size(); ++i) {
    const auto& e = r.per_object[i];
    objects +=
        (i ? ", " : "") + Json()
                              .raw("id", std::to_string(std::abs(e.id)))
                              .text("kind", truth_label::isPerson(e.id) ? "person" : "object")
                              .count("hit_frames", e.hit_frames)
                              .count("frames", e.frames)
                              .count("appearance_frames", e.appearance_frames)
                              .count("complete_frames", e.complete_frames)
                              .str();
  }
  objects += "]";
  return Json(true)
             .text("run", run)
             .text("truth_points", truth)
             .num("q_person", o.q_person)
             .text("person_status", o.person_status)
             .count("frames", r.frames)
             .count("frames_without_detections", r.frames_without_detections)
             .count("truth_only_frames", r.truth_only_frames)
             .count("clusters", r.clusters)
             .count("clusters_scored", r.clusters_scored)
             .count("scored_ground", r.scored_ground)
             .count("unscored_person", r.unscored_person)
             .count("unscored_nonperson", r.unscored_nonperson)
             .count("detections", r.detections)
             .count("detections_without_cluster", r.detections_without_cluster)
             .count("detections_unknown_cluster", r.detections_unknown_cluster)
             .count("detections_duplicate", r.detections_duplicate)
             .count("detection_frames_unmatched", r.detection_frames_unmatched)
             .count("track_rows_person", r.track_rows_person)
             .count("track_rows_without_cluster", r.track_rows_without_cluster)
             .count("track_clusters_unscored", r.track_clusters_unscored)
             .num("min_score", r.min_score)
             .num("max_score", r.max_score)
             .raw("per_cluster", pairJson(r.per_cluster))
             .raw("per_object_any", pairJson(r.per_object_any))
             .raw("per_object_majority", pairJson(r.per_object_majority))
             .count("persons_never_scored", r.persons_never_scored)
             .count("objects_never_scored", r.objects_never_scored)
             .raw("per_object", objects)
             .str() +
         "\n";
}

/// `dir/name`, which must exist: otherwise one line naming it and what made it.
std::string runFile(const std::string& dir, const char* name, const char* writer) {
  const std::string p = (std::filesystem::path(dir) / name).string();
  if (!std::filesystem::is_regular_file(p))
    throw ConfigError("pedtrack eval --decisions: " + p + ": missing (" + writer + ")");
  return p;
}

}  // namespace

int evalDecisionsCommand(const std::vector<std::string>& args) {
  std::string run_dir, truth_points;
  eval::DecisionOptions o;
  bool as_json = false;
  po::options_description opts("options");
  opts.add_options()("decisions", po::value(&run_dir)->required(),
                     "run directory of `pedtrack run --out` on a sim source (point_labels.bin, "
                     "detections.csv with a cluster column, tracks.csv)")(
      "truth-points", po::value(&truth_points),
      "the simulation's truth_points.bin (default: RUN_DIR/truth_points.bin)")(
      "q-person", po::value(&o.q_person)->default_value(0.5),
      "appearance: a cluster is a person when its detection's score is >= this (P2's Q_P)")(
      "person-status", po::value(&o.person_status)->default_value("confirmed"),
      "appearance + motion: a cluster is a person when a track with this status is on it")(
      "json", po::bool_switch(&as_json), "print one JSON object instead of the tables");
  po::variables_map vm;
  // `--decisions --help` would take --help for the directory.
  const bool help = std::find(args.begin(), args.end(), "--help") != args.end() ||
                    std::find(args.begin(), args.end(), "-h") != args.end();
  if (!parseOptions("eval",
                    "--decisions RUN_DIR [--truth-points FILE] [--q-person 0.5] "
                    "[--person-status confirmed] [--json]",
                    opts, {}, help ? std::vector<std::string>{"--help"} : args, vm,
                    "eval --decisions"))
    return exit_code::kOk;
  if (!std::isfinite(o.q_person))
    throw ConfigError("pedtrack eval: --q-person: must be a number (see `pedtrack eval --help`)");
  if (o.person_status.empty())
    throw ConfigError("pedtrack eval: --person-status: must not be empty");
  if (!std::filesystem::is_directory(run_dir))
    throw ConfigError("pedtrack eval --decisions: " + run_dir + ": no such run directory");
  eval::DecisionInputs in;
  in.truth_points =
      truth_points.empty()
          ? runFile(run_dir, "truth_points.bin",
                    "written by the sim source; give --truth-points for another simulation")
          : truth_points;
  if (!std::filesystem::is_regular_file(in.truth_points))
    throw ConfigError("pedtrack eval --decisions: " + in.truth_points + ": missing");
  in.point_labels = runFile(run_dir, "point_labels.bin",
                            "written by `pedtrack run --out` with a segmenter, unless "
                            "--no-point-labels");
  in.detections = runFile(run_dir, "detections.csv",
                          "written by `pedtrack run --out` from the first detection on: the run "
                          "made none");
  in.tracks = runFile(run_dir, "tracks.csv", "written by `pedtrack run --out`");
  const DecisionReport r = eval::evaluateDecisions(in, o);
  std::cout << (as_json ? json(r, o, run_dir, in.truth_points)
                        : text(r, o, run_dir, in.truth_points));
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
