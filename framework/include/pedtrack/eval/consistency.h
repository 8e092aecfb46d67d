#pragma once
// Filter consistency (Bar-Shalom, Li & Kirubarajan 2001, §5.4), as P4 reports it: NEES
// e = dᵀ P⁻¹ d of the position error d = track − truth with the track's covariance P (2 dof),
// and the tracker's own NIS. Per truth id and frame the values of the N Monte Carlo runs are
// averaged; N times that average is χ²(N·dof) for a consistent filter, so the two-sided 95 %
// region of the average is [χ²(N·dof)⁻¹(0.025), χ²(N·dof)⁻¹(0.975)] / N.
#include <cstddef>
#include <vector>

#include "pedtrack/eval/clear_mot.h"

namespace pedtrack::eval {

struct ChiSquareBounds {
  double lower = 0, upper = 0;
};

/// Two-sided `confidence` region of the mean of n independent χ²(dof) values.
ChiSquareBounds chiSquareBounds(int dof, std::size_t n, double confidence = 0.95);

/// dᵀ P⁻¹ d for d = (dx, dy), P = [pxx pxy; pxy pyy]; NaN unless P is positive definite.
double normalizedSquare(double dx, double dy, double pxx, double pxy, double pyy);

struct ConsistencySample {
  long truth_id = 0;
  std::size_t frame = 0;  ///< frame index within its run; runs are aligned by this index
  double value = 0;
};

/// The samples of one run's scored matches: NEES for tracks with a covariance (fixed-frame
/// positions, since the covariance is fixed-frame), NIS for tracks with a `nis` value.
std::vector<ConsistencySample> neesSamples(const std::vector<MatchedPair>& pairs);
std::vector<ConsistencySample> nisSamples(const std::vector<MatchedPair>& pairs);

struct ConsistencyPoint {
  long truth_id = 0;
  std::size_t frame = 0;
  std::size_t n = 0;       ///< runs that contributed (≤ runs: a truth may be unmatched in some)
  double mean = 0;         ///< average over those runs
  ChiSquareBounds bounds;  ///< for n values
  bool inside = false;
};

struct ConsistencyReport {
  int dof = 2;
  std::size_t runs = 1;
  std::size_t samples = 0;
  double mean = 0;                       ///< of all samples (the time- and run-average)
  ChiSquareBounds mean_bounds;           ///< region of `mean` for `samples` values
  ChiSquareBounds nominal_bounds;        ///< region of one point averaged over all `runs`
  double fraction_inside = 0;            ///< of the points, each against its own bounds
  std::vector<ConsistencyPoint> points;  ///< by truth id, then frame
  struct PerTruth {
    long id = 0;
    std::size_t points = 0;
    double mean = 0;
    double fraction_inside = 0;
  };
  std::vector<PerTruth> per_truth;
};

/// Samples of every run pooled: averaged per (truth id, frame index) and judged against the
/// χ² region of their count. `samples` must not be empty.
ConsistencyReport consistency(const std::vector<ConsistencySample>& samples, int dof,
                              std::size_t runs, double confidence = 0.95);

}  // namespace pedtrack::eval
