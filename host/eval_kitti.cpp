// `pedtrack eval --kitti DIR --detections D/detections.csv`: a run of the kitti source over the
// KITTI object benchmark's scans (DIR/velodyne) against their labels (DIR/label_2, DIR/calib):
// each labelled person found or missed, and every cluster called a person inside the camera's
// field of view (the only part KITTI labels) named by the labelled object it lies on.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "commands.h"
#include "options.h"
#include "pedtrack/errors.h"
#include "pedtrack/eval/kitti_labels.h"
#include "pedtrack/eval/object_table.h"
#include "pedtrack/outputs.h"
#include "report_format.h"

namespace pedtrack::cli {
namespace {

using eval::KittiFrameMatch;

struct KittiArgs {
  std::string dir, detections;
  double min_score = 0.5, margin = 0.3, scan_rate = 10;
  bool json = false;
};

std::string jsonQuoted(const std::string& s) {
  return "\"" + jsonEscape(s) + "\"";
}

std::string where(const eval::KittiCalled& c) {
  return mrpt::format("cluster %ld at (%.2f, %.2f) %.1f m, score %.2f", c.cluster, c.x, c.y,
                      std::hypot(c.x, c.y), c.score);
}

struct Totals {
  long people = 0, found = 0, called_in_view = 0, on_people = 0, on_nothing = 0;
  std::map<std::string, long> on_type;
};

Totals totals(const std::vector<KittiFrameMatch>& frames) {
  Totals t;
  for (const auto& m : frames) {
    for (std::size_t i = 0; i < m.objects.size(); ++i)
      if (m.objects[i].person()) t.people++, t.found += m.detected_by[i] >= 0;
    for (const auto& c : m.called) {
      if (!c.in_view) continue;
      ++t.called_in_view;
      if (c.object < 0)
        ++t.on_nothing;
      else if (m.objects[std::size_t(c.object)].person())
        ++t.on_people;
      else
        ++t.on_type[m.objects[std::size_t(c.object)].type];
    }
  }
  return t;
}

std::string text(const std::vector<KittiFrameMatch>& frames, const KittiArgs& a) {
  std::ostringstream o;
  o << "KITTI labels " << a.dir << " against " << a.detections
    << mrpt::format(" (a person: score >= %.2f; on an object: inside its box grown by %.2f m)\n",
                    a.min_score, a.margin);
  for (const auto& m : frames) {
    o << mrpt::format("frame %06ld\n", m.frame);
    for (std::size_t i = 0; i < m.objects.size(); ++i) {
      const auto& b = m.objects[i];
      if (!b.person()) continue;
      o << mrpt::format("  %s at (%.2f, %.2f) %.1f m: ", b.type.c_str(), b.x, b.y,
                        std::hypot(b.x, b.y))
        << (m.detected_by[i] >= 0 ? "found, " + where(m.called[std::size_t(m.detected_by[i])])
                                  : std::string("missed"))
        << "\n";
    }
    for (const auto& c : m.called)
      if (c.in_view)
        o << "  called a person in the camera's view: " << where(c) << ": "
          << (c.object < 0 ? std::string("no labelled object")
                           : m.objects[std::size_t(c.object)].type)
          << "\n";
  }
  const Totals t = totals(frames);
  o << mrpt::format(
      "labelled people %ld, found %ld; called persons in the camera's view %ld: on "
      "a person %ld, on no labelled object %ld",
      t.people, t.found, t.called_in_view, t.on_people, t.on_nothing);
  for (const auto& [type, n] : t.on_type) o << ", on a " << type << " " << n;
  o << "\n";
  return o.str();
}

std::string json(const std::vector<KittiFrameMatch>& frames, const KittiArgs& a) {
  const Totals t = totals(frames);
  std::ostringstream o;
  o << "{\"kitti\": " << jsonQuoted(a.dir) << ",\"detections\": " << jsonQuoted(a.detections)
    << ",\"min_score\": " << a.min_score << ",\"margin_m\": " << a.margin
    << ",\"people\": " << t.people << ",\"found\": " << t.found
    << ",\"called_in_view\": " << t.called_in_view << ",\"on_people\": " << t.on_people
    << ",\"on_nothing\": " << t.on_nothing << ",\"on_type\": {";
  bool first = true;
  for (const auto& [type, n] : t.on_type)
    o << (first ? "" : ",") << jsonQuoted(type) << ":" << n, first = false;
  o << "},\"frames\": [";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto& m = frames[f];
    o << (f ? "," : "") << "{\"frame\": " << m.frame << ",\"objects\": [";
    for (std::size_t i = 0; i < m.objects.size(); ++i) {
      const auto& b = m.objects[i];
      o << (i ? "," : "") << "{\"type\": " << jsonQuoted(b.type) << ",\"x\": " << b.x
        << ",\"y\": " << b.y << ",\"found_by\": "
        << (m.detected_by[i] >= 0 ? m.called[std::size_t(m.detected_by[i])].cluster : -1) << "}";
    }
    o << "],\"called\": [";
    for (std::size_t c = 0; c < m.called.size(); ++c) {
      const auto& k = m.called[c];
      o << (c ? "," : "") << "{\"cluster\": " << k.cluster << ",\"x\": " << k.x << ",\"y\": " << k.y
        << ",\"score\": " << k.score << ",\"in_view\": " << (k.in_view ? "true" : "false")
        << ",\"on\": "
        << (k.object < 0 ? std::string("null") : jsonQuoted(m.objects[std::size_t(k.object)].type))
        << "}";
    }
    o << "]}";
  }
  o << "]}\n";
  return o.str();
}

}  // namespace

int evalKittiCommand(const std::vector<std::string>& args) {
  KittiArgs a;
  po::options_description opts("options");
  opts.add_options()("kitti", po::value(&a.dir)->required(),
                     "a KITTI object benchmark folder: label_2/ and calib/ (the run read its "
                     "velodyne/ scans)")(
      "detections", po::value(&a.detections)->required(),
      "detections.csv of `pedtrack run --input DIR/velodyne` (a classifier with q_person = 0 "
      "writes every cluster)")("min-score", po::value(&a.min_score)->default_value(0.5),
                               "a cluster whose detection scores at least this is called a person")(
      "margin", po::value(&a.margin)->default_value(0.3),
      "m: a cluster is on a labelled object when inside its box grown by this")(
      "scan-rate", po::value(&a.scan_rate)->default_value(10),
      "Hz, the kitti source's scan_rate of the run: a row of time t is scan t x rate")(
      "json", po::bool_switch(&a.json), "print one JSON object");
  po::variables_map vm;
  if (!parseOptions("eval",
                    "--kitti DIR --detections D/detections.csv [--min-score 0.5] [--margin 0.3] "
                    "[--json]",
                    opts, {}, args, vm, "eval --kitti"))
    return exit_code::kOk;
  if (!std::isfinite(a.min_score) || !(a.margin >= 0) || !(a.scan_rate > 0))
    throw ConfigError(
        "pedtrack eval --kitti: --min-score, --margin >= 0 and --scan-rate > 0 "
        "must be numbers");
  // A folder or file missing is bad input (exit 2); a bad file inside is bad data.
  for (const char* sub : {"label_2", "calib"})
    if (!std::filesystem::is_directory(std::filesystem::path(a.dir) / sub))
      throw ConfigError("pedtrack eval --kitti: " + a.dir + ": no " + sub +
                        "/ folder (a KITTI object benchmark folder: label_2/, calib/)");
  if (!std::filesystem::is_regular_file(a.detections))
    throw ConfigError("pedtrack eval --kitti: --detections " + a.detections + ": no such file");
  const auto labels = eval::readKittiObjectDir(a.dir);
  const ObjectTable det = readDetectionTable(a.detections);
  std::map<long, std::vector<eval::KittiCalled>> called;
  for (const ObjectRow& r : det.rows) {
    if (!(r.score >= a.min_score)) continue;
    const long scan = std::lround(r.t * a.scan_rate);
    // The Velodyne's frame is the sensor frame (the fixed frame too without OXTS poses).
    const bool sensor = std::isfinite(r.sensor_x) && std::isfinite(r.sensor_y);
    called[scan].push_back(
        {r.cluster, sensor ? r.sensor_x : r.x, sensor ? r.sensor_y : r.y, r.score, false, -1});
  }
  std::vector<KittiFrameMatch> frames;
  for (const auto& [n, scan] : labels)
    frames.push_back(eval::matchKittiFrame(n, scan.objects, scan.calib, called[n], a.margin));
  std::cout << (a.json ? json(frames, a) : text(frames, a));
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
