#include "train_dataset.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "pedtrack/errors.h"
#include "pedtrack/ini_text.h"
#include "pedtrack/param_table.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/plugin_registry.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/progress.h"
#include "pedtrack/sim/simulator.h"
#include "pedtrack/text.h"
#include "scan_thinning.h"
#ifdef PEDTRACK_WITH_ROSBAG
#include "eval_bag.h"
#endif

namespace pedtrack::cli {

namespace fs = std::filesystem;
using classify::Label;
using classify::SampleSet;
namespace {

// A [recording.NAME] section's keys (kind, region and part become DatasetInput's fields).
struct RecordingKeys {
  std::string file;
  DatasetInput::Kind kind = DatasetInput::Kind::Negative;
  std::string topic, labels_topic;
  std::string region;        // x0 y0 x1 y1, sensor frame (m); empty: none
  std::string part = "0 1";  // from to: the share of the frames used
};

const ParamTable<Dataset>& datasetTable() {
  using P = Dataset;
  static const auto t =
      ParamTable<P>()
          .text(&P::pipeline, "pipeline",
                "segmentation pipeline (its segmenter stages run; relative to this file)")
          .required()
          .text(&P::features, "features",
                "the features a model reads, space-separated (empty: all the segmenters give)")
          .integer(&P::frame_step, "frame_step", "", 1, 100000, "use every Nth frame of each input")
          .real(&P::min_range, "min_range", "m", 0, 1000, "clusters nearer the sensor are left out")
          .real(&P::max_range, "max_range", "m", 0, 1000,
                "clusters farther from the sensor are left out (0: no limit)")
          .real(&P::match_distance, "match_distance", "m", 0.001, 10,
                "a label marks the cluster whose centroid is nearest, within this")
          .text(&P::beam_steps, "beam_steps",
                "recordings: also learn from every Nth beam of each 2D scan, for each N listed "
                "(1: as recorded). A leg is then sampled as at N times its range, and its "
                "distance feature says so; training legs recorded near reach the far ones")
          .real(&P::purity, "purity", "", 0.5, 1,
                "sim: a cluster is a person when this share of its points is one person's, a "
                "non-person when at most 1 - this share is anyone's; else mixed (left out)");
  return t;
}

const ParamTable<DatasetInput>& simInputTable() {
  using P = DatasetInput;
  static const auto t =
      ParamTable<P>()
          .text(&P::file, "scenario", "scenario file (relative to this file)")
          .required()
          .integer(&P::seed, "seed", "", -1, 4294967295.0, "random seed (-1: the scenario's)");
  return t;
}

const ParamTable<RecordingKeys>& recordingTable() {
  using P = RecordingKeys;
  using K = DatasetInput::Kind;
  static const auto t =
      ParamTable<P>()
          .text(&P::file, "file", "rawlog or ROS1 bag (relative to this file)")
          .required()
          .choice(&P::kind, "kind", {{"negative", K::Negative}, {"positive", K::Positive}},
                  "negative: a recording without people, every cluster a non-person; positive: "
                  "clusters at labels or inside region are persons")
          .text(&P::topic, "topic", "scan topic of a bag (empty: its only scan topic)")
          .text(&P::labels_topic, "labels_topic",
                "positive bag: geometry_msgs/PoseArray topic of person (leg) positions")
          .text(&P::region, "region",
                "positive: x0 y0 x1 y1 box (sensor frame, m) where only people move")
          .text(&P::part, "part",
                "from to: the share of the recording's frames used (0 0.5: first half)");
  return t;
}

}  // namespace

const std::vector<std::pair<std::string, std::vector<ParamSpec>>>& datasetKeys() {
  static const std::vector<std::pair<std::string, std::vector<ParamSpec>>> keys = {
      {"dataset", datasetTable().specs()},
      {"sim.NAME", simInputTable().specs()},
      {"recording.NAME", recordingTable().specs()},
  };
  return keys;
}

namespace {

std::string anchored(const std::string& base_dir, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(base_dir) / path).lexically_normal().string();
}

}  // namespace

Dataset loadDataset(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": dataset file not found");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = preprocessIniText(ss.str(), path);
  mrpt::config::CConfigFileMemory ini(text);
  std::vector<std::string> sections;
  ini.getAllSections(sections);
  std::sort(sections.begin(), sections.end());
  const std::string dir = fs::path(path).parent_path().string();
  Dataset d;
  d.file = path;
  bool have_dataset = false;
  for (const auto& sec : sections) {
    std::string kind = sec;
    if (sec.rfind("sim.", 0) == 0 && sec.size() > 4) kind = "sim.NAME";
    if (sec.rfind("recording.", 0) == 0 && sec.size() > 10) kind = "recording.NAME";
    const auto& declared = datasetKeys();
    auto it = std::find_if(declared.begin(), declared.end(),
                           [&](const auto& k) { return k.first == kind; });
    if (it == declared.end())
      throw ConfigError(path + ": [" + sec +
                        "]: unknown section (dataset, sim.NAME, recording.NAME)");
    std::vector<std::pair<std::string, std::string>> kv;
    std::vector<std::string> keys;
    ini.getAllKeys(sec, keys);
    for (const auto& k : keys) kv.emplace_back(k, trim(ini.read_string(sec, k, "")));
    const ParamSet p = validateSection(it->second, kv, path, sec, "a [" + kind + "] section");
    if (kind == "dataset") {
      have_dataset = true;
      datasetTable().readInto(p, d);  // the keys' members only
      d.pipeline = anchored(dir, d.pipeline);
      d.steps.clear();
      const std::string where = datasetTable().where(p, &Dataset::beam_steps);
      for (double v : parseNumbers(d.beam_steps, 0, where)) {
        if (!(v >= 1 && v <= 20 && v == std::floor(v)))
          throw ConfigError(where + ": " + shortestNumber(v) + " is no whole step from 1 to 20");
        d.steps.push_back(int(v));
      }
      if (d.steps.empty()) throw ConfigError(where + ": no step (1: the scans as recorded)");
    } else if (kind == "sim.NAME") {
      DatasetInput in = simInputTable().read(p);
      in.kind = DatasetInput::Kind::Sim;
      in.name = sec;
      in.file = anchored(dir, in.file);
      d.inputs.push_back(in);
    } else {
      const RecordingKeys r = recordingTable().read(p);
      DatasetInput in;
      in.kind = r.kind;
      in.name = sec;
      in.file = anchored(dir, r.file);
      in.topic = r.topic;
      in.labels_topic = r.labels_topic;
      if (!r.region.empty())
        in.region = parseNumbers(r.region, 4, recordingTable().where(p, &RecordingKeys::region));
      const std::string part_where = recordingTable().where(p, &RecordingKeys::part);
      const auto part = parseNumbers(r.part, 2, part_where);
      in.part_from = part[0], in.part_to = part[1];
      if (!(0 <= in.part_from && in.part_from < in.part_to && in.part_to <= 1))
        throw ConfigError(part_where + ": need 0 <= from < to <= 1");
      if (in.kind == DatasetInput::Kind::Positive && in.labels_topic.empty() && in.region.empty())
        throw ConfigError(recordingTable().where(p, &RecordingKeys::kind) +
                          ": a positive recording needs labels_topic or region (which clusters "
                          "are people)");
      d.inputs.push_back(in);
    }
  }
  if (!have_dataset) throw ConfigError(path + ": [dataset] pipeline: missing required section");
  if (d.inputs.empty())
    throw ConfigError(path + ": no [sim.NAME] or [recording.NAME] section: nothing to learn from");
  return d;
}

// A recording's path as the model file records it: under $PEDTRACK_DATA it is written
// ${PEDTRACK_DATA}/..., so a model says where its data came from on any machine.
static std::string portable(const std::string& path) {
  const char* data = std::getenv("PEDTRACK_DATA");
  if (!data || !*data) return path;
  const std::string root = fs::absolute(data).lexically_normal().string();
  const std::string file = fs::absolute(path).lexically_normal().string();
  return file.rfind(root + "/", 0) == 0 ? "${PEDTRACK_DATA}" + file.substr(root.size()) : path;
}

std::string Dataset::describe() const {
  std::ostringstream o;
  o << "pipeline " << pipeline << "; frame_step " << frame_step;
  if (steps != std::vector<int>{1}) o << "; beam_steps " << beam_steps;
  if (min_range > 0 || max_range > 0) o << "; range " << min_range << "-" << max_range << " m";
  for (const auto& in : inputs) {
    o << "; " << in.name << ": ";
    if (in.kind == DatasetInput::Kind::Sim) {
      o << "sim " << in.file << (in.seed >= 0 ? " seed " + std::to_string(in.seed) : "");
      continue;
    }
    o << (in.kind == DatasetInput::Kind::Positive ? "positive " : "negative ") << portable(in.file);
    if (!in.topic.empty()) o << " " << in.topic;
    if (!in.labels_topic.empty()) o << " labels " << in.labels_topic;
    if (!in.region.empty())
      o << " region " << in.region[0] << " " << in.region[1] << " " << in.region[2] << " "
        << in.region[3];
    if (in.part_from > 0 || in.part_to < 1) o << " part " << in.part_from << "-" << in.part_to;
  }
  return o.str();
}

namespace {

// The source and segmenter stages of a pipeline. Its classifier stages (the model being trained
// may not exist yet) and tracker stages are dropped before the file is validated, so a detection
// pipeline trains the model it will use on exactly its own segmentation.
PipelineOverrides segmentationOnly(PipelineOverrides ov, const std::string& file,
                                   const PluginRegistry& registry) {
  std::ifstream in(file);
  if (!in) throw ConfigError(file + ": pipeline file not found");
  std::stringstream ss;
  ss << in.rdbuf();
  mrpt::config::CConfigFileMemory ini(preprocessIniText(ss.str(), file));
  std::string keep;
  for (const auto& st : splitList(ini.read_string("pipeline", "stages", ""))) {
    const std::string plugin = trim(ini.read_string(st, "plugin", ""));
    if (st == "source" || plugin.empty() || registry.get(plugin).category == Category::Segmenter)
      keep += (keep.empty() ? "" : " ") + st;
  }
  ov.sets.insert(ov.sets.begin(), "pipeline.stages=" + keep);
  return ov;
}

struct Segmentation {
  Segmentation(const Dataset& d, const PipelineOverrides& ov, const PluginRegistry& registry)
      : config(
            PipelineConfig::load(d.pipeline, segmentationOnly(ov, d.pipeline, registry), registry)),
        pipeline(config),
        segmenters(pipeline.stages()) {
    if (segmenters.empty())
      throw ConfigError(d.pipeline + ": [pipeline] stages: no segmenter to make clusters");
  }
  void process(Frame& f) {
    for (Stage* s : segmenters) s->process(f);
  }
  PipelineConfig config;
  Pipeline pipeline;
  std::vector<Stage*> segmenters;
};

// Adds the frame's clusters that `label` labels (-1: left out).
// range_scale: the frame's scans were thinned to look range_scale times farther (beam_steps).
template <class LabelFn>
void addClusters(const Dataset& d, const Frame& f, SampleSet& out, CollectStats& st, LabelFn label,
                 double range_scale) {
  if (f.clusters.empty()) return;
  if (!f.cluster_feature_names)
    throw ConfigError(d.pipeline + ": the segmenters give the clusters no features");
  if (out.features.empty()) out.features = *f.cluster_feature_names;
  if (*f.cluster_feature_names != out.features)
    throw ConfigError(d.pipeline + ": the segmenters' features changed between frames");
  const auto mount = f.sensorMount();
  const int distance = f.clusterFeatureIndex("distance");
  std::vector<double> x;
  for (std::size_t c = 0; c < f.clusters.size(); ++c) {
    const Cluster& cl = f.clusters[c];
    const double r = range_scale * std::hypot(cl.cx - mount.x(), cl.cy - mount.y());
    if (r < d.min_range || (d.max_range > 0 && r > d.max_range)) {
      ++st.out_of_range;
      continue;
    }
    if (cl.features.size() != out.dims()) continue;
    bool finite = true;
    for (double v : cl.features) finite = finite && std::isfinite(v);
    if (!finite) continue;
    const int l = label(c);
    if (l < 0) continue;
    x = cl.features;
    if (distance >= 0) x[std::size_t(distance)] *= range_scale;
    out.add(x.data(), Label(l));
  }
}

void collectSim(const Dataset& d, const DatasetInput& in, const PluginRegistry& reg, bool progress,
                SampleSet& out, CollectStats& st) {
  Segmentation seg(d, PipelineOverrides{}, reg);
  sim::Simulator sim(sim::loadScenario(in.file, in.seed));
  sim.setPointTruth(true);
  Progress prog(in.name, progress);
  sim::SimFrame sf;
  for (std::size_t k = 0; sim.next(sf); ++k) {
    if (k % std::size_t(d.frame_step)) continue;
    Frame f;
    f.index = sf.index;
    f.t = sf.t;
    f.robot_pose = sf.robot_odometry;
    f.observations.push_back(sf.observations.back());
    f.sensor_pose = sf.robot_odometry + sim.scenario().sensor.mount;
    seg.process(f);
    ++st.frames;
    std::map<std::int32_t, std::size_t> owners;
    addClusters(
        d, f, out, st,
        [&](std::size_t c) {
          const auto& idx = f.clusters[c].indices;
          owners.clear();
          std::size_t people = 0;
          for (std::uint32_t i : idx) {
            const std::int32_t o = i < sf.point_truth.size() ? sf.point_truth[i] : 0;
            if (o > 0) ++owners[o], ++people;
          }
          std::size_t top = 0;
          for (const auto& [o, n] : owners) top = std::max(top, n);
          const double n = double(std::max<std::size_t>(idx.size(), 1));
          if (top >= d.purity * n) return int(Label::Person);
          if (people <= (1 - d.purity) * n) return int(Label::NonPerson);
          ++st.mixed;
          return -1;
        },
        1.0);
    prog.update(k + 1, double(k + 1) / double(std::max<std::size_t>(sim.frameCount(), 1)));
  }
  prog.done(sim.frameCount());
}

void collectRecording(const Dataset& d, const DatasetInput& in, const PluginRegistry& reg,
                      bool progress, SampleSet& out, CollectStats& st) {
  PipelineOverrides ov;
  ov.input = in.file;
  ov.topic = in.topic;
  Segmentation seg(d, ov, reg);
  std::vector<eval::TimedObjects> labels;
  if (in.kind == DatasetInput::Kind::Positive && !in.labels_topic.empty()) {
#ifdef PEDTRACK_WITH_ROSBAG
    labels = readBagLabels(in.file, in.topic, in.labels_topic).scans;
#else
    throw ConfigError(in.file + ": labels_topic needs ROS bag support (PEDTRACK_WITH_ROSBAG)");
#endif
  }
  // Labels a segmented frame's clusters and adds them (step: its beams were thinned by this;
  // each frame's labels are counted at the first step listed, not once per step).
  auto learnFrom = [&](const Frame& f, int step) {
    const bool counts = step == d.steps.front();
    if (in.kind == DatasetInput::Kind::Negative) {
      addClusters(
          d, f, out, st, [](std::size_t) { return int(Label::NonPerson); }, step);
      return;
    }
    // Positives: cluster centroids in the sensor frame, against labels or the region.
    const auto mount = f.sensorMount();
    std::vector<std::pair<double, double>> at_sensor;
    for (const Cluster& c : f.clusters) {
      double x, y, z;
      mount.inverseComposePoint(c.cx, c.cy, c.cz, x, y, z);
      at_sensor.emplace_back(x, y);
    }
    std::vector<int> label(f.clusters.size(), -1);
    if (!in.region.empty()) {
      for (std::size_t c = 0; c < at_sensor.size(); ++c) {
        const auto [x, y] = at_sensor[c];
        if (x >= in.region[0] && x <= in.region[2] && y >= in.region[1] && y <= in.region[3])
          label[c] = int(Label::Person);
      }
    } else {
      auto it = std::lower_bound(labels.begin(), labels.end(), f.t - 1e-4,
                                 [](const eval::TimedObjects& t, double v) { return t.t < v; });
      if (it != labels.end() && it->t <= f.t + 1e-4) {
        // Greedy nearest pairs, each cluster marked by at most one label.
        for (const auto& o : it->objects) {
          if (counts) ++st.labels;
          int best = -1;
          double best_d = d.match_distance;
          for (std::size_t c = 0; c < at_sensor.size(); ++c) {
            const double dist = std::hypot(at_sensor[c].first - o.x, at_sensor[c].second - o.y);
            if (label[c] < 0 && dist <= best_d) best = int(c), best_d = dist;
          }
          if (best < 0) continue;
          label[std::size_t(best)] = int(Label::Person);
          if (counts) ++st.labels_matched;
        }
      }
    }
    addClusters(
        d, f, out, st, [&](std::size_t c) { return label[c]; }, step);
  };
  Progress prog(in.name, progress);
  Frame f;
  std::size_t k = 0;
  for (;; ++k) {
    f = Frame();
    f.index = k;
    if (!seg.pipeline.source().next(f)) break;
    const double at = seg.pipeline.source().progress();
    prog.update(k + 1, at);
    if (at >= 0 && at <= in.part_from) continue;
    if (at > in.part_to) break;
    if (k % std::size_t(d.frame_step)) continue;
    for (int step : d.steps) {
      // Step 1 is the frame as read; each other step starts its beams at another offset from
      // frame to frame.
      Frame thinned;
      if (step > 1)
        thinned = thinnedFrame(f, step, int(k / std::size_t(d.frame_step) % std::size_t(step)));
      Frame& g = step > 1 ? thinned : f;
      try {
        seg.process(g);
      } catch (const DataError& e) {
        std::cerr << "warning: " << in.name << " frame " << k << ": " << e.what() << "\n";
        continue;
      }
      if (step == d.steps.front()) ++st.frames;  // frames read, not once per step
      learnFrom(g, step);
    }
  }
  prog.done(k);
}

}  // namespace

SampleSet collectSamples(const Dataset& d, const std::vector<std::string>& plugin_path,
                         bool progress, CollectStats& st) {
  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  SampleSet all;
  for (const auto& in : d.inputs) {
    SampleSet s;
    const std::size_t before_mixed = st.mixed;
    if (in.kind == DatasetInput::Kind::Sim)
      collectSim(d, in, registry, progress, s, st);
    else
      collectRecording(d, in, registry, progress, s, st);
    if (progress)
      std::cerr << in.name << ": " << s.count(Label::Person) << " persons, "
                << s.count(Label::NonPerson) << " non-persons"
                << (st.mixed > before_mixed
                        ? ", " + std::to_string(st.mixed - before_mixed) + " mixed left out"
                        : std::string())
                << "\n";
    if (s.size()) all.append(s);
  }
  if (all.size() == 0) throw DataError(d.pipeline + ": the inputs produced no labelled cluster");
  return all;
}

}  // namespace pedtrack::cli
