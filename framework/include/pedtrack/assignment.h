#pragma once
// Minimum-cost rectangular assignment (Kuhn-Munkres with potentials, shortest augmenting paths
// as in Jonker-Volgenant; O(n² m) for n ≤ m) with gating. Written here because no installed
// library has one: MRPT 2.5 offers nearest-neighbour and JCBB association only, OpenCV 4.6 keeps
// its Kuhn-Munkres private to the tracking module, and Boost.Graph 1.74's
// maximum_weighted_matching maximises weight on general graphs without a cardinality-first rule.
// Evaluation and trackers' data association share it.
#include <Eigen/Core>
#include <limits>
#include <utility>
#include <vector>

namespace pedtrack {

struct Assignment {
  std::vector<int> row_to_col;  ///< column assigned to each row, -1 when unassigned
  std::vector<int> col_to_row;  ///< row assigned to each column, -1 when unassigned
  double cost = 0;              ///< sum of the costs of the assigned pairs
  /// The assigned (row, column) pairs, by row.
  std::vector<std::pair<int, int>> pairs() const;
  std::size_t size() const;  ///< number of assigned pairs
};

/// Assigns rows to columns (each at most once). A pair whose cost is above `gate`, NaN or
/// infinite is forbidden. Among the assignments that use allowed pairs only, returns one with
/// the most pairs and, among those, the least total cost — so gating never makes the solver drop
/// a feasible pair to save cost (the rule of py-motmetrics and of TrackEval). Costs may be
/// negative; to maximise weights, pass their negation (see maximizeAssignment).
Assignment solveAssignment(const Eigen::MatrixXd& cost,
                           double gate = std::numeric_limits<double>::infinity());
Assignment solveAssignment(const std::vector<std::vector<double>>& cost,
                           double gate = std::numeric_limits<double>::infinity());
/// `cost` is row-major, rows × cols.
Assignment solveAssignment(const std::vector<double>& cost, int rows, int cols,
                           double gate = std::numeric_limits<double>::infinity());

/// The assignment with the most pairs of weight ≥ `min_weight` (NaN = forbidden) and, among
/// those, the largest total weight. `Assignment::cost` is then the total weight.
Assignment maximizeAssignment(const std::vector<double>& weight, int rows, int cols,
                              double min_weight = -std::numeric_limits<double>::infinity());

}  // namespace pedtrack
