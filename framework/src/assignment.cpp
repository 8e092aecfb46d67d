#include "pedtrack/assignment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pedtrack {
namespace {

// Kuhn-Munkres with row/column potentials: rows are added one at a time and each is placed by a
// Dijkstra-like search for the shortest augmenting path in reduced costs. `a` is n×m row-major,
// n ≤ m, every entry finite. Returns the row assigned to each column (-1: none).
std::vector<int> hungarian(const std::vector<double>& a, int n, int m) {
  const double inf = std::numeric_limits<double>::infinity();
  // 1-based bookkeeping; column 0 is the virtual start of each search.
  std::vector<double> u(n + 1, 0), v(m + 1, 0), minv(m + 1);
  std::vector<int> p(m + 1, 0), way(m + 1, 0);
  std::vector<char> used(m + 1);
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::fill(minv.begin(), minv.end(), inf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const int i0 = p[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = a[std::size_t(i0 - 1) * m + (j - 1)] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const int j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> col_row(m, -1);
  for (int j = 1; j <= m; ++j)
    if (p[j] > 0) col_row[j - 1] = p[j] - 1;
  return col_row;
}

bool allowed(double c, double gate) {
  return std::isfinite(c) && !(c > gate);
}

}  // namespace

std::vector<std::pair<int, int>> Assignment::pairs() const {
  std::vector<std::pair<int, int>> out;
  for (std::size_t r = 0; r < row_to_col.size(); ++r)
    if (row_to_col[r] >= 0) out.emplace_back(int(r), row_to_col[r]);
  return out;
}

std::size_t Assignment::size() const {
  return std::count_if(row_to_col.begin(), row_to_col.end(), [](int c) { return c >= 0; });
}

Assignment solveAssignment(const std::vector<double>& cost, int rows, int cols, double gate) {
  Assignment out;
  out.row_to_col.assign(std::max(rows, 0), -1);
  out.col_to_row.assign(std::max(cols, 0), -1);
  if (rows <= 0 || cols <= 0) return out;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double c : cost) {
    if (!allowed(c, gate)) continue;
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
  if (lo > hi) return out;  // nothing allowed
  // Forbidden pairs get a cost so high that one more forbidden pair always costs more than any
  // spread of allowed costs could save: the optimum then has the fewest forbidden pairs (= the
  // most allowed ones) and, among those, the least allowed cost. Shifting by `lo` keeps the
  // allowed costs in [0, hi - lo] so the big cost stays small relative to double precision.
  const int n = std::min(rows, cols), m = std::max(rows, cols);
  const bool transpose = rows > cols;
  const double big = (hi - lo + 1) * (n + 1);
  std::vector<double> a(std::size_t(n) * m);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double v = cost[std::size_t(r) * cols + c];
      const double w = allowed(v, gate) ? v - lo : big;
      if (transpose)
        a[std::size_t(c) * m + r] = w;
      else
        a[std::size_t(r) * m + c] = w;
    }
  const std::vector<int> col_row = hungarian(a, n, m);
  for (int j = 0; j < m; ++j) {
    const int i = col_row[j];
    if (i < 0) continue;
    const int r = transpose ? j : i, c = transpose ? i : j;
    const double v = cost[std::size_t(r) * cols + c];
    if (!allowed(v, gate)) continue;
    out.row_to_col[r] = c;
    out.col_to_row[c] = r;
    out.cost += v;
  }
  return out;
}

Assignment solveAssignment(const Eigen::MatrixXd& cost, double gate) {
  std::vector<double> flat(std::size_t(cost.rows()) * cost.cols());
  for (Eigen::Index r = 0; r < cost.rows(); ++r)
    for (Eigen::Index c = 0; c < cost.cols(); ++c) flat[r * cost.cols() + c] = cost(r, c);
  return solveAssignment(flat, int(cost.rows()), int(cost.cols()), gate);
}

Assignment solveAssignment(const std::vector<std::vector<double>>& cost, double gate) {
  const int rows = int(cost.size()), cols = rows ? int(cost[0].size()) : 0;
  std::vector<double> flat;
  flat.reserve(std::size_t(rows) * cols);
  for (const auto& row : cost) {
    if (int(row.size()) != cols) throw std::invalid_argument("solveAssignment: ragged matrix");
    flat.insert(flat.end(), row.begin(), row.end());
  }
  return solveAssignment(flat, rows, cols, gate);
}

Assignment maximizeAssignment(const std::vector<double>& weight, int rows, int cols,
                              double min_weight) {
  std::vector<double> neg(weight.size());
  std::transform(weight.begin(), weight.end(), neg.begin(), [](double w) { return -w; });
  Assignment a = solveAssignment(neg, rows, cols, -min_weight);
  a.cost = -a.cost;
  return a;
}

}  // namespace pedtrack
