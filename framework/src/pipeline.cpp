#include "pedtrack/pipeline.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "pedtrack/errors.h"
#include "pedtrack/fault_injection.h"
#include "pedtrack/frame_guard.h"
#include "pedtrack/frame_supply.h"
#include "pedtrack/point_labels.h"
#include "pedtrack/progress.h"
#include "pedtrack/rawlog_recorder.h"

namespace pedtrack {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::unique_ptr<Plugin> create(const PipelineConfig& cfg, const StageConfig& sc) {
  PluginContext ctx;
  ctx.params = sc.params;
  ctx.config = cfg.ini.get();
  ctx.section = sc.section;
  try {
    return sc.descriptor->create(ctx);
  } catch (const ConfigError& e) {
    // Plugins name the key; the section and file are added here once for all of them.
    const std::string what = e.what();
    if (what.rfind(cfg.file, 0) == 0) throw ConfigError(what);  // a framework-made copy
    throw ConfigError(cfg.file + ": [" + sc.section + "] " + what);
  } catch (const std::exception& e) {
    throw ConfigError(cfg.file + ": [" + sc.section + "] " + sc.descriptor->name + ": " + e.what());
  }
}

}  // namespace

Pipeline::Pipeline(const PipelineConfig& config) : config_(config) {
  for (std::size_t i = 0; i < config.stages.size(); ++i) {
    std::unique_ptr<Plugin> p = create(config, config.stages[i]);
    if (i == 0) {
      auto* s = dynamic_cast<Sensor*>(p.get());
      if (!s)
        throw ConfigError(config.file + ": [" + config.stages[i].section +
                          "] plugin: not a sensor");
      p.release();
      source_.reset(s);
      if (config.faults) {
        try {
          source_ = wrapWithFaults(std::move(source_), *config.faults);
        } catch (const ConfigError& e) {
          throw ConfigError(config.file + ": " + e.what());
        }
      }
    } else {
      auto* s = dynamic_cast<Stage*>(p.get());
      if (!s)
        throw ConfigError(config.file + ": [" + config.stages[i].section + "] plugin: not a stage");
      p.release();
      stages_.emplace_back(s);
    }
  }
}

Pipeline::~Pipeline() = default;

std::vector<Stage*> Pipeline::stages() const {
  std::vector<Stage*> out;
  for (const auto& s : stages_) out.push_back(s.get());
  return out;
}

RunSummary Pipeline::run(const RunOptions& opt) {
  RunSummary sum;
  sum.pipeline = config_.file;
  if (config_.stages[0].params.has("file")) sum.input = config_.stages[0].params.getString("file");
  for (const auto& sc : config_.stages) sum.stages.emplace_back(sc.section, sc.descriptor->name);

  std::unique_ptr<TracksCsvWriter> csv;
  std::unique_ptr<DetectionsCsvWriter> detections_csv;  // created on the first detection
  std::unique_ptr<ClustersCsvWriter> clusters_csv;      // created on the first cluster
  std::unique_ptr<LabelFileWriter> labels;
  // Plugins start first: one that rejects the output directory (exit 2) leaves nothing behind.
  const bool created = !opt.out_dir.empty() && std::filesystem::create_directories(opt.out_dir);
  try {
    source_->start(opt.out_dir);
    for (auto& s : stages_) s->start(opt.out_dir);
  } catch (const std::exception& e) {
    std::error_code ec;
    if (created && std::filesystem::is_empty(opt.out_dir, ec)) std::filesystem::remove(opt.out_dir);
    if (dynamic_cast<const ConfigError*>(&e)) throw ConfigError(e.what());
    throw DataError(e.what());
  }
  if (!opt.out_dir.empty()) {
    csv = std::make_unique<TracksCsvWriter>(opt.out_dir + "/tracks.csv");
    // Stale side outputs of an earlier run would be read as this run's.
    for (const char* f : {"/detections.csv", "/clusters.csv", "/point_labels.bin"})
      std::filesystem::remove(opt.out_dir + f);
    const bool segments = std::any_of(stages_.begin(), stages_.end(), [](const auto& s) {
      return dynamic_cast<const Segmenter*>(s.get()) != nullptr;
    });
    if (segments && opt.point_labels)
      labels = std::make_unique<LabelFileWriter>(opt.out_dir + "/point_labels.bin", LabelKind::Run);
  }
  Progress progress("run", opt.progress);
  const auto start = Clock::now();
  std::size_t warnings = 0;
  std::unique_ptr<RawlogRecorder> recorder;
  if (!opt.record.empty()) recorder = std::make_unique<RawlogRecorder>(opt.record);
  FrameSupply supply(*source_, opt, recorder.get());
  sum.live = supply.live();
  Frame frame;
  Clock::time_point arrival;
  FrameGuard guard;
  if (source_->detectionsOnly()) guard.expectDetectionsOnly();
  std::vector<PlanarPoint> people;
  while (!stopRequested()) {
    const auto t0 = Clock::now();
    if (!supply.next(frame, arrival)) break;
    // The source's time per frame; for a live source, how long the stages waited for data.
    sum.stages[0].add(msSince(t0));
    if (!guard.admit(frame)) {  // counted; the stages never see it
      ++sum.frames_skipped;
      continue;
    }
    frame.people = people;  // as the tracker last knew them
    bool ok = true;
    for (std::size_t i = 0; i < stages_.size() && ok; ++i) {
      const auto ts = Clock::now();
      try {
        stages_[i]->process(frame);
      } catch (const std::exception& e) {
        // A bad frame costs that frame, never the run.
        ok = false;
        if (warnings++ < 10)
          std::cerr << "warning: frame " << frame.index << ": [" << config_.stages[i + 1].section
                    << "] " << e.what() << (warnings == 10 ? " (further warnings suppressed)" : "")
                    << "\n";
      }
      sum.stages[i + 1].add(msSince(ts));
    }
    people = frame.people;
    if (!ok) {
      ++sum.frames_failed;
      continue;
    }
    if (csv) csv->write(frame);
    if (csv && !detections_csv && !frame.detections.empty())
      detections_csv = std::make_unique<DetectionsCsvWriter>(opt.out_dir + "/detections.csv");
    if (detections_csv) detections_csv->write(frame);
    if (csv && !clusters_csv && !frame.clusters.empty())
      clusters_csv = std::make_unique<ClustersCsvWriter>(opt.out_dir + "/clusters.csv", frame);
    if (clusters_csv) clusters_csv->write(frame);
    if (csv) {
      try {  // the source's own results format (kitti_tracks.txt); what is written stays
        source_->results(frame);
      } catch (const std::exception& e) {
        sum.status = "error";
        sum.error = e.what();
        break;
      }
    }
    if (labels) labels->write(runLabels(frame));
    if (csv && supply.live()) csv->flush();  // a live frame's latency ends with its tracks on disk
    sum.latency.add(msSince(arrival));
    ++sum.frames_processed;
    progress.update(supply.framesRead(), source_->progress());
  }
  supply.stop();  // joins a live source's thread: it checks stopRequested() between reads
  sum.frames_read = supply.framesRead();
  sum.input_warnings = guard.counts();
  if (csv) sum.nonfinite_track_rows = csv->nonfiniteRows();
  sum.frames_dropped = supply.dropped();
  if (!supply.error().empty()) {
    sum.status = "error";
    sum.error = supply.error();
  }
  if (recorder) {
    sum.frames_recorded = recorder->written();
    recorder->close();
  }
  if (stopRequested() && sum.status == "ok") sum.status = "interrupted";
  try {  // a plugin that cannot complete its side outputs fails the run, after the rest is out
    for (auto& s : stages_) s->finish();
    source_->finish();
    sum.stages[0].counters = source_->counters();
    for (std::size_t i = 0; i < stages_.size(); ++i)
      sum.stages[i + 1].counters = stages_[i]->counters();
  } catch (const std::exception& e) {
    sum.status = "error";
    sum.error = e.what();
  }
  sum.entries_skipped = source_->entriesSkipped();
  sum.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  progress.done(sum.frames_read);
  if (csv) csv->close();
  if (detections_csv) detections_csv->close();
  if (clusters_csv) clusters_csv->close();
  try {
    if (labels) labels->close();
  } catch (const std::exception& e) {
    sum.status = "error";
    sum.error = e.what();
  }
  if (!opt.out_dir.empty()) writeRunJson(opt.out_dir + "/run.json", sum);
  return sum;
}

}  // namespace pedtrack
