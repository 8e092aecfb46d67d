#include "pedtrack/classify/roc.h"

#include <algorithm>
#include <numeric>

namespace pedtrack::classify {

Confusion confusionAt(const std::vector<double>& scores, const std::vector<Label>& y,
                      double threshold) {
  Confusion c;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    const bool decided = scores[i] >= threshold;
    if (y[i] == Label::Person)
      (decided ? c.tp : c.fn)++;
    else
      (decided ? c.fp : c.tn)++;
  }
  return c;
}

namespace {
std::vector<std::size_t> byScoreDescending(const std::vector<double>& s) {
  std::vector<std::size_t> o(s.size());
  std::iota(o.begin(), o.end(), 0);
  std::stable_sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return s[a] > s[b]; });
  return o;
}
}  // namespace

std::vector<RocPoint> rocCurve(const std::vector<double>& scores, const std::vector<Label>& y) {
  const auto o = byScoreDescending(scores);
  double P = 0, N = 0;
  for (Label l : y) (l == Label::Person ? P : N) += 1;
  std::vector<RocPoint> roc{{0, 0, scores.empty() ? 1.0 : scores[o.front()] + 1e-12}};
  double tp = 0, fp = 0;
  for (std::size_t i = 0; i < o.size(); ++i) {
    (y[o[i]] == Label::Person ? tp : fp) += 1;
    // One point after each run of equal scores.
    if (i + 1 == o.size() || scores[o[i + 1]] != scores[o[i]])
      roc.push_back({N > 0 ? fp / N : 0, P > 0 ? tp / P : 0, scores[o[i]]});
  }
  return roc;
}

RocPoint bestAtFpr(const std::vector<RocPoint>& roc, double max_fpr) {
  RocPoint best;
  for (const auto& p : roc)
    if (p.fpr <= max_fpr && p.tpr >= best.tpr) best = p;
  return best;
}

RocPoint bestAtTpr(const std::vector<RocPoint>& roc, double min_tpr) {
  for (const auto& p : roc)  // fpr grows along the curve: the first one reaching min_tpr
    if (p.tpr >= min_tpr) return p;
  return roc.empty() ? RocPoint{1, 1, 0} : roc.back();
}

double rocAuc(const std::vector<double>& scores, const std::vector<Label>& y) {
  // Trapezoids over the curve equal U / (n₊ n₋) with ties counted one half.
  const auto roc = rocCurve(scores, y);
  double a = 0;
  for (std::size_t i = 1; i < roc.size(); ++i)
    a += (roc[i].fpr - roc[i - 1].fpr) * 0.5 * (roc[i].tpr + roc[i - 1].tpr);
  return a;
}

}  // namespace pedtrack::classify
