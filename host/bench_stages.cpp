// `pedtrack bench --pipeline P.ini`: each processing stage of a pipeline timed on its own. The
// frames are read and their point clouds decoded before timing (decoding is the source's and
// the cloud's cost, not a stage's), then every stage runs on a fresh copy of each cached frame,
// `repeat` times over, on this one thread.
#include <chrono>
#include <cstdio>
#include <opencv2/core.hpp>
#include <thread>

#include "commands.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/plugin_registry.h"
#include "pedtrack/stage_stats.h"

namespace pedtrack::cli {

int benchStages(const std::string& pipeline_file, const std::string& input,
                const std::string& topic, const std::vector<std::string>& sets, long frames,
                long repeat, const std::vector<std::string>& plugin_path) {
  // One core, as the figures claim: OpenCV would otherwise spread a classifier's predict() over
  // its thread pool (as in bench_model.cpp).
  cv::setNumThreads(1);
  PluginRegistry registry(PluginRegistry::defaultSearchPath(plugin_path));
  PipelineOverrides ov;
  ov.input = input;
  ov.topic = topic;
  ov.sets = sets;
  const PipelineConfig config = PipelineConfig::load(pipeline_file, ov, registry);
  Pipeline pipeline(config);
  const std::vector<Stage*> stages = pipeline.stages();
  if (stages.empty()) throw ConfigError(pipeline_file + ": [pipeline] stages: no stage to bench");

  std::vector<Frame> cache;
  std::size_t points = 0;
  Frame f;
  while (static_cast<long>(cache.size()) < frames) {
    f = Frame();
    f.index = cache.size();
    if (!pipeline.source().next(f)) break;
    points += f.cloud().size();  // decoded now, shared by every copy below
    cache.push_back(f);
  }
  if (cache.empty()) throw DataError(pipeline_file + ": the source produced no frame");

  std::vector<StageStats> stats;
  for (std::size_t i = 0; i < stages.size(); ++i)
    stats.emplace_back(config.stages[i + 1].section, config.stages[i + 1].descriptor->name);
  StageStats total("all stages", "");
  using Clock = std::chrono::steady_clock;
  std::size_t clusters = 0, failed = 0;
  for (long r = 0; r < repeat; ++r)
    for (const Frame& cached : cache) {
      Frame frame = cached;
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
      if (ok) total.add(sum);
      clusters += frame.clusters.size();
    }
  std::printf("build: %s, %u hardware threads, one used\n", PEDTRACK_BUILD_TYPE,
              std::thread::hardware_concurrency());
  std::printf(
      "pipeline %s: %zu frames (%.0f points each on average, decoded before timing), "
      "%ld pass%s; %.1f clusters per frame\n",
      pipeline_file.c_str(), cache.size(), double(points) / cache.size(), repeat,
      repeat == 1 ? "" : "es", double(clusters) / double(cache.size() * repeat));
  if (failed) std::printf("%zu frames failed in a stage (not in the total)\n", failed);
  std::printf("%-16s %-14s %10s %10s %10s %10s\n", "stage", "plugin", "p50 ms", "p99 ms", "mean ms",
              "max ms");
  for (const StageStats* s : [&] {
         std::vector<const StageStats*> v;
         for (const auto& x : stats) v.push_back(&x);
         v.push_back(&total);
         return v;
       }())
    std::printf("%-16s %-14s %10.4f %10.4f %10.4f %10.4f\n", s->name().c_str(), s->plugin().c_str(),
                s->percentile(50), s->percentile(99), s->mean(), s->max());
  return 0;
}

}  // namespace pedtrack::cli
