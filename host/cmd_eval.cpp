// `pedtrack eval`: tracks against truth (CLEAR MOT, errors, IDF1, HOTA, NEES/NIS; Monte Carlo
// runs pooled), or detections against truth points (precision/recall), the truth being the
// simulator's truth.csv or, with ROS bag support, a bag's labelled leg positions.
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <optional>

#include "commands.h"
#include "eval_range_bands.h"
#include "eval_report.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/eval/detection_pr.h"
#include "pedtrack/eval/evaluate.h"
#include "pedtrack/eval/segmentation.h"
#include "pedtrack/outputs.h"
#include "pedtrack/text.h"
#ifdef PEDTRACK_WITH_ROSBAG
#include "eval_bag.h"
#endif

namespace pedtrack::cli {
namespace {

constexpr double kTimeTolerance = 1e-4;  // s: two stamps this close are one frame

struct EvalArgs {
  std::vector<std::string> truth, tracks;
  std::string detections, frame = "fixed", topic, labels_topic, truth_points, labels;
  std::string range_bins, model_names, shape_plot, shape_bounds;
  double threshold = 0, hota_distance = 0, range_bin = 1, isolation = 0.5;
  long min_points = 10, fragment = 3;
  long min_visible = 1, following = 0;
  int nis_dof = 2;
  bool has_following = false, legs = false, json = false;
  std::string angles;       // MIN,MAX: bearing window in degrees (laser frame), bags only
  bool people_bag = false;  // --truth is a leg_tracker benchmark bag (annotated people)
};

bool isBag(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".bag") == 0;
}

void check(bool ok, const std::string& message) {
  if (!ok) throw ConfigError("pedtrack eval: " + message + " (see `pedtrack eval --help`)");
}

/// --shape-bounds amin,amax,bmin,bmax; not given when `text` is empty.
ShapeBounds shapeBounds(const std::string& text) {
  ShapeBounds b;
  if (text.empty()) return b;
  const std::vector<std::string> v = splitList(text);
  check(v.size() == 4, "--shape-bounds: expected amin,amax,bmin,bmax (4 numbers in m)");
  double x[4];
  for (int i = 0; i < 4; ++i) {
    char* end = nullptr;
    x[i] = std::strtod(v[i].c_str(), &end);
    check(end != v[i].c_str() && *end == '\0' && std::isfinite(x[i]),
          "--shape-bounds: '" + v[i] + "' is not a number (expected amin,amax,bmin,bmax in m)");
  }
  check(x[0] <= x[1] && x[2] <= x[3], "--shape-bounds: expected amin <= amax and bmin <= bmax");
  return {true, x[0], x[1], x[2], x[3]};
}

void validate(const EvalArgs& a, const po::variables_map& vm) {
  if (!a.truth_points.empty() || !a.labels.empty()) {
    check(!a.truth_points.empty() && !a.labels.empty(),
          "segmentation needs both --truth-points and --labels");
    check(a.truth.empty() && a.tracks.empty() && a.detections.empty(),
          "--truth-points/--labels score segmentation; --truth, --tracks and --detections do not "
          "go with them");
    check(a.min_points >= 1, "--min-points: must be >= 1");
    check(a.fragment >= 1, "--fragment: must be >= 1");
    check(a.isolation >= 0 && a.isolation <= kClearanceCap,
          "--isolation: must be within [0, " + std::to_string(int(kClearanceCap)) + "] m");
    return;
  }
  check(!a.truth.empty(), "--truth is required");
  check(a.tracks.empty() != a.detections.empty(), "give either --tracks or --detections");
  check(a.frame == "fixed" || a.frame == "sensor",
        "--frame: '" + a.frame + "' is not one of fixed, sensor");
  check(a.threshold > 0, "--threshold: must be > 0 m");
  check(a.min_visible >= 0, "--min-visible: must be >= 0");
  if (!a.tracks.empty()) {
    check(a.truth.size() == 1 || a.truth.size() == a.tracks.size(),
          "give one --truth, or one per --tracks (Monte Carlo runs in pairs); got " +
              std::to_string(a.truth.size()) + " and " + std::to_string(a.tracks.size()));
    const bool bag = std::any_of(a.truth.begin(), a.truth.end(), isBag);
    check(!bag || std::all_of(a.truth.begin(), a.truth.end(), isBag),
          "--truth: give bags only, or truth.csv files only");
    check(!bag || a.people_bag || (a.truth.size() == 1 && a.tracks.size() == 1),
          "--truth " + a.truth[0] + ": a bag of labelled legs scores one --tracks");
    check(!bag || a.truth.size() == a.tracks.size(),
          "bags are pooled in pairs: one --truth BAG per --tracks");
    check(!bag || vm["frame"].defaulted() || a.frame == "sensor",
          "--frame fixed: a bag's labels are in the laser frame (sensor_x, sensor_y)");
    check(!bag || (a.range_bins.empty() && a.shape_plot.empty()),
          "--range-bins and --shape-plot need a truth.csv, not a bag");
    check(!bag || a.people_bag || !a.has_following,
          "--following needs a truth.csv or a bag of annotated people (leg_tracker/Person)");
    check(a.angles.empty() || a.people_bag, "--angles applies to a bag of annotated people");
    check(!vm.count("hota-distance") || a.hota_distance > 0, "--hota-distance: must be > 0 m");
    check(a.nis_dof >= 1, "--nis-dof: must be >= 1");
    check(!a.legs, "--legs applies to --detections only");
    check(a.model_names.empty() || !a.range_bins.empty(), "--model-names needs --range-bins");
    check(a.shape_bounds.empty() || !a.shape_plot.empty(), "--shape-bounds needs --shape-plot");
    if (!a.range_bins.empty()) parseRangeEdges(a.range_bins, "--range-bins");
    shapeBounds(a.shape_bounds);
  } else {
    for (const char* o : {"range-bins", "model-names", "shape-plot", "shape-bounds"})
      check(!vm.count(o), "--" + std::string(o) + " applies to --tracks only");
    check(a.truth.size() == 1, "--detections takes one --truth");
    check(a.range_bin > 0, "--range-bin: must be > 0 m");
    check(!a.has_following, "--following applies to --tracks only");
    check(!a.legs || a.frame == "fixed",
          "--legs: truth.csv has leg positions in the fixed frame only");
    check(!isBag(a.truth[0]) || vm["frame"].defaulted() || a.frame == "sensor",
          "--frame fixed: a bag's leg labels are in the laser frame (sensor_x, sensor_y)");
  }
}

int evalTracking(const EvalArgs& a) {
  eval::TrackingOptions opt;
  opt.threshold = a.threshold;
  if (a.has_following) opt.following = a.following;
  opt.hota_distance = a.hota_distance > 0 ? a.hota_distance : a.threshold;
  opt.nis_dof = a.nis_dof;
  const auto frame = a.frame == "sensor" ? eval::CoordFrame::Sensor : eval::CoordFrame::Fixed;
  // Every file is read (and rejected) before any output.
  std::vector<ObjectTable> truths, tracks;
  for (const auto& p : a.truth) truths.push_back(readObjectTable(p));
  for (const auto& p : a.tracks) tracks.push_back(readObjectTable(p));
  std::vector<std::vector<eval::EvalFrame>> runs;
  for (std::size_t r = 0; r < tracks.size(); ++r) {
    const ObjectTable& truth = truths[truths.size() == 1 ? 0 : r];
    runs.push_back(eval::alignFrames(
        eval::objectsByTime(truth, frame, a.min_visible, kTimeTolerance),
        eval::objectsByTime(tracks[r], frame, 0, kTimeTolerance), kTimeTolerance));
  }
  const eval::TrackingReport rep = eval::evaluateTracking(runs, opt);
  EvalSetup s;
  s.threshold = a.threshold;
  s.frame = a.frame;
  s.min_visible = a.min_visible;
  s.following = opt.following;
  s.hota_distance = opt.hota_distance;
  if (a.range_bins.empty() && a.shape_plot.empty()) {
    std::cout << (a.json ? trackingJson(rep, s) : trackingText(rep, s));
    return exit_code::kOk;
  }
  // The matches of every run again, for the bands and the shape plot.
  std::vector<eval::MatchedPair> pairs;
  eval::ClearMotOptions co;
  co.threshold = opt.threshold;
  co.following = opt.following;
  for (const auto& frames : runs) {
    const auto cm = eval::clearMot(frames, co);
    pairs.insert(pairs.end(), cm.pairs.begin(), cm.pairs.end());
  }
  std::optional<eval::RangeBandReport> bands;
  const std::vector<std::string> names = splitList(a.model_names);
  if (!a.range_bins.empty()) {
    ModelProbs probs;
    for (const auto& t : tracks) probs.add(t);
    bands = eval::rangeBands(pairs, parseRangeEdges(a.range_bins, "--range-bins"),
                             [&](const ObjectRow& r) { return probs.of(r); });
  }
  std::size_t shape_rows = 0;
  if (!a.shape_plot.empty()) {
    shape_rows = drawShapePlot(a.shape_plot, pairs, shapeBounds(a.shape_bounds));
  }
  if (a.json) {
    std::vector<std::pair<std::string, std::string>> extra;
    if (bands) extra.emplace_back("range_bands", rangeBandsJson(*bands, names));
    std::cout << trackingJson(rep, s, extra);
  } else {
    std::cout << trackingText(rep, s);
    if (bands) std::cout << rangeBandsText(*bands, names);
    if (!a.shape_plot.empty())
      std::cout << "\nshape plot: " << a.shape_plot << " (" << shape_rows
                << " matched track rows with alpha, beta)\n";
  }
  return exit_code::kOk;
}

// Is --truth a leg_tracker benchmark bag (annotated people, leg_tracker/Person)? With
// --labels-topic left at its default, when the bag has one Person topic; given, when it is one.
bool isPeopleBag(const std::string& path, const std::string& labels_topic, bool defaulted) {
#ifdef PEDTRACK_WITH_ROSBAG
  const std::string people = bagPeopleTopic(path);
  return !people.empty() && (defaulted || labels_topic == people);
#else
  (void)path, (void)labels_topic, (void)defaulted;
  return false;
#endif
}

// --angles MIN,MAX in degrees; not given when `text` is empty.
std::optional<std::pair<double, double>> bearingWindow(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::vector<std::string> v = splitList(text);
  check(v.size() == 2, "--angles: expected MIN,MAX (degrees)");
  double x[2];
  for (int i = 0; i < 2; ++i) {
    char* end = nullptr;
    x[i] = std::strtod(v[i].c_str(), &end);
    check(end != v[i].c_str() && *end == '\0' && std::isfinite(x[i]),
          "--angles: '" + v[i] + "' is not a number (expected MIN,MAX in degrees)");
  }
  check(x[0] < x[1] && x[0] >= -180 && x[1] <= 180,
        "--angles: expected -180 <= MIN < MAX <= 180 (degrees)");
  return std::make_pair(x[0], x[1]);
}

// The objects whose bearing from the sensor (laser frame) lies in [min, max] degrees.
void keepBearings(std::vector<eval::TimedObjects>& frames, std::pair<double, double> window) {
  for (auto& f : frames)
    f.objects.erase(std::remove_if(f.objects.begin(), f.objects.end(),
                                   [&](const eval::Object& o) {
                                     const double b = std::atan2(o.y, o.x) * 180 / M_PI;
                                     return b < window.first || b > window.second;
                                   }),
                    f.objects.end());
}

// Tracks against leg_tracker benchmark bags (ICRA 2015), several pooled: its clear_mot.py rules
// on the people annotated after each scan (laser frame), and the tracks that follow no annotated
// person per scan (in a following bag only the followed person is annotated).
int evalTracksOnPeopleBag(const EvalArgs& a) {
#ifdef PEDTRACK_WITH_ROSBAG
  const auto window = bearingWindow(a.angles);
  std::vector<std::vector<eval::EvalFrame>> runs;
  std::size_t scans = 0, annotated_scans = 0;
  // Per bag: the time of its last scan with an annotation. After it nobody is annotated (a
  // recording whose annotation stops early), so no track there can be told target or not.
  std::vector<double> last_annotated;
  // The frames point into their track tables' rows: every table lives until the scoring is done.
  std::deque<ObjectTable> tables;
  for (std::size_t i = 0; i < a.truth.size(); ++i) {
    BagPeople people = readBagPeople(a.truth[i], a.topic, a.labels_topic);
    tables.push_back(readObjectTable(a.tracks[i]));
    auto tracks = eval::objectsByTime(tables.back(), eval::CoordFrame::Sensor, 0, kTimeTolerance);
    std::size_t span = 0;
    for (std::size_t k = 0; k < people.scans.size(); ++k)
      if (!people.scans[k].objects.empty()) span = k + 1;
    last_annotated.push_back(span ? people.scans[span - 1].t : -INFINITY);
    annotated_scans += span;
    if (window) {
      keepBearings(people.scans, *window);
      keepBearings(tracks, *window);
    }
    scans += people.scans.size();
    runs.push_back(eval::alignFrames(people.scans, tracks, kTimeTolerance));
  }
  eval::TrackingOptions opt;
  opt.threshold = a.threshold;
  if (a.has_following) opt.following = a.following;
  opt.hota_distance = a.hota_distance > 0 ? a.hota_distance : a.threshold;
  opt.nis_dof = a.nis_dof;
  const eval::TrackingReport rep = eval::evaluateTracking(runs, opt);
  // Every track row that matches no annotated person; and those up to each bag's last annotation.
  std::size_t non_target = 0, non_target_annotated = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto cm = eval::clearMot(runs[r], {a.threshold, std::nullopt});
    non_target += cm.counts.false_positives;
    for (std::size_t k = 0; k < runs[r].size(); ++k)
      if (runs[r][k].t <= last_annotated[r] + kTimeTolerance)
        non_target_annotated += cm.unmatched[k].size();
  }
  EvalSetup s;
  s.threshold = a.threshold;
  s.frame = "sensor";
  s.following = opt.following;
  s.hota_distance = opt.hota_distance;
  s.truth_source = "bag";
  const double per_scan = scans ? double(non_target) / double(scans) : NAN;
  const double per_annotated =
      annotated_scans ? double(non_target_annotated) / double(annotated_scans) : NAN;
  const auto number = [](double v) { return std::isfinite(v) ? mrpt::format("%.10g", v) : "null"; };
  if (a.json) {
    std::cout << trackingJson(
        rep, s,
        {{"scans", std::to_string(scans)},
         {"non_target_track_rows", std::to_string(non_target)},
         {"non_target_tracks_per_scan", number(per_scan)},
         {"annotated_scans", std::to_string(annotated_scans)},
         {"non_target_track_rows_annotated", std::to_string(non_target_annotated)},
         {"non_target_tracks_per_annotated_scan", number(per_annotated)},
         {"angles", a.angles.empty() ? "null" : "\"" + a.angles + "\""}});
  } else {
    std::cout << trackingText(rep, s);
    std::printf(
        "\nBenchmark bags: %zu, %zu scans%s; tracks on no annotated person: %zu rows, "
        "%.3f per scan; up to the last annotated scan (%zu scans): %zu rows, %.3f per scan\n",
        a.truth.size(), scans, a.angles.empty() ? "" : (", bearings " + a.angles).c_str(),
        non_target, per_scan, annotated_scans, non_target_annotated, per_annotated);
  }
  return exit_code::kOk;
#else
  (void)a;
  return exit_code::kBadInput;
#endif
}

// Tracks against a labelled bag's legs (eval/leg_coverage.h): leg_tracker's bags label legs,
// not people, so no CLEAR MOT; the share of labelled legs with a track near them, and the
// track rows near none.
int evalTracksOnBag(const EvalArgs& a) {
#ifdef PEDTRACK_WITH_ROSBAG
  if (a.people_bag) return evalTracksOnPeopleBag(a);
  const auto legs = readBagLabels(a.truth[0], a.topic, a.labels_topic).scans;
  const ObjectTable table = readObjectTable(a.tracks[0]);
  const auto tracks = eval::objectsByTime(table, eval::CoordFrame::Sensor, 0, kTimeTolerance);
  const eval::LegCoverage c =
      eval::legCoverage(eval::alignFrames(legs, tracks, kTimeTolerance), a.threshold);
  EvalSetup setup;
  setup.threshold = a.threshold;
  std::cout << (a.json ? legCoverageJson(c, setup) : legCoverageText(c, setup, a.truth[0]));
  return exit_code::kOk;
#else
  throw ConfigError("--truth " + a.truth[0] +
                    ": this pedtrack was built without ROS bag support (PEDTRACK_WITH_ROSBAG)");
#endif
}

int evalDetections(const EvalArgs& a) {
  EvalSetup s;
  s.threshold = a.threshold;
  s.frame = a.frame;
  s.min_visible = a.min_visible;
  s.legs = a.legs;
  std::vector<eval::TimedObjects> truth;
  if (isBag(a.truth[0])) {
#ifdef PEDTRACK_WITH_ROSBAG
    truth = readBagLabels(a.truth[0], a.topic, a.labels_topic).scans;
    s.truth_source = "bag";
    s.frame = "sensor";  // the labels are in the laser frame
    s.legs = true;
#else
    throw ConfigError("--truth " + a.truth[0] +
                      ": this pedtrack was built without ROS bag support (PEDTRACK_WITH_ROSBAG)");
#endif
  }
  const ObjectTable dets = readDetectionTable(a.detections);
  ObjectTable truth_table;
  if (s.truth_source == "csv") {
    truth_table = readObjectTable(a.truth[0]);
    truth = a.legs ? eval::legsByTime(truth_table, a.min_visible, kTimeTolerance)
                   : eval::objectsByTime(
                         truth_table,
                         a.frame == "sensor" ? eval::CoordFrame::Sensor : eval::CoordFrame::Fixed,
                         a.min_visible, kTimeTolerance);
  }
  const auto estimates = eval::objectsByTime(
      dets, s.frame == "sensor" ? eval::CoordFrame::Sensor : eval::CoordFrame::Fixed, 0,
      kTimeTolerance);
  if (s.truth_source == "bag") {
    // Detections at times of no scan usually mean the run read another topic or bag.
    std::size_t orphans = 0;
    for (const auto& e : estimates) {
      auto it = std::lower_bound(truth.begin(), truth.end(), e.t - kTimeTolerance,
                                 [](const eval::TimedObjects& t, double v) { return t.t < v; });
      orphans += it == truth.end() || it->t > e.t + kTimeTolerance;
    }
    if (orphans)
      std::cerr << "warning: " << orphans << " of " << estimates.size()
                << " detection frames match no scan of the bag (counted as false positives)\n";
  }
  const auto frames = eval::alignFrames(truth, estimates, kTimeTolerance);
  const eval::DetectionCounts c = eval::detectionPR(frames, a.threshold, a.range_bin);
  std::cout << (a.json ? detectionJson(c, s) : detectionText(c, s));
  return exit_code::kOk;
}

int evalSegmentation(const EvalArgs& a) {
  eval::SegmentationOptions o;
  o.min_points = a.min_points;
  o.fragment = a.fragment;
  o.isolation = a.isolation;
  const eval::SegmentationReport r = eval::evaluateSegmentation(a.truth_points, a.labels, o);
  std::cout << (a.json ? segmentationJson(r, o) : segmentationText(r, o));
  return exit_code::kOk;
}

}  // namespace

int evalCommand(const std::vector<std::string>& args) {
  for (const auto& s : args) {
    if (s == "--model" || s.rfind("--model=", 0) == 0) return evalClassifierCommand(args);
    if (s == "--decisions" || s.rfind("--decisions=", 0) == 0) return evalDecisionsCommand(args);
    if (s == "--kitti" || s.rfind("--kitti=", 0) == 0) return evalKittiCommand(args);
  }
  // KITTI tracking: a --calib, or --truth / --tracks naming KITTI files (.txt) or folders.
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    const auto value = [&](const char* key) -> std::string {
      const std::string k = key;
      if (s == k && i + 1 < args.size()) return args[i + 1];
      return s.rfind(k + "=", 0) == 0 ? s.substr(k.size() + 1) : "";
    };
    const auto kitti = [](const std::string& v) {
      return !v.empty() &&
             (std::filesystem::path(v).extension() == ".txt" || std::filesystem::is_directory(v));
    };
    if (s == "--calib" || s.rfind("--calib=", 0) == 0 || kitti(value("--truth")) ||
        kitti(value("--tracks")))
      return evalKittiMotCommand(args);
  }
  EvalArgs a;
  po::options_description opts("options");
  opts.add_options()("truth", po::value(&a.truth)->composing(),
                     "truth.csv (repeat once per --tracks for Monte Carlo runs), or a labelled ROS "
                     "bag (--detections; or --tracks: the share of its labelled legs with a track "
                     "within --threshold, default 0.35 m)")(
      "tracks", po::value(&a.tracks)->composing(), "tracks.csv to score (repeatable: runs)")(
      "detections", po::value(&a.detections), "detections.csv to score instead of tracks")(
      "threshold", po::value(&a.threshold),
      "largest match distance, m (default 0.75 for tracks, 0.1 for detections, 0.35 for tracks "
      "against a bag's legs)")(
      "following", po::value(&a.following)->implicit_value(0),
      "score only this truth id and ignore false positives (person following); without an id "
      "(or 0): every annotated truth is the followed person (a benchmark following bag)")(
      "angles", po::value(&a.angles),
      "MIN,MAX: a benchmark bag's bearing window in degrees (laser frame): truths and tracks "
      "outside it are dropped (the benchmark's moving-robot files: -80,12)")(
      "min-visible", po::value(&a.min_visible)->default_value(1),
      "truths with fewer visible points are unscored: they may absorb a match, never miss")(
      "hota-distance", po::value(&a.hota_distance),
      "HOTA similarity distance tau, m: sim = max(0, 1 - d/tau) (default: --threshold)")(
      "nis-dof", po::value(&a.nis_dof)->default_value(2), "degrees of freedom of the nis column")(
      "frame", po::value(&a.frame)->default_value("fixed"),
      "fixed: compare x,y; sensor: compare sensor_x,sensor_y")(
      "legs", po::bool_switch(&a.legs),
      "detections: take the truth points from truth.csv's leg columns")(
      "topic", po::value(&a.topic), "bag truth: the scan topic (default: the only LaserScan one)")(
      "labels-topic", po::value(&a.labels_topic)->default_value("/leg_cluster_positions"),
      "bag truth: the geometry_msgs/PoseArray topic of labelled legs, or the leg_tracker/Person "
      "topic of annotated people (a benchmark bag's only Person topic is taken by default); "
      "none: the bag has no people (every detection is a false positive)")(
      "range-bin", po::value(&a.range_bin)->default_value(1.0),
      "detections: width of the distance bins of recall by range, m")(
      "truth-points", po::value(&a.truth_points),
      "segmentation: truth_points.bin of a simulation (pedtrack sim / the sim source)")(
      "labels", po::value(&a.labels), "segmentation: point_labels.bin of a run on that simulation")(
      "min-points", po::value(&a.min_points)->default_value(10),
      "segmentation: people with fewer returns in a frame are not scored there")(
      "fragment", po::value(&a.fragment)->default_value(3),
      "segmentation: a cluster holds a person (or object) from this many of its points")(
      "isolation", po::value(&a.isolation)->default_value(0.5),
      "segmentation: people at least this clear of everything else (m) are the isolated subset")(
      "range-bins", po::value(&a.range_bins),
      "tracks: edges of distance bands from the sensor, m (e.g. 0,10,20,30: [0,10), ..., "
      "[30,inf)); per band the matches' errors, alpha, beta and model probabilities")(
      "model-names", po::value(&a.model_names),
      "tracks: names of the model_probs entries, in order (e.g. ellipse,box,cog; default "
      "prob_1, prob_2, ...)")("shape-plot", po::value(&a.shape_plot),
                              "tracks: PNG of the matched rows' alpha and beta against range")(
      "shape-bounds", po::value(&a.shape_bounds),
      "tracks: amin,amax,bmin,bmax (m), drawn dashed on --shape-plot")(
      "json", po::bool_switch(&a.json), "print one JSON object instead of the table");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!parseOptions(
          "eval",
          "--truth truth.csv|BAG.bag --tracks tracks.csv [options] | --truth truth.csv|BAG.bag "
          "--detections detections.csv|clusters.csv [options] | --truth-points "
          "truth_points.bin --labels point_labels.bin [options] | --model MODEL.yml --dataset "
          "D.ini [options] (classifiers: `pedtrack eval --model M --help`) | --decisions "
          "RUN_DIR [options] (`pedtrack eval --decisions D --help`) | --kitti DIR --detections "
          "detections.csv (`pedtrack eval --kitti D --help`) | --truth LABELS --calib CALIB "
          "--tracks "
          "kitti_tracks.txt|RUNS (KITTI tracking: `pedtrack eval --calib C --help`)",
          opts, pos, args, vm))
    return exit_code::kOk;
  a.has_following = vm.count("following") > 0;
  const bool bag_tracks = !a.tracks.empty() && std::any_of(a.truth.begin(), a.truth.end(), isBag);
  a.people_bag =
      bag_tracks && isPeopleBag(a.truth.front(), a.labels_topic, vm["labels-topic"].defaulted());
  if (a.people_bag && vm["labels-topic"].defaulted()) a.labels_topic.clear();
  // Against labelled legs a track (the person's centre) is within half a stride of each leg;
  // against annotated people, the benchmark's 0.75 m.
  if (!vm.count("threshold"))
    a.threshold = a.tracks.empty() ? 0.1 : bag_tracks && !a.people_bag ? 0.35 : 0.75;
  validate(a, vm);
  if (!a.truth_points.empty()) return evalSegmentation(a);
  const int code = bag_tracks         ? evalTracksOnBag(a)
                   : a.tracks.empty() ? evalDetections(a)
                                      : evalTracking(a);
  // A truth bag cut short was scored on what it holds (and warned about): the score is partial.
  return code == exit_code::kOk && !truthBagsCutShort().empty() ? exit_code::kFailure : code;
}

}  // namespace pedtrack::cli
