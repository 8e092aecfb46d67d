#pragma once
// `pedtrack montecarlo` output: the report as a table or JSON (montecarlo.json), and the per
// truth id and frame figures as consistency.csv.
#include <string>
#include <vector>

#include "montecarlo_run.h"
#include "montecarlo_score.h"

namespace pedtrack::cli {

/// What was run, echoed in the report.
struct MonteCarloInfo {
  MonteCarloSetup setup;
  double threshold = 0.75;
  std::vector<RunOutcome> outcomes;  ///< every run, in order; the ok ones were scored
  std::vector<std::string> files;    ///< written into the output directory, by name
};

/// The score, or null when nothing was scored (every run failed).
std::string monteCarloText(const MonteCarloInfo& info, const MonteCarloScore* score);
std::string monteCarloJson(const MonteCarloInfo& info, const MonteCarloScore* score);

/// consistency.csv: one row per truth id and frame index matched in some run:
/// truth_id,frame,t,n,nees_mean,nees_lower,nees_upper,nees_inside,nis_mean,nis_lower,nis_upper,
/// nis_inside,rmse_x,rmse_y,rmse,heading_n,heading_rmse (empty when a column has no value). Throws
/// DataError when the file cannot be written.
void writeConsistencyCsv(const std::string& path, const MonteCarloScore& score);

}  // namespace pedtrack::cli
