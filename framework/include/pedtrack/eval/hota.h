#pragma once
// HOTA (Luiten et al., IJCV 2021) as TrackEval's hota.py computes it, with a distance similarity
// sim = max(0, 1 − d/τ) in place of IoU. Per α in 0.05, 0.10, …, 0.95: every frame gets one
// assignment maximising sim × global alignment score (the association bonus of hota.py), pairs
// with sim ≥ α are TP; then A(c) = TPA/(TPA + FNA + FPA) per matched id pair, AssA the TP-weighted
// mean of A, DetA = TP/(TP + FN + FP), LocA the mean sim of TPs, HOTA = sqrt(DetA·AssA). The
// reported numbers are means over α.
#include <array>
#include <vector>

#include "pedtrack/eval/frames.h"

namespace pedtrack::eval {

struct HotaResult {
  static constexpr int kAlphas = 19;
  static double alpha(int a) { return 0.05 * (a + 1); }
  // Per α. Over several runs these combine as TrackEval combines sequences.
  std::array<double, kAlphas> tp{}, fn{}, fp{};
  std::array<double, kAlphas> ass_a{}, ass_re{}, ass_pr{}, loc_a{};

  double detA(int a) const;
  double detRe(int a) const;
  double detPr(int a) const;
  double hota(int a) const;
  // Means over α (the numbers TrackEval reports).
  double hota() const;
  double detA() const;
  double assA() const;
  double locA() const;
  double detRe() const;
  double detPr() const;
  double assRe() const;
  double assPr() const;
};

/// HOTA of one run (all truths scored; remove unscored ones first, see withoutUnscored).
HotaResult hota(const std::vector<EvalFrame>& frames, double tau);

/// One frame with any similarity in [0, 1] (KITTI's: 3D IoU): the ids of its truths and tracks
/// and their truth-major similarity matrix (truths × tracks).
struct HotaFrame {
  std::vector<long> truths, tracks;
  std::vector<double> similarity;
};
/// HOTA over such frames; throws std::invalid_argument when a similarity matrix has the wrong size.
HotaResult hota(const std::vector<HotaFrame>& frames);

/// Several runs pooled as TrackEval pools sequences: TP/FN/FP summed, AssA/AssRe/AssPr/LocA
/// averaged with the runs' TP counts as weights.
HotaResult combineHota(const std::vector<HotaResult>& runs);

}  // namespace pedtrack::eval
