#pragma once
// `pedtrack eval --range-bins`, `--shape-plot`: the matches of a tracking evaluation by distance
// from the sensor (P1 Table II: errors, torso semi-axes and the average model probabilities per
// band) and the semi-axes against range (P1 Fig. 11).
#include <string>
#include <unordered_map>
#include <vector>

#include "pedtrack/eval/object_table.h"
#include "pedtrack/eval/pair_errors.h"

namespace pedtrack::cli {

/// "0,10,20,30" → {0, 10, 20, 30}. Throws ConfigError (naming `option`) unless the list holds
/// finite numbers ≥ 0, increasing.
std::vector<double> parseRangeEdges(const std::string& text, const std::string& option);

/// The `model_probs` column of tracks tables (";"-separated numbers), by row; rows with the
/// column empty (or tables without it) have none.
class ModelProbs {
 public:
  /// Reads `table.path` again for the column. Throws ConfigError naming file, line and column
  /// for a value that is not a number.
  void add(const ObjectTable& table);
  const std::vector<double>* of(const ObjectRow& row) const;

 private:
  std::unordered_map<const ObjectRow*, std::vector<double>> probs_;
};

/// Column names of the model probabilities: `names`, then prob_<k> (1-based) up to `models`.
std::vector<std::string> modelColumns(const std::vector<std::string>& names, std::size_t models);

std::string rangeBandsText(const eval::RangeBandReport& r, const std::vector<std::string>& names);
/// The value of the JSON key "range_bands".
std::string rangeBandsJson(const eval::RangeBandReport& r, const std::vector<std::string>& names);

struct ShapeBounds {
  bool given = false;
  double alpha_min = 0, alpha_max = 0, beta_min = 0, beta_max = 0;  ///< m
};

/// Draws `png`: alpha and beta of the matched estimate rows against their distance from the
/// sensor, the matched truths' mean alpha and beta as reference lines, and `bounds` dashed.
/// Returns the number of rows drawn (0: the plot only says so). Throws DataError when `png`
/// cannot be written.
std::size_t drawShapePlot(const std::string& png, const std::vector<eval::MatchedPair>& pairs,
                          const ShapeBounds& bounds);

}  // namespace pedtrack::cli
