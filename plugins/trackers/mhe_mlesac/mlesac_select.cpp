#include "mhe_mlesac/mlesac_select.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "mhe_mlesac/mhe_screen.h"

namespace pedtrack::track::mhe {
namespace {

MheProblem baseProblem(const MlesacInput& in) {
  MheProblem pb;
  pb.frames = in.frames;
  pb.prior = in.prior;
  pb.arrival_mean = in.arrival_mean;
  pb.arrival_info = in.arrival_info;
  pb.sample.assign(in.frames->size(), {});
  return pb;
}

// Line 4 of Algorithm 1: |Ψ| distinct points drawn uniformly from the whole horizon (all of them
// when there are no more), as per-frame index lists, sorted (equal samples compare equal).
std::vector<std::vector<int>> drawSample(const std::vector<int>& offsets, int total, int size,
                                         std::mt19937& rng) {
  std::vector<int> pick(static_cast<std::size_t>(total));
  std::iota(pick.begin(), pick.end(), 0);
  if (size < total) {
    for (int i = 0; i < size; ++i) {  // partial Fisher–Yates
      std::uniform_int_distribution<int> u(i, total - 1);
      std::swap(pick[i], pick[u(rng)]);
    }
    pick.resize(std::size_t(size));
    std::sort(pick.begin(), pick.end());
  }
  std::vector<std::vector<int>> sample(offsets.size() - 1);
  std::size_t k = 0;
  for (int g : pick) {
    while (g >= offsets[k + 1]) ++k;
    sample[k].push_back(g - offsets[k]);
  }
  return sample;
}

// The winner's inliers (|s| < d_th over the whole horizon) as the sample of one more solve: all
// of them, or `refit_points` of them drawn at random (the solve's cost grows with its sample,
// its answer barely once the sample is several times |Ψ|).
void refit(const MheProblem& winner, const MheParams& params, const MlesacOptions& options,
           MheSolver& solver, MlesacResult& out, std::mt19937& rng) {
  MheProblem pb = winner;
  std::vector<std::pair<int, int>> inliers;  // (frame, point)
  for (int k = 0; k < pb.size(); ++k) {
    pb.sample[k].clear();
    const auto& pts = (*pb.frames)[k].points;
    const Deviation s(out.xs[k]);
    for (int i = 0; i < int(pts.size()); ++i)
      if (std::abs(s(pts[i])) < params.d_th) inliers.emplace_back(k, i);
  }
  const int count = std::min(int(inliers.size()), options.refit_points);
  for (int i = 0; i < count; ++i) {  // partial Fisher–Yates (a no-op when all are kept)
    std::uniform_int_distribution<int> u(i, int(inliers.size()) - 1);
    std::swap(inliers[std::size_t(i)], inliers[std::size_t(u(rng))]);
  }
  inliers.resize(std::size_t(count));
  std::sort(inliers.begin(), inliers.end());
  for (const auto& [k, i] : inliers) pb.sample[std::size_t(k)].push_back(i);
  if (count < 3) return;
  pb.data_weight = 1 / (params.r * count);
  const SolveResult r = solver.solve(pb, out.xs);
  ++out.solved;
  if (!r.usable()) {
    ++out.failed;
    return;
  }
  out.xs = r.xs;
  out.score = selectionCost(pb, params, options.selection, r.xs);
}

}  // namespace

MlesacResult mheMlesac(const MlesacInput& in, const MheParams& params, const MlesacOptions& options,
                       MheSolver& solver, std::mt19937& rng) {
  MlesacResult out;
  const std::vector<HorizonFrame>& frames = *in.frames;
  std::vector<int> offsets{0};
  for (const HorizonFrame& f : frames) offsets.push_back(offsets.back() + int(f.points.size()));
  const int total = offsets.back();
  if (total == 0) return out;

  // Lines 2–5: the candidates' problems (a sample drawn twice is one candidate).
  const MheProblem base = baseProblem(in);
  const int size = options.sampling ? std::min(params.subset, total) : total;
  const int draws = options.sampling && size < total ? params.candidates : 1;
  std::vector<MheProblem> problems;
  std::set<std::vector<std::vector<int>>> seen;
  for (int j = 0; j < draws; ++j) {
    auto sample = drawSample(offsets, total, size, rng);
    if (!seen.insert(sample).second) continue;
    MheProblem pb = base;
    pb.sample = std::move(sample);
    pb.data_weight = 1 / (params.r * size);
    problems.push_back(std::move(pb));
  }
  out.candidates = int(problems.size());

  // The screen: every candidate minimised approximately and scored (line 6).
  std::vector<std::vector<State>> starts(problems.size(), in.prior);
  std::vector<std::size_t> order(problems.size());
  std::iota(order.begin(), order.end(), 0);
  const bool screen = options.finalists > 0 && int(problems.size()) > options.finalists;
  if (screen) {
    const MheScreen screener(base, params);
    std::vector<double> score(problems.size());
    auto rank = [&](std::size_t keep) {
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return score[a] < score[b]; });
      order.resize(std::min(order.size(), keep));
    };
    // Half the steps for every candidate, the rest for the survivors only.
    const int first = std::max(1, options.screen_iterations / 2);
    for (std::size_t j = 0; j < problems.size(); ++j) {
      starts[j] = screener.minimise(problems[j], first);
      score[j] = selectionCost(problems[j], params, options.selection, starts[j]).cost;
    }
    rank(std::size_t(std::max(options.survivors, options.finalists)));
    if (options.screen_iterations > first)
      for (std::size_t j : order) {
        starts[j] = screener.minimise(problems[j], options.screen_iterations - first, &starts[j]);
        score[j] = selectionCost(problems[j], params, options.selection, starts[j]).cost;
      }
    rank(order.size());  // the survivors by their final screen score
  }

  // Lines 5–15 for the finalists: Ipopt's solution, the lowest selection cost wins. A candidate
  // Ipopt fails on is replaced by the next-ranked one, so `finalists` solutions compete.
  const int wanted = screen ? options.finalists : int(order.size());
  int usable = 0;
  std::size_t winner = 0;
  for (std::size_t j : order) {
    if (usable == wanted) break;
    const SolveResult r = solver.solve(problems[j], starts[j]);
    ++out.solved;
    if (!r.usable()) {
      ++out.failed;
      continue;
    }
    ++usable;
    const Selected s = selectionCost(problems[j], params, options.selection, r.xs);
    if (!out.ok || s.cost < out.score.cost) {
      out.ok = true;
      out.xs = r.xs;
      out.score = s;
      winner = j;
    }
  }
  if (out.ok && options.refit && options.sampling)
    refit(problems[winner], params, options, solver, out, rng);
  return out;
}

}  // namespace pedtrack::track::mhe
