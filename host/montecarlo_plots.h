#pragma once
// `pedtrack montecarlo` figures, after P4 Figs. 9–19 and 22: per truth id the runs' average NEES
// and NIS per frame against their χ² bounds, and the per-axis position RMSE; and one run's track
// log-likelihood ratios against the confirmation and deletion thresholds.
#include <string>
#include <vector>

#include "montecarlo_score.h"

namespace pedtrack::cli {

/// Draws nees_<id>.png, nis_<id>.png (when the tracks have NIS), rmse_<id>.png and
/// heading_<id>.png (when some matched track row has yaw) into `dir` for every truth id matched
/// in some run; `name` (the scenario) heads each title. Returns the file names written. Throws
/// DataError when a file cannot be written.
std::vector<std::string> drawConsistencyPlots(const std::string& dir, const MonteCarloScore& score,
                                              const std::string& name);

/// Draws `png` from a tracker's existence.csv (t,frame,track,existence,llr,llr_confirm,
/// llr_delete,status): each track's LLR over time, with the confirmation and deletion
/// thresholds. Returns false, drawing nothing, when `existence_csv` does not exist or has no
/// rows. Throws ConfigError for a file without those columns, DataError when `png` cannot be
/// written.
bool drawLlrPlot(const std::string& existence_csv, const std::string& png,
                 const std::string& title);

}  // namespace pedtrack::cli
