// `pedtrack bench --pipeline P.ini`: each processing stage of a pipeline timed on its own. The
// frames are read and their point clouds decoded before timing (decoding is the source's and
// the cloud's cost, not a stage's), then every stage runs on a fresh copy of each cached frame,
// `repeat` times over, on this one thread. `--points N` resamples every cached cloud to N points
// first, to measure cost against cloud size; `--csv` writes the figures for `bench --suite`.
#include <mrpt/obs/CObservationPointCloud.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <opencv2/core.hpp>
#include <random>
#include <thread>

#include "commands.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/plugin_registry.h"
#include "pedtrack/stage_stats.h"

namespace pedtrack::cli {
namespace {

// The frame with its range observations replaced by one point cloud of exactly `n` points in
// the robot frame, drawn from its own cloud: evenly spaced points when n is smaller; when larger,
// every point repeated with up to 2 cm of jitter — a denser sensor seeing the same scene.
Frame resampled(const Frame& f, std::size_t n, std::mt19937& rng) {
  const auto& src = f.cloud();
  Frame g = f.sameTimeAndPoses();
  mrpt::Clock::time_point stamp{};
  for (const auto& obs : f.observations) {
    if (!isRangeObservation(*obs))
      g.observations.push_back(obs);
    else if (stamp == mrpt::Clock::time_point{})
      stamp = obs->timestamp;
  }
  auto map = mrpt::maps::CSimplePointsMap::Create();
  map->reserve(n);
  const std::size_t m = src.size();
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  for (std::size_t i = 0; m > 0 && i < n; ++i) {
    float x, y, z;
    src.getPoint(n <= m ? i * m / n : i % m, x, y, z);
    if (i >= m) x += jitter(rng), y += jitter(rng), z += jitter(rng);  // a repeated return
    map->insertPointFast(x, y, z);
  }
  map->mark_as_modified();
  auto pc = mrpt::obs::CObservationPointCloud::Create();
  pc->pointcloud = map;
  pc->sensorLabel = "RESAMPLED";
  pc->timestamp = stamp;
  g.observations.push_back(pc);
  return g;
}

}  // namespace

int benchStages(const StageBenchOptions& o) {
  // One core, as the figures claim: OpenCV would otherwise spread a classifier's predict() over
  // its thread pool (as in bench_model.cpp).
  cv::setNumThreads(1);
  PluginRegistry registry(PluginRegistry::defaultSearchPath(o.plugin_path));
  PipelineOverrides ov;
  ov.input = o.input;
  ov.topic = o.topic;
  ov.sets = o.sets;
  const PipelineConfig config = PipelineConfig::load(o.pipeline, ov, registry);
  Pipeline pipeline(config);
  const std::vector<Stage*> stages = pipeline.stages();
  if (stages.empty()) throw ConfigError(o.pipeline + ": [pipeline] stages: no stage to bench");

  std::vector<Frame> cache;
  std::size_t points = 0;
  std::mt19937 rng(1);
  Frame f;
  while (static_cast<long>(cache.size()) < o.frames) {
    f = Frame();
    f.index = cache.size();
    if (!pipeline.source().next(f)) break;
    if (o.points > 0) f = resampled(f, static_cast<std::size_t>(o.points), rng);
    points += f.cloud().size();  // decoded now, shared by every copy below
    cache.push_back(f);
  }
  if (cache.empty()) throw DataError(o.pipeline + ": the source produced no frame");

  std::vector<StageStats> stats;
  for (std::size_t i = 0; i < stages.size(); ++i)
    stats.emplace_back(config.stages[i + 1].section, config.stages[i + 1].descriptor->name);
  StageStats total("all stages", "");
  using Clock = std::chrono::steady_clock;
  std::size_t clusters = 0, tracks = 0, failed = 0;
  std::vector<PlanarPoint> people;  // as Pipeline::run carries them from frame to frame
  for (long r = 0; r < o.repeat; ++r)
    for (const Frame& cached : cache) {
      Frame frame = cached;
      frame.people = people;
      double sum = 0;
      bool ok = true;
      for (std::size_t i = 0; i < stages.size() && ok; ++i) {
        const auto t0 = Clock::now();
        try {
          stages[i]->process(frame);
        } catch (const std::exception& e) {  // as in a run: the frame is lost, not the bench
          ok = false;
          if (++failed == 1)
            std::fprintf(stderr, "warning: frame %zu: %s\n", frame.index, e.what());
        }
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        stats[i].add(ms);
        sum += ms;
      }
      people = frame.people;
      if (ok) total.add(sum);
      clusters += frame.clusters.size();
      tracks += frame.tracks.size();
    }
  const double passes = double(cache.size() * o.repeat);
  std::vector<const StageStats*> rows;
  for (const auto& x : stats) rows.push_back(&x);
  rows.push_back(&total);

  if (!o.csv.empty()) {
    std::ofstream csv(o.csv);
    csv << "stage,plugin,p50_ms,p99_ms,mean_ms,max_ms,frames,points,clusters,tracks,failed\n";
    for (const StageStats* s : rows)
      csv << s->name() << ',' << s->plugin() << ',' << s->percentile(50) << ',' << s->percentile(99)
          << ',' << s->mean() << ',' << s->max() << ',' << cache.size() << ','
          << double(points) / cache.size() << ',' << clusters / passes << ',' << tracks / passes
          << ',' << failed << '\n';
    if (!csv) throw ConfigError("--csv '" + o.csv + "': cannot write");
  }
  std::printf("build: %s, %u hardware threads, one used\n", PEDTRACK_BUILD_TYPE,
              std::thread::hardware_concurrency());
  std::printf(
      "pipeline %s: %zu frames (%.0f points each on average, decoded before timing), "
      "%ld pass%s; %.1f clusters and %.1f tracks per frame\n",
      o.pipeline.c_str(), cache.size(), double(points) / cache.size(), o.repeat,
      o.repeat == 1 ? "" : "es", clusters / passes, tracks / passes);
  if (failed) std::printf("%zu frames failed in a stage (not in the total)\n", failed);
  std::printf("%-16s %-14s %10s %10s %10s %10s\n", "stage", "plugin", "p50 ms", "p99 ms", "mean ms",
              "max ms");
  for (const StageStats* s : rows)
    std::printf("%-16s %-14s %10.4f %10.4f %10.4f %10.4f\n", s->name().c_str(), s->plugin().c_str(),
                s->percentile(50), s->percentile(99), s->mean(), s->max());
  return 0;
}

}  // namespace pedtrack::cli
