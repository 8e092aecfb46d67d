// P0's MHE-Ellipse (eq. 3–10) and its Ipopt solution: derivatives, recovery of a noise-free
// walk, the constraints on every solution.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "mhe_mlesac/mhe_ellipse.h"
#include "mhe_mlesac/mhe_solver.h"
#include "mhe_mlesac/mlesac_select.h"
#include "mhe_walk.h"

using namespace pedtrack::track::mhe;
using pedtrack::test::MheWalk;

TEST_CASE("the deviation's gradient and Hessian match finite differences") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    State x = State::Zero();
    x << 0.3 * u(rng), 0.2 * u(rng), 3 * u(rng), 0, 0, 0, 0.15 + 0.04 * u(rng),
        0.08 + 0.02 * u(rng);
    const Point p(0.3 * u(rng), 0.3 * u(rng));
    Eigen::Matrix<double, 5, 1> g;
    Eigen::Matrix<double, 5, 5> H;
    const double s = deviation(x, p, g, &H);
    REQUIRE(s == Approx(deviation(x, p)).epsilon(1e-12));
    const int idx[5] = {0, 1, 2, 6, 7};
    const double h = 1e-6;
    for (int j = 0; j < 5; ++j) {
      State a = x, b = x;
      a(idx[j]) += h;
      b(idx[j]) -= h;
      CHECK(g(j) ==
            Approx((deviation(a, p) - deviation(b, p)) / (2 * h)).margin(1e-4).epsilon(1e-5));
      Eigen::Matrix<double, 5, 1> ga, gb;
      deviation(a, p, ga, nullptr);
      deviation(b, p, gb, nullptr);
      const Eigen::Matrix<double, 5, 1> col = (ga - gb) / (2 * h);
      for (int r = 0; r < 5; ++r) CHECK(H(r, j) == Approx(col(r)).margin(1e-3).epsilon(1e-5));
    }
  }
}

TEST_CASE("the system noise of eq. 2 is the velocity and semi-axis change over dt") {
  State a = State::Zero(), b = State::Zero();
  a << 0, 0, 0, 1, 0, 0.5, 0.18, 0.1;
  b << 0.1, 0, 0.05, 1.2, -0.1, 0.5, 0.19, 0.1;
  const auto n = systemNoise(a, b, 0.1);
  CHECK(n(0) == Approx(2.0));
  CHECK(n(1) == Approx(-1.0));
  CHECK(n(2) == Approx(0.0).margin(1e-12));
  CHECK(n(3) == Approx(0.1));
  CHECK(n(4) == Approx(0.0).margin(1e-12));
}

TEST_CASE("MHE on a noise-free constant-velocity walk recovers the state") {
  MheParams params;
  // A walker 2 m ahead crossing at 0.9 m/s and turning slowly; P0's sizes (α along θ).
  MheWalk walk(params.horizon, 0.1, {2.0, -0.4, 0.3, 0.2, 0.88, 0.2, 0.18, 0.09});
  MheProblem pb = walk.problem(params, /*perturb=*/true);
  MheSolver solver(params);
  const SolveResult r = solver.solve(pb, pb.prior);
  REQUIRE(r.usable());
  const State& est = r.xs.back();
  const State truth = walk.truth(params.horizon - 1);
  INFO("estimate " << est.transpose() << "\ntruth    " << truth.transpose());
  CHECK((est.head<2>() - truth.head<2>()).norm() < 0.005);
  CHECK(std::abs(est(2) - truth(2)) < 0.02);
  CHECK((est.segment<2>(3) - truth.segment<2>(3)).norm() < 0.05);
  CHECK(std::abs(est(5) - truth(5)) < 0.1);
  CHECK(std::abs(est(6) - truth(6)) < 0.005);
  CHECK(std::abs(est(7) - truth(7)) < 0.005);
  CHECK(constraintViolation(pb, params, r.xs) < 1e-6);
  // The solution is at least as good as the truth in eq. 5 (it minimises it).
  CHECK(mheCost(pb, params, r.xs).total() <=
        mheCost(pb, params, walk.truthWindow()).total() + 1e-6);
}

TEST_CASE("every MHE solution satisfies the constraints (6)-(10)") {
  MheParams params;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  MheSolver solver(params);
  std::vector<double> ms;
  for (int trial = 0; trial < 25; ++trial) {
    // Walkers whose true size breaks the bounds (a wide coat, a child) and points with noise and
    // outliers: the solution must still keep every constraint.
    const State x0 = (State() << 1.5 + u(rng), u(rng), 3 * u(rng), u(rng), u(rng), 0.5 * u(rng),
                      0.12 + 0.15 * (u(rng) + 1), 0.04 + 0.05 * (u(rng) + 1))
                         .finished();
    MheWalk walk(params.horizon, 0.1, x0, /*noise=*/0.01, /*outliers=*/0.2, trial);
    MheProblem pb = walk.problem(params, true);
    const auto t0 = std::chrono::steady_clock::now();
    const SolveResult r = solver.solve(pb, pb.prior);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    INFO("trial " << trial << ": " << toString(r.status));
    REQUIRE(r.usable());
    CHECK(constraintViolation(pb, params, r.xs) < 1e-6);
    for (const State& x : r.xs) {
      CHECK(x(6) >= x(7) - 1e-9);
      CHECK(x(6) >= params.alpha_min - 1e-9);
      CHECK(x(6) <= params.alpha_max + 1e-9);
      CHECK(x(7) >= params.beta_min - 1e-9);
      CHECK(x(7) <= params.beta_max + 1e-9);
    }
  }
  std::sort(ms.begin(), ms.end());
  WARN("MHE-Ellipse solve (H = 10, all points): median " << ms[ms.size() / 2] << " ms");
}

TEST_CASE("the MLESAC selection prefers the candidate whose sample has no outliers") {
  MheParams params;
  // A walker with 25 % of the points pushed 15–30 cm outwards (arms, a bag): candidate A samples
  // only true torso points, candidate B the same number with a third of them outliers.
  const State x0 = (State() << 2.0, 0.3, 0.4, -0.5, 0.7, 0.1, 0.18, 0.09).finished();
  MheWalk clean(params.horizon, 0.1, x0, 0.005, 0.0, 5);
  MheWalk dirty(params.horizon, 0.1, x0, 0.005, 0.25, 5);
  MheProblem base = dirty.problem(params, true);
  MheProblem a = base, b = base;
  int na = 0, nb = 0;
  for (int k = 0; k < base.size(); ++k) {
    a.sample[k].clear();
    b.sample[k].clear();
    const auto& pts = dirty.frames()[k].points;
    const auto& ref = clean.frames()[k].points;  // same seed: outliers are the points that moved
    for (int i = 0; i < int(pts.size()); ++i) {
      const bool outlier = (pts[i] - ref[i]).norm() > 0.1;
      if (!outlier && i % 2 == 0) a.sample[k].push_back(i), ++na;
      if (outlier || i % 3 == 0) b.sample[k].push_back(i), ++nb;
    }
  }
  a.data_weight = 1 / (params.r * na);
  b.data_weight = 1 / (params.r * nb);
  MheSolver solver(params);
  const SolveResult ra = solver.solve(a, a.prior), rb = solver.solve(b, b.prior);
  REQUIRE(ra.usable());
  REQUIRE(rb.usable());
  for (Selection sel : {Selection::InlierMean, Selection::Truncated}) {
    const Selected sa = selectionCost(base, params, sel, ra.xs);
    const Selected sb = selectionCost(base, params, sel, rb.xs);
    INFO("clean sample J " << sa.cost << " (" << sa.inliers << " inliers), with outliers J "
                           << sb.cost << " (" << sb.inliers << ")");
    CHECK(sa.cost < sb.cost);
  }
  // And the clean candidate is the accurate one.
  const State truth = dirty.truth(params.horizon - 1);
  CHECK((ra.xs.back().head<2>() - truth.head<2>()).norm() < 0.01);
  CHECK((rb.xs.back().head<2>() - truth.head<2>()).norm() > 0.02);
}

TEST_CASE("MHE-MLESAC with its refit beats MHE on every point when there are outliers") {
  MheParams params;
  MheSolver solver(params);
  std::mt19937 rng(2);
  double err_mlesac = 0, err_all = 0;
  for (unsigned seed = 0; seed < 5; ++seed) {
    const State x0 = (State() << 2.5, -0.5, 1.2, 0.3, -0.8, 0, 0.18, 0.09).finished();
    MheWalk walk(params.horizon, 0.1, x0, 0.005, 0.2, seed);
    MheProblem pb = walk.problem(params, true);
    MlesacInput in;
    in.frames = &walk.frames();
    in.prior = pb.prior;
    in.arrival_mean = pb.arrival_mean;
    in.arrival_info = pb.arrival_info;
    MlesacOptions robust, plain;
    plain.sampling = false;
    const MlesacResult r = mheMlesac(in, params, robust, solver, rng);
    const MlesacResult q = mheMlesac(in, params, plain, solver, rng);
    REQUIRE(r.ok);
    REQUIRE(q.ok);
    CHECK(r.candidates == params.candidates);
    CHECK(q.candidates == 1);
    for (const State& x : r.xs) CHECK(x(6) >= x(7));
    const State truth = walk.truth(params.horizon - 1);
    err_mlesac += (r.xs.back().head<2>() - truth.head<2>()).norm();
    err_all += (q.xs.back().head<2>() - truth.head<2>()).norm();
  }
  INFO("mean position error: MHE-MLESAC " << err_mlesac / 5 << " m, MHE on all points "
                                          << err_all / 5 << " m");
  CHECK(err_mlesac < 0.5 * err_all);
  CHECK(err_mlesac / 5 < 0.04);
}

TEST_CASE("solvers on two threads at once give each thread's own answer") {
  // MUMPS (sequential) keeps global state: unserialised, two solves at once crash the process
  // (montecarlo -j 2 did). Each thread solves the same walk and must get the single-thread answer.
  MheParams params;
  MheWalk walk(params.horizon, 0.1, {2.0, -0.4, 0.3, 0.2, 0.88, 0.2, 0.18, 0.09});
  const MheProblem pb = walk.problem(params, /*perturb=*/true);
  MheSolver reference_solver(params);
  const SolveResult reference = reference_solver.solve(pb, pb.prior);
  REQUIRE(reference.usable());
  std::vector<SolveResult> results(2);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      MheSolver solver(params);
      for (int i = 0; i < 20; ++i) results[std::size_t(t)] = solver.solve(pb, pb.prior);
    });
  for (std::thread& th : threads) th.join();
  for (const SolveResult& r : results) {
    REQUIRE(r.usable());
    CHECK((r.xs.back() - reference.xs.back()).norm() < 1e-9);
  }
}
