// `pedtrack eval --truth LABELS --calib CALIB --tracks RESULTS`: KITTI's 3D tracking evaluation
// (AB3DMOT's rules, eval/kitti_mot.h) of kitti_tracks.txt files against KITTI tracking labels,
// one sequence or every sequence of a folder, each on its own and pooled.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/eval/kitti_mot.h"
#include "pedtrack/outputs.h"

namespace pedtrack::cli {
namespace {
namespace fs = std::filesystem;

struct KittiMotArgs {
  std::string truth, calib, tracks, object_class = "pedestrian";
  double iou = 0.25, distance = 0;
  bool json = false, score_drift = false;
};

// The results file of sequence `name` under `tracks`: a kitti_tracks.txt, a run's --out folder,
// or a folder of those (runs/NAME/kitti_tracks.txt) or of results files (NAME.txt, AB3DMOT's).
std::string resultsOf(const std::string& tracks, const std::string& name, bool single) {
  const fs::path t(tracks);
  if (fs::is_regular_file(t)) return tracks;
  if (single && fs::is_regular_file(t / "kitti_tracks.txt"))
    return (t / "kitti_tracks.txt").string();
  for (const fs::path& p : {t / name / "kitti_tracks.txt", t / (name + ".txt")})
    if (fs::is_regular_file(p)) return p.string();
  return "";
}

// Fills image boxes a results file left empty (x2 <= x1) from the 3D box, so KITTI's 25 px rule
// still applies to them.
void projectMissingBoxes(std::vector<eval::KittiTrackRow>& rows, const std::string& calib) {
  if (calib.empty()) return;
  const eval::KittiCalib c = eval::readKittiCalib(calib);
  for (auto& r : rows) {
    if (r.x2 > r.x1 && r.y2 > r.y1) continue;
    std::array<double, 4> xyxy{};
    if (kittiImageBox(c, r.box, xyxy))
      r.x1 = xyxy[0], r.y1 = xyxy[1], r.x2 = xyxy[2], r.y2 = xyxy[3];
  }
}

std::string num(double v, int digits = 4) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream o;
  o.precision(digits);
  o << std::fixed << v;
  return o.str();
}

std::string jsonOf(const eval::KittiMotResult& r) {
  const auto& b = r.best;
  std::ostringstream o;
  o << "{\"samota\": " << num(r.samota) << ", \"amota\": " << num(r.amota)
    << ", \"amotp\": " << num(r.amotp) << ", \"mota\": " << num(b.mota())
    << ", \"motp\": " << num(b.motp()) << ", \"id_switches\": " << b.ids
    << ", \"fragmentations\": " << b.frag << ", \"false_positives\": " << b.fp
    << ", \"misses\": " << b.fn << ", \"true_positives\": " << b.tp << ", \"truths\": " << b.n_gt
    << ", \"recall\": " << num(b.recall()) << ", \"precision\": " << num(b.precision())
    << ", \"trajectories\": " << b.trajectories << ", \"mostly_tracked\": " << b.mostly_tracked
    << ", \"mostly_lost\": " << b.mostly_lost << ", \"score_threshold\": " << num(r.threshold)
    << ", \"recall_levels\": " << r.levels << ", \"hota\": " << num(r.hota.hota())
    << ", \"deta\": " << num(r.hota.detA()) << ", \"assa\": " << num(r.hota.assA())
    << ", \"loca\": " << num(r.hota.locA()) << "}";
  return o.str();
}

std::string pct(double v) {
  return std::isfinite(v) ? num(100 * v, 2) : "-";
}

std::string row(const std::string& name, const eval::KittiMotResult& r) {
  const auto& b = r.best;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-8s %7s %7s %7s %7s %5ld %5ld %6ld %6ld %6ld %7s %6s\n",
                name.c_str(), pct(r.samota).c_str(), pct(r.amota).c_str(), pct(b.mota()).c_str(),
                pct(b.motp()).c_str(), b.ids, b.frag, b.fp, b.fn, b.n_gt, pct(b.recall()).c_str(),
                pct(r.hota.hota()).c_str());
  return buf;
}

}  // namespace

int evalKittiMotCommand(const std::vector<std::string>& args) {
  KittiMotArgs a;
  po::options_description opts("options");
  opts.add_options()("truth", po::value(&a.truth)->required(),
                     "KITTI tracking labels: one sequence's SSSS.txt, or the label_02 folder")(
      "calib", po::value(&a.calib),
      "the sequence's calibration SSSS.txt, or the calib folder: image boxes a results file "
      "leaves empty are projected from the 3D boxes through P2")(
      "tracks", po::value(&a.tracks)->required(),
      "results in KITTI's format: a kitti_tracks.txt, a run's --out folder, or a folder of runs "
      "(runs/SSSS/kitti_tracks.txt) or of SSSS.txt files")(
      "class", po::value(&a.object_class)->default_value("pedestrian"),
      "pedestrian (Person_sitting ignored) or car (Van ignored)")(
      "iou", po::value(&a.iou)->default_value(0.25), "3D IoU a match needs")(
      "distance", po::value(&a.distance),
      "m: match by the boxes' bottom centres within this distance in bird's-eye view instead of "
      "IoU (MOTP is then the mean distance, m)")(
      "score-drift", po::bool_switch(&a.score_drift),
      "reproduce AB3DMOT's evaluate.py exactly: it re-averages the track scores it overwrote in "
      "every pass, and a track can drop below the threshold its own mean set")(
      "json", po::bool_switch(&a.json), "print one JSON object");
  po::variables_map vm;
  if (!parseOptions("eval",
                    "--truth LABELS.txt|LABEL_DIR [--calib CALIB.txt|CALIB_DIR] --tracks "
                    "kitti_tracks.txt|RUNS_DIR [--iou 0.25 | --distance D] [--json]",
                    opts, {}, args, vm, "eval --calib"))
    return exit_code::kOk;
  if (!(a.iou > 0 && a.iou <= 1)) throw ConfigError("pedtrack eval: --iou must lie in (0, 1]");
  if (vm.count("distance") && !vm["iou"].defaulted())
    throw ConfigError(
        "pedtrack eval: --iou and --distance: give one (matching by IoU or by distance)");
  if (vm.count("distance") && !(a.distance > 0))
    throw ConfigError("pedtrack eval: --distance must be a positive number of metres");
  if (a.object_class != "pedestrian" && a.object_class != "car")
    throw ConfigError("pedtrack eval: --class '" + a.object_class + "': pedestrian or car");
  for (const auto& [what, p] : {std::pair{"--truth", a.truth}, {"--tracks", a.tracks}})
    if (!fs::exists(p))
      throw ConfigError("pedtrack eval: " + std::string(what) + " " + p +
                        ": no such file or folder");
  if (!a.calib.empty() && !fs::exists(a.calib))
    throw ConfigError("pedtrack eval: --calib " + a.calib + ": no such file or folder");

  // The sequences: the one label file, or every label file that has results.
  std::vector<std::pair<std::string, std::string>> labels;  // name, path
  const bool single = fs::is_regular_file(a.truth);
  if (!single && fs::is_regular_file(a.tracks))
    throw ConfigError("pedtrack eval: --tracks " + a.tracks +
                      " is one sequence's results: give its label file as --truth, or a folder "
                      "of runs for the label folder");
  if (!single && !a.calib.empty() && !fs::is_directory(a.calib))
    throw ConfigError("pedtrack eval: --calib " + a.calib +
                      " is one file: a label folder needs the calib folder");
  if (single) {
    labels.push_back({fs::path(a.truth).stem().string(), a.truth});
  } else {
    for (const auto& e : fs::directory_iterator(a.truth))
      if (e.path().extension() == ".txt")
        labels.push_back({e.path().stem().string(), e.path().string()});
    std::sort(labels.begin(), labels.end());
  }
  eval::KittiMotOptions o;
  o.object_class = a.object_class;
  o.min_iou = a.iou;
  o.max_distance = a.distance;
  o.score_drift = a.score_drift;
  std::vector<eval::KittiSequence> seqs;
  std::vector<std::string> without, names;
  for (const auto& [name, path] : labels) {
    const std::string results = resultsOf(a.tracks, name, single);
    if (results.empty()) {
      without.push_back(name);
      continue;
    }
    eval::KittiSequence s;
    s.name = results;
    s.truth = eval::readKittiTrackFile(path);
    s.tracks = eval::readKittiTrackFile(results);
    const std::string calib = a.calib.empty() ? ""
                              : fs::is_directory(a.calib)
                                  ? (fs::path(a.calib) / (name + ".txt")).string()
                                  : a.calib;
    if (!calib.empty() && !fs::is_regular_file(calib))
      throw ConfigError("pedtrack eval: --calib: no " + calib + " for sequence " + name);
    projectMissingBoxes(s.tracks, calib);
    seqs.push_back(std::move(s));
    names.push_back(name);
  }
  if (seqs.empty())
    throw ConfigError("pedtrack eval: --tracks " + a.tracks + ": no results for any sequence of " +
                      a.truth + " (looked for NAME/kitti_tracks.txt and NAME.txt)");
  // A run that failed must not vanish from the pooled figures unnoticed.
  if (!without.empty()) {
    std::string list;
    for (const auto& n : without) list += (list.empty() ? "" : " ") + n;
    std::cerr << "note: no results for " << without.size() << " of " << labels.size()
              << " labelled sequences, not scored: " << list << "\n";
  }
  std::vector<eval::KittiMotResult> per;
  for (const auto& s : seqs) per.push_back(eval::evaluateKittiMot({s}, o));
  const eval::KittiMotResult pooled = eval::evaluateKittiMot(seqs, o);
  if (a.json) {
    std::cout << "{\"class\": \"" << a.object_class << "\", \"match\": \""
              << (a.distance > 0 ? "distance" : "iou3d")
              << "\", \"threshold\": " << (a.distance > 0 ? a.distance : a.iou)
              << ", \"score_drift\": " << (a.score_drift ? "true" : "false")
              << ", \"sequences\": {";
    for (std::size_t i = 0; i < seqs.size(); ++i)
      std::cout << (i ? ", " : "") << "\"" << jsonEscape(names[i]) << "\": " << jsonOf(per[i]);
    std::cout << "}, \"pooled\": " << jsonOf(pooled) << "}\n";
    return exit_code::kOk;
  }
  std::cout << "KITTI tracking, " << a.object_class << ", "
            << (a.distance > 0 ? "bird's-eye centre distance <= " + num(a.distance, 2) + " m"
                               : "3D IoU >= " + num(a.iou, 2))
            << " (AB3DMOT's rules" << (a.score_drift ? ", with evaluate.py's score drift" : "")
            << "; MOTA, MOTP, IDS, FRAG, FP, FN at the score threshold of the best MOTA)\n"
            << "sequence  sAMOTA   AMOTA    MOTA    MOTP   IDS  FRAG     FP     FN  truths  recall "
               "  HOTA\n";
  for (std::size_t i = 0; i < seqs.size(); ++i) std::cout << row(names[i], per[i]);
  if (seqs.size() > 1) std::cout << row("pooled", pooled);
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
