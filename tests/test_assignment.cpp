// The assignment solver (pedtrack/assignment.h: the Hungarian method with a gate, used by the
// evaluation's matching and the trackers' association) against brute force, and its overloads.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "pedtrack/assignment.h"

using namespace pedtrack;
using Catch::Detail::Approx;

namespace {

// Every (partial) one-to-one assignment of allowed pairs: the most pairs, then the least cost.
std::pair<std::size_t, double> bruteForce(const std::vector<double>& c, int rows, int cols,
                                          double gate) {
  std::pair<std::size_t, double> best{0, 0};
  std::vector<char> used(cols, 0);
  std::function<void(int, std::size_t, double)> go = [&](int r, std::size_t n, double cost) {
    if (r == rows) {
      if (n > best.first || (n == best.first && cost < best.second - 1e-12)) best = {n, cost};
      return;
    }
    go(r + 1, n, cost);  // row r unassigned
    for (int j = 0; j < cols; ++j) {
      const double v = c[r * cols + j];
      if (used[j] || !std::isfinite(v) || v > gate) continue;
      used[j] = 1;
      go(r + 1, n + 1, cost + v);
      used[j] = 0;
    }
  };
  go(0, 0, 0);
  return best;
}

}  // namespace

TEST_CASE("assignment equals brute force on random small matrices", "[eval][assignment]") {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> dim(1, 5);
  std::uniform_real_distribution<double> val(-2, 3);
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = dim(rng), cols = dim(rng);
    std::vector<double> c(rows * cols);
    for (double& v : c) v = val(rng);
    if (trial % 7 == 0) c[0] = std::nan("");
    const double gate = trial % 2 ? 1.0 : std::numeric_limits<double>::infinity();
    const Assignment a = solveAssignment(c, rows, cols, gate);
    const auto [n, cost] = bruteForce(c, rows, cols, gate);
    INFO("trial " << trial << " " << rows << "x" << cols);
    REQUIRE(a.size() == n);
    CHECK(a.cost == Approx(cost).margin(1e-9));
    for (const auto& [r, col] : a.pairs()) {
      CHECK(a.col_to_row[col] == r);
      CHECK(c[r * cols + col] <= gate);
    }
  }
}

TEST_CASE("assignment overloads, maximisation and empty inputs", "[eval][assignment]") {
  Eigen::MatrixXd m(2, 3);
  m << 4, 1, 3, 2, 0, 5;
  const Assignment e = solveAssignment(m);
  CHECK(e.cost == Approx(3));  // (0,1) + (1,0): 1 + 2
  CHECK(e.row_to_col == std::vector<int>{1, 0});
  CHECK(e.col_to_row == std::vector<int>{1, 0, -1});
  const Assignment v = solveAssignment(std::vector<std::vector<double>>{{4, 1, 3}, {2, 0, 5}}, 1.5);
  // Gate 1.5 allows (0,1)=1 and (1,1)=0 only, which share a column: one pair, the cheaper.
  CHECK(v.size() == 1);
  CHECK(v.row_to_col[1] == 1);
  const Assignment mx = maximizeAssignment({4, 1, 3, 2, 0, 5}, 2, 3);
  CHECK(mx.cost == Approx(9));  // (0,0) + (1,2)
  CHECK(solveAssignment(std::vector<double>{}, 0, 3).size() == 0);
  CHECK(solveAssignment(std::vector<double>{}, 3, 0).row_to_col == std::vector<int>(3, -1));
}
