// `pedtrack bench --model M.yml --samples S.csv`: a classifier's own cost, the time to score one
// frame's clusters (--batch feature vectors, default 100) on one thread, over every batch of
// the samples file, --repeat times over.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <opencv2/core.hpp>

#include "commands.h"
#include "pedtrack/classify/model_file.h"
#include "pedtrack/errors.h"
#include "sample_csv.h"

namespace pedtrack::cli {

int benchModel(const std::string& model, const std::string& samples, long batch, long repeat) {
  if (samples.empty()) throw ConfigError("pedtrack bench --model: needs --samples FILE.csv");
  if (batch < 1 || repeat < 1)
    throw ConfigError("pedtrack bench: --batch and --repeat must be >= 1");
  cv::setNumThreads(1);  // one core, as a pipeline stage runs
  const auto scorer = classify::loadScorer(model);
  const classify::SampleSet s = readSamplesCsv(samples).select(scorer->info().features);
  if (s.size() == 0) throw ConfigError(samples + ": no samples");
  // Batches of `batch` vectors, cycling through the file so every batch is full.
  std::vector<double> rows(std::size_t(batch) * s.dims()), out;
  std::vector<double> ms;
  using Clock = std::chrono::steady_clock;
  const std::size_t batches = std::max<std::size_t>(1, s.size() / std::size_t(batch));
  for (long r = 0; r < repeat; ++r)
    for (std::size_t b = 0; b < batches; ++b) {
      for (long i = 0; i < batch; ++i) {
        const double* src = s.row((b * std::size_t(batch) + std::size_t(i)) % s.size());
        std::copy(src, src + s.dims(), rows.begin() + long(std::size_t(i) * s.dims()));
      }
      const auto t0 = Clock::now();
      scorer->score(rows.data(), std::size_t(batch), out);
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
  std::sort(ms.begin(), ms.end());
  double mean = 0;
  for (double v : ms) mean += v / double(ms.size());
  std::printf(
      "%s (%s, %zu features, trained on %zu + %zu samples): %ld clusters per call, %zu "
      "calls\n  mean %.4f ms, p50 %.4f ms, p99 %.4f ms, max %.4f ms per %ld clusters "
      "(%.2f us per cluster)\n",
      model.c_str(), scorer->info().kind.c_str(), s.dims(), scorer->info().persons,
      scorer->info().nonpersons, batch, ms.size(), mean, ms[ms.size() / 2],
      ms[std::min(ms.size() - 1, ms.size() * 99 / 100)], ms.back(), batch,
      1000 * mean / double(batch));
  return exit_code::kOk;
}

}  // namespace pedtrack::cli
