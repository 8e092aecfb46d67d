#pragma once
// `pedtrack montecarlo --compare`: several Monte Carlo result directories (of one scenario, e.g.
// one per tracker) side by side, as P0 Table I and Fig. 9: a markdown table of their pooled
// figures and, per truth id, the per-frame distance and heading errors of each in one figure.
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pedtrack::cli {

/// One truth id's per-frame errors of one directory (its consistency.csv rows, by frame).
struct CompareCurve {
  std::vector<std::size_t> frame;
  std::vector<double> t;        ///< UNIX s
  std::vector<double> rmse;     ///< m, position RMSE over the runs
  std::vector<double> heading;  ///< rad, heading RMSE over the runs; NaN where none
};

/// What one directory's montecarlo.json and consistency.csv hold for the comparison.
struct CompareEntry {
  std::string label, dir;
  std::size_t runs = 0;  ///< runs scored
  double position_rmse_m = std::nan(""), heading_rmse_rad = std::nan(""), mota = std::nan("");
  double axis_rmse_rad = std::nan("");     ///< heading error modulo π; NaN in results without it
  std::optional<std::size_t> id_switches;  ///< over all runs; absent without tracks
  double t0 = std::nan("");                ///< first frame of run 0 (UNIX s), NaN when unknown
  std::map<long, CompareCurve> curves;     ///< by truth id
};

/// Reads DIR/montecarlo.json (required) and DIR/consistency.csv (when present). Throws
/// ConfigError, one line naming the directory, when DIR or its montecarlo.json is missing or
/// unreadable.
CompareEntry readMonteCarloDir(const std::string& dir, const std::string& label);

/// The markdown table: one row per entry, columns label, position RMSE (mm), heading RMSE (rad),
/// axis RMSE (rad), MOTA, ID switches, runs ("-" where undefined); the cells padded so that
/// columns align.
std::string compareMarkdown(const std::vector<CompareEntry>& entries);

/// Draws errors_<truth id>.png into `dir` for every truth id of some entry: distance error (m)
/// over heading error (rad) against time, one colour per entry with a legend. Times are from
/// the earliest entry's t0. Returns the file names written; throws DataError when one cannot be.
std::vector<std::string> drawCompareErrors(const std::string& dir,
                                           const std::vector<CompareEntry>& entries);

}  // namespace pedtrack::cli
