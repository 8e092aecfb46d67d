#include "pedtrack/eval/hota.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "pedtrack/assignment.h"

namespace pedtrack::eval {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Mean over α of f(a).
template <class F>
double meanOverAlphas(F f) {
  double s = 0;
  for (int a = 0; a < HotaResult::kAlphas; ++a) s += f(a);
  return s / HotaResult::kAlphas;
}

struct FrameIds {
  std::vector<int> truth, track;  // dense ids of the frame's objects
  std::vector<double> sim;        // truth-major similarity matrix
};

}  // namespace

double HotaResult::detA(int a) const {
  return tp[a] / std::max(1.0, tp[a] + fn[a] + fp[a]);
}
double HotaResult::detRe(int a) const {
  return tp[a] / std::max(1.0, tp[a] + fn[a]);
}
double HotaResult::detPr(int a) const {
  return tp[a] / std::max(1.0, tp[a] + fp[a]);
}
double HotaResult::hota(int a) const {
  return std::sqrt(detA(a) * ass_a[a]);
}
double HotaResult::hota() const {
  return meanOverAlphas([&](int a) { return hota(a); });
}
double HotaResult::detA() const {
  return meanOverAlphas([&](int a) { return detA(a); });
}
double HotaResult::assA() const {
  return meanOverAlphas([&](int a) { return ass_a[a]; });
}
double HotaResult::locA() const {
  return meanOverAlphas([&](int a) { return loc_a[a]; });
}
double HotaResult::detRe() const {
  return meanOverAlphas([&](int a) { return detRe(a); });
}
double HotaResult::detPr() const {
  return meanOverAlphas([&](int a) { return detPr(a); });
}
double HotaResult::assRe() const {
  return meanOverAlphas([&](int a) { return ass_re[a]; });
}
double HotaResult::assPr() const {
  return meanOverAlphas([&](int a) { return ass_pr[a]; });
}

HotaResult hota(const std::vector<EvalFrame>& frames, double tau) {
  std::vector<HotaFrame> hf(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (const Object& t : frames[k].truths) hf[k].truths.push_back(t.id);
    for (const Object& e : frames[k].estimates) hf[k].tracks.push_back(e.id);
    for (const Object& t : frames[k].truths)
      for (const Object& e : frames[k].estimates)
        hf[k].similarity.push_back(std::max(0.0, 1.0 - distance(t, e) / tau));
  }
  return hota(hf);
}

HotaResult hota(const std::vector<HotaFrame>& frames) {
  std::map<long, int> truth_ix, track_ix;
  for (const HotaFrame& f : frames) {
    for (long id : f.truths) truth_ix.emplace(id, int(truth_ix.size()));
    for (long id : f.tracks) track_ix.emplace(id, int(track_ix.size()));
  }
  const int g = int(truth_ix.size()), n = int(track_ix.size());
  std::vector<FrameIds> fr(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    for (long id : frames[k].truths) fr[k].truth.push_back(truth_ix[id]);
    for (long id : frames[k].tracks) fr[k].track.push_back(track_ix[id]);
    fr[k].sim = frames[k].similarity;
    if (fr[k].sim.size() != fr[k].truth.size() * fr[k].track.size())
      throw std::invalid_argument("hota: a frame's similarity is not truths x tracks");
  }

  // Global alignment score: soft co-occurrence of each id pair over the whole run.
  std::vector<double> potential(std::size_t(g) * n, 0.0), gt_count(g, 0.0), tr_count(n, 0.0);
  for (const FrameIds& f : fr) {
    const std::size_t ng = f.truth.size(), nt = f.track.size();
    std::vector<double> row_sum(ng, 0.0), col_sum(nt, 0.0);
    for (std::size_t i = 0; i < ng; ++i)
      for (std::size_t j = 0; j < nt; ++j) {
        row_sum[i] += f.sim[i * nt + j];
        col_sum[j] += f.sim[i * nt + j];
      }
    for (std::size_t i = 0; i < ng; ++i)
      for (std::size_t j = 0; j < nt; ++j) {
        const double s = f.sim[i * nt + j];
        const double denom = row_sum[i] + col_sum[j] - s;
        if (denom > kEps) potential[std::size_t(f.truth[i]) * n + f.track[j]] += s / denom;
      }
    for (int id : f.truth) gt_count[id] += 1;
    for (int id : f.track) tr_count[id] += 1;
  }
  std::vector<double> global(potential.size(), 0.0);
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < n; ++j) {
      const double p = potential[std::size_t(i) * n + j];
      global[std::size_t(i) * n + j] = p / (gt_count[i] + tr_count[j] - p);
    }

  HotaResult r;
  std::vector<std::vector<double>> matches(HotaResult::kAlphas,
                                           std::vector<double>(std::size_t(g) * n, 0.0));
  std::array<double, HotaResult::kAlphas> loc_sum{};
  for (const FrameIds& f : fr) {
    const std::size_t ng = f.truth.size(), nt = f.track.size();
    if (ng == 0 || nt == 0) {
      for (int a = 0; a < HotaResult::kAlphas; ++a) {
        r.fn[a] += double(ng);
        r.fp[a] += double(nt);
      }
      continue;
    }
    std::vector<double> score(ng * nt);
    for (std::size_t i = 0; i < ng; ++i)
      for (std::size_t j = 0; j < nt; ++j)
        score[i * nt + j] = global[std::size_t(f.truth[i]) * n + f.track[j]] * f.sim[i * nt + j];
    const Assignment as = maximizeAssignment(score, int(ng), int(nt));
    for (int a = 0; a < HotaResult::kAlphas; ++a) {
      double matched = 0;
      for (const auto& [i, j] : as.pairs()) {
        const double s = f.sim[std::size_t(i) * nt + j];
        if (s < HotaResult::alpha(a) - kEps) continue;
        matched += 1;
        loc_sum[a] += s;
        matches[a][std::size_t(f.truth[i]) * n + f.track[j]] += 1;
      }
      r.tp[a] += matched;
      r.fn[a] += double(ng) - matched;
      r.fp[a] += double(nt) - matched;
    }
  }
  for (int a = 0; a < HotaResult::kAlphas; ++a) {
    double ass = 0, re = 0, pr = 0;
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < n; ++j) {
        const double m = matches[a][std::size_t(i) * n + j];
        if (m == 0) continue;
        ass += m * m / std::max(1.0, gt_count[i] + tr_count[j] - m);
        re += m * m / std::max(1.0, gt_count[i]);
        pr += m * m / std::max(1.0, tr_count[j]);
      }
    r.ass_a[a] = ass / std::max(1.0, r.tp[a]);
    r.ass_re[a] = re / std::max(1.0, r.tp[a]);
    r.ass_pr[a] = pr / std::max(1.0, r.tp[a]);
    // hota.py's guard: LocA is 1 when nothing matched.
    r.loc_a[a] = std::max(1e-10, loc_sum[a]) / std::max(1e-10, r.tp[a]);
  }
  return r;
}

HotaResult combineHota(const std::vector<HotaResult>& runs) {
  if (runs.size() == 1) return runs.front();
  HotaResult c;
  for (int a = 0; a < HotaResult::kAlphas; ++a) {
    double ass = 0, re = 0, pr = 0, loc = 0;
    for (const HotaResult& r : runs) {
      c.tp[a] += r.tp[a];
      c.fn[a] += r.fn[a];
      c.fp[a] += r.fp[a];
      ass += r.ass_a[a] * r.tp[a];
      re += r.ass_re[a] * r.tp[a];
      pr += r.ass_pr[a] * r.tp[a];
      loc += r.loc_a[a] * r.tp[a];
    }
    c.ass_a[a] = ass / std::max(1.0, c.tp[a]);
    c.ass_re[a] = re / std::max(1.0, c.tp[a]);
    c.ass_pr[a] = pr / std::max(1.0, c.tp[a]);
    c.loc_a[a] = std::max(1e-10, loc) / std::max(1e-10, c.tp[a]);
  }
  return c;
}

}  // namespace pedtrack::eval
