// The shared tracking parts against hand computations: a Kalman step, the IMM cycle, gates, PDA
// and JPDA weights, existence and its LLR thresholds, M-of-N, and occlusion.
#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <cmath>

#include "imm_pdaf/gate.h"
#include "imm_pdaf/jpda.h"
#include "imm_pdaf/occlusion.h"
#include "imm_pdaf/pda.h"
#include "pedtrack/track/gnn.h"
#include "pedtrack/track/imm.h"
#include "pedtrack/track/kalman.h"
#include "pedtrack/track/management.h"
#include "pedtrack/track/tracker_base.h"

using namespace pedtrack;
using namespace pedtrack::track;
using Catch::Detail::Approx;

namespace {
Gaussian start() {
  Gaussian g;
  g.x = Eigen::Vector4d(0, 0, 1, 0);
  g.P = Eigen::MatrixXd::Identity(4, 4);
  return g;
}
}  // namespace

TEST_CASE("a CV Kalman step matches the hand computation", "[track]") {
  // q = 1, Δt = 1: P⁻_x = [[1,1],[0,1]] I [[1,0],[1,1]] + [[1/3,1/2],[1/2,1]] = [[7/3,3/2],[3/2,2]]
  Gaussian g = start();
  ConstantVelocity cv(1.0);
  kalmanPredict(g, cv, 1.0);
  CHECK(g.x(0) == Approx(1));
  CHECK(g.P(0, 0) == Approx(7.0 / 3));
  CHECK(g.P(0, 2) == Approx(1.5));
  CHECK(g.P(2, 2) == Approx(2));
  // z = (1.5, 0), R = I: S = 10/3, K_x = (0.7, 0.45), ν = 0.5.
  const Innovation in = kalmanUpdate(g, positionMeasurement(4, 1.0), Eigen::Vector2d(1.5, 0));
  CHECK(in.S(0, 0) == Approx(10.0 / 3));
  CHECK(in.nis == Approx(0.25 / (10.0 / 3) + 0.0));
  CHECK(g.x(0) == Approx(1.35));
  CHECK(g.x(2) == Approx(1.225));
  CHECK(g.P(0, 0) == Approx(0.7));
  CHECK(g.P(0, 2) == Approx(0.45));
  CHECK(g.P(2, 2) == Approx(1.325));
  CHECK(in.log_likelihood ==
        Approx(-0.5 * (in.nis + std::log(in.S.determinant()) + 2 * std::log(2 * M_PI))));
}

TEST_CASE("motion models: CT turns the velocity, CA and the unicycle Jacobian", "[track]") {
  CoordinatedTurn ct(M_PI / 2, 0);  // a quarter turn in 1 s
  const Eigen::VectorXd x = ct.predict(Eigen::Vector4d(0, 0, 1, 0), 1.0);
  CHECK(x(0) == Approx(2 / M_PI));  // r = v/ω = 2/π, quarter circle ends at (r, r)
  CHECK(x(1) == Approx(2 / M_PI));
  CHECK(x(2) == Approx(0).margin(1e-12));
  CHECK(x(3) == Approx(1));
  CHECK(CoordinatedTurn(0, 1).jacobian(x, 0.5).isApprox(ConstantVelocity(1).jacobian(x, 0.5)));
  ConstantAcceleration ca(0);
  Eigen::VectorXd a(6);
  a << 0, 0, 1, 0, 2, 0;
  CHECK(ca.predict(a, 1.0)(0) == Approx(2));  // x + v t + a t²/2
  CHECK(ca.noise(a, 1.0).isZero());
  // Unicycle (P2 eq. 15): the analytic Jacobian equals a numeric one.
  Unicycle u(0.1, 0.2);
  const Eigen::Vector4d s(1, 2, 0.7, 1.3);
  const Eigen::MatrixXd A = u.jacobian(s, 0.1);
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector4d d = Eigen::Vector4d::Zero();
    d(k) = 1e-6;
    const Eigen::VectorXd num = (u.predict(s + d, 0.1) - u.predict(s - d, 0.1)) / 2e-6;
    CHECK(num.isApprox(A.col(k), 1e-6));
  }
  CHECK(u.velocity(s)(0) == Approx(1.3 * std::cos(0.7)));
}

TEST_CASE("an IMM of one model, or of identical models, is the Kalman filter", "[track]") {
  const auto cv = std::make_shared<ConstantVelocity>(0.5);
  const LinearMeasurement m = positionMeasurement(4, 0.2);
  for (int n : {1, 3}) {
    Eigen::MatrixXd pi = Eigen::MatrixXd::Constant(n, n, n == 1 ? 1.0 : 0.1);
    if (n == 3) pi.diagonal().setConstant(0.8);
    Imm imm(std::vector<std::shared_ptr<const MotionModel>>(n, cv), pi);
    ImmState s = imm.init(start());
    Gaussian kf = start();
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector2d z(0.3 * k + 0.05, -0.1 * k);
      imm.predict(s, 0.2);
      kalmanPredict(kf, *cv, 0.2);
      Eigen::VectorXd ll(n);
      for (int j = 0; j < n; ++j) ll(j) = kalmanUpdate(s.modes[j], m, z).log_likelihood;
      Imm::updateProbabilities(s, ll);
      kalmanUpdate(kf, m, z);
    }
    const Gaussian c = Imm::combine(s);
    CHECK(c.x.isApprox(kf.x, 1e-9));
    CHECK(c.P.isApprox(kf.P, 1e-9));
    CHECK(s.mu.sum() == Approx(1));
  }
  CHECK_THROWS_AS(Imm({cv, cv}, Eigen::Matrix2d::Constant(0.4)), std::invalid_argument);
}

TEST_CASE("IMM model probabilities follow the likelihoods", "[track]") {
  const auto cv = std::make_shared<ConstantVelocity>(0.1);
  Eigen::Matrix2d pi;
  pi << 0.9, 0.1, 0.2, 0.8;
  Imm imm({cv, cv}, pi);
  ImmState s = imm.init(start(), Eigen::Vector2d(0.5, 0.5));
  imm.predict(s, 0.1);
  CHECK(s.mu(0) == Approx(0.55));  // c = Πᵀ μ = (0.55, 0.45)
  Imm::updateProbabilities(s, Eigen::Vector2d(std::log(2.0), std::log(1.0)));
  CHECK(s.mu(0) == Approx(1.1 / 1.55));
}

TEST_CASE("chi-square gates and their volumes", "[track]") {
  CHECK(gateThreshold(0.99, 2) == Approx(-2 * std::log(0.01)));  // 9.2103
  CHECK(gateThreshold(0.95, 2) == Approx(5.991465));
  CHECK(gateThreshold(0.99, 4) == Approx(13.2767).epsilon(1e-4));
  CHECK(unitBallVolume(2) == Approx(M_PI));
  CHECK(unitBallVolume(3) == Approx(4 * M_PI / 3));
  Eigen::Matrix2d S;
  S << 4, 0, 0, 1;
  CHECK(gateVolume(9.0, S) == Approx(M_PI * 9 * 2));
}

TEST_CASE("PDA weights and the existence update on a hand-made gate", "[track]") {
  const PdaParams p{0.9, 0.99, 0.5};
  const PdaWeights w = pdaWeights(p, {0.2, 0.05}, clutterDensity(p, 2, 1.0));
  // e = 0.9·(0.2, 0.05)/0.5 = (0.36, 0.09), miss = 1 − 0.891 = 0.109, total 0.559.
  CHECK(w.beta0 == Approx(0.109 / 0.559));
  CHECK(w.beta[0] == Approx(0.36 / 0.559));
  CHECK(w.beta[1] == Approx(0.09 / 0.559));
  CHECK(w.delta == Approx(0.891 - 0.45));
  CHECK(existenceUpdate(0.5, w.delta) == Approx(0.559 * 0.5 / (1 - 0.441 * 0.5)));
  CHECK(existenceUpdate(0.5, p.p_detect * p.p_gate) < 0.5);  // a miss lowers existence
  CHECK(existencePredict(0.8, 0.9, 0.05) == Approx(0.73));
  // Non-parametric clutter: (m − P_D P_G P_T) / V.
  const PdaParams np{0.9, 0.99, 0};
  CHECK(clutterDensity(np, 3, 2.0, 1.0) == Approx((3 - 0.891) / 2));
  CHECK(clutterDensity(np, 1, 2.0, 0.5) == Approx((1 - 0.4455) / 2));
  // The PDA update with a single certain measurement is the Kalman update.
  Gaussian a = start(), b = start();
  const LinearMeasurement m = positionMeasurement(4, 0.5);
  PdaWeights one;
  one.beta0 = 0;
  one.beta = {1};
  pdaUpdate(a, m, {Eigen::Vector2d(0.4, 0.2)}, one);
  kalmanUpdate(b, m, Eigen::Vector2d(0.4, 0.2));
  CHECK(a.x.isApprox(b.x));
  CHECK(a.P.isApprox(b.P));
}

TEST_CASE("JPDA shares a measurement between two tracks; PDA does not", "[track]") {
  Eigen::MatrixXd e(2, 2);
  e << 1, 0, 1, 0.5;  // track 0 gates m0; track 1 gates m0 and m1
  const Eigen::Vector2d miss(0.1, 0.1);
  const auto j = jpda(e, miss);
  // Events (t0, t1): (-,-) .01, (-,0) .1, (-,1) .05, (0,-) .1, (0,1) .5 → total .76
  CHECK(j.beta(0, 0) == Approx(0.6 / 0.76));
  CHECK(j.beta(1, 0) == Approx(0.1 / 0.76));
  CHECK(j.beta(1, 1) == Approx(0.55 / 0.76));
  CHECK(j.beta0(1) == Approx(0.11 / 0.76));
  CHECK(j.clusters_enumerated == 1);
  const auto p = independentPda(e, miss);
  CHECK(p.beta(0, 0) == Approx(1 / 1.1));
  CHECK(p.beta(1, 0) == Approx(1 / 1.6));
  CHECK(p.effective_evidence.isApprox(e));
  // The effective evidence reproduces JPDA's weights through the PDA formula.
  const double total = miss(1) + j.effective_evidence.row(1).sum();
  CHECK(j.effective_evidence(1, 1) / total == Approx(j.beta(1, 1)));
  // A single track is plain PDA.
  const auto single = jpda(e.topRows(1), miss.head(1));
  CHECK(single.beta(0, 0) == Approx(1 / 1.1));
}

TEST_CASE("LLR thresholds from alpha_T and beta_T", "[track]") {
  const ExistenceLlr l(0.01, 0.01);
  CHECK(l.confirmThreshold() == Approx(std::log(99.0)));
  CHECK(l.deleteThreshold() == Approx(-std::log(99.0)));
  const ExistenceLlr m(0.001, 0.1);
  CHECK(m.confirmThreshold() == Approx(std::log(0.9 / 0.001)));
  CHECK(m.deleteThreshold() == Approx(std::log(0.1 / 0.999)));
  CHECK(ExistenceLlr::llr(0.5) == Approx(0).margin(1e-12));
  CHECK(l.step(TrackStatus::Tentative, 0.995) == TrackStatus::Confirmed);
  CHECK(l.step(TrackStatus::Tentative, 0.5) == TrackStatus::Tentative);
  CHECK(l.step(TrackStatus::Confirmed, 0.5) == TrackStatus::Confirmed);
  CHECK(l.step(TrackStatus::Confirmed, 0.005) == TrackStatus::Deleted);
  CHECK_THROWS_AS(ExistenceLlr(0, 0.1), std::invalid_argument);
}

TEST_CASE("M-of-N confirms at M hits and deletes after misses", "[track]") {
  MOfN a(2, 3, 2);
  CHECK(a.step(true) == TrackStatus::Tentative);
  CHECK(a.step(false) == TrackStatus::Tentative);
  CHECK(a.step(true) == TrackStatus::Confirmed);
  CHECK(a.step(false) == TrackStatus::Confirmed);
  CHECK(a.step(false) == TrackStatus::Deleted);
  MOfN b(2, 3, 2);
  b.step(false);
  CHECK(b.step(false) == TrackStatus::Deleted);  // 2 hits can no longer come in 3 scans
  const ScoreHysteresis h{0.5, 0.0};
  CHECK(h.accepts(0.6, false));
  CHECK_FALSE(h.accepts(0.3, false));
  CHECK(h.accepts(0.3, true));
  CHECK_FALSE(h.accepts(0.0, true));
}

TEST_CASE("score evidence confirms steady persons, not one high score", "[track]") {
  CHECK(ScoreEvidence::logOdds(0.5) == Approx(0).margin(1e-12));
  CHECK(ScoreEvidence::logOdds(0.9) == Approx(std::log(9.0)));
  CHECK(ScoreEvidence::logOdds(1.0) == 3);  // held within ±3
  CHECK(ScoreEvidence::logOdds(0.0) == -3);
  // Scores of 0.9 (log-odds 2.197) reach 5 at the third scan.
  ScoreEvidence person(5, -1);
  person.add(true, 0.9);
  person.add(true, 0.9);
  CHECK_FALSE(person.confirmed());
  person.add(true, 0.9);
  CHECK(person.confirmed());
  // One 0.99 then scores near 0.5 and a miss: never confirmed; scores of 0.3 refute it.
  ScoreEvidence bush(5, -1);
  bush.add(true, 0.99);
  bush.add(true, 0.55);
  bush.add(false, 0);
  bush.add(true, 0.5);
  CHECK_FALSE(bush.confirmed());
  CHECK(bush.sum() == Approx(ScoreEvidence::logOdds(0.99) + ScoreEvidence::logOdds(0.55) - 1));
  for (int i = 0; i < 6; ++i) bush.add(true, 0.3);
  CHECK(bush.refuted());  // 3 + 0.20 - 1 - 6 x 0.85 <= -2.5
}

TEST_CASE("re-identification's radius and distance to a lost person", "[track]") {
  const Reidentification reid{1.0, 1.0};
  CHECK(reid.radius(0.8, 0.3) == Approx(1.1));  // 0.8 + 1 m/s x 0.3 s
  CHECK(reid.radius(0.8, 5.0) == Approx(1.8));  // grown by at most 1 m
  // Last seen at (0, 0) walking 1 m/s along x: 2 s later (2, 0.5) is 0.5 m from where the
  // velocity carried them, (0, -0.3) 0.3 m from where they were seen.
  const Eigen::Vector2d at(0, 0), v(1, 0);
  CHECK(Reidentification::lostDistance(at, v, 2, {2, 0.5}) == Approx(0.5));
  CHECK(Reidentification::lostDistance(at, v, 2, {0, -0.3}) == Approx(0.3));
}

TEST_CASE("GNN takes the cheapest gated pairs", "[track]") {
  const double c[2][3] = {{1, 5, 9}, {2, 9, 9}};
  const auto a = gnnAssociate(
      2, 3, [&](int t, int m) { return c[t][m]; }, 6);
  CHECK(a.row_to_col[0] == 1);
  CHECK(a.row_to_col[1] == 0);
  CHECK(a.col_to_row[2] == -1);
}

TEST_CASE("a place behind a nearer cluster is hidden", "[track]") {
  Frame f;  // sensor at the origin, looking along x
  Cluster c;
  c.cx = 2;
  c.size_x = c.size_y = 0.4;
  f.clusters.push_back(c);
  const OcclusionMap o(f);
  CHECK(o.hidden(4, 0));
  CHECK(o.hidden(4, 0.3));
  CHECK_FALSE(o.hidden(4, 2));
  CHECK_FALSE(o.hidden(1, 0));    // in front of it
  CHECK_FALSE(o.hidden(2.1, 0));  // the cluster itself
}

TEST_CASE("frame clock and tracks.csv rows", "[track]") {
  FrameClock clock(0.1, 1.0);
  CHECK(clock.step(100.0) == 0.1);
  CHECK(clock.step(100.25) == Approx(0.25));
  CHECK(clock.step(100.2) == 0.1);  // backwards
  CHECK(clock.step(105.0) == 1.0);  // capped
  Gaussian g = start();
  g.P(0, 1) = g.P(1, 0) = 0.3;
  const Track r = trackRow(7, g, ConstantVelocity(1));
  CHECK(r.id == 7);
  CHECK(r.vx == 1);
  CHECK(r.yaw == Approx(0));
  CHECK(r.cov_xy == 0.3);
  CHECK(r.has_cov);
  CHECK(wrapAngle(3 * M_PI) == Approx(M_PI));
  CHECK(wrapAngle(-M_PI) == Approx(M_PI));
}
