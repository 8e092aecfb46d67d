#pragma once
// `pedtrack montecarlo` scoring: the runs' truth.csv and tracks.csv scored together as
// `pedtrack eval` scores Monte Carlo runs, plus what P4's consistency figures show per truth id
// and frame index: the runs' average NEES and NIS against their χ² bounds, and the position
// RMSE over the runs; and each run's ID switches.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "pedtrack/eval/evaluate.h"

namespace pedtrack::cli {

/// One truth id at one frame index, over the runs that matched it there.
struct FramePoint {
  long truth_id = 0;
  std::size_t frame = 0;  ///< frame index within each run (runs are aligned by it)
  double t = 0;           ///< time of that frame in the first run that has it (UNIX s)
  std::size_t n = 0;      ///< runs whose tracks matched this truth here
  double rmse_x = 0, rmse_y = 0, rmse = 0;  ///< √(mean over those runs of the squared error), m
  std::optional<eval::ConsistencyPoint> nees, nis;
  /// Of those runs, the ones whose track and truth rows both have yaw, and √(mean of their
  /// squared wrapped heading error), rad (NaN when none).
  std::size_t heading_n = 0;
  double heading_rmse = std::nan("");
};

struct TruthSummary {
  long id = 0;
  std::size_t frames = 0;          ///< frame indices where some run scored this truth
  std::size_t matched_frames = 0;  ///< … and some run matched it (the FramePoints)
  std::size_t nees_frames = 0, nis_frames = 0;
  double nees_inside = 0, nis_inside = 0;  ///< fraction of those frames inside the bounds
  double rmse_mean = 0, rmse_max = 0;      ///< over the matched frames' rmse, m
  std::size_t heading_frames = 0;          ///< matched frames with a heading_rmse
  double heading_rmse_mean = 0, heading_rmse_max = 0;  ///< over those frames, rad
};

struct RunScore {
  std::size_t track_rows = 0;
  std::size_t id_switches = 0;
  double mota = 0;
};

struct MonteCarloScore {
  std::vector<RunScore> runs;
  std::size_t track_rows = 0;  ///< over all runs; 0: nothing to score
  /// Every run pooled (evaluateTracking); absent when there are no track rows.
  std::optional<eval::TrackingReport> tracking;
  std::vector<FramePoint> points;  ///< by truth id, then frame
  std::vector<TruthSummary> truths;
  double t0 = 0;  ///< time of the first frame of the first run (the plots' origin)

  std::size_t runsWithoutSwitch() const;
};

/// Scores the runs whose files are `truth[r]` and `tracks[r]` (fixed frame, truths with no
/// visible points unscored, as `pedtrack eval` does). Throws ConfigError for a file it cannot
/// read.
MonteCarloScore scoreMonteCarlo(const std::vector<std::string>& truth,
                                const std::vector<std::string>& tracks,
                                const eval::TrackingOptions& options);

}  // namespace pedtrack::cli
