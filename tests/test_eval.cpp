// Evaluation metrics on hand-built scenes with hand-derived answers. The assignment solver the
// matching uses: test_assignment.cpp.
#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/eval/detection_pr.h"
#include "pedtrack/eval/evaluate.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::eval;

namespace {

Object obj(long id, double x, double y, bool scored = true) {
  Object o;
  o.id = id;
  o.x = x;
  o.y = y;
  o.scored = scored;
  return o;
}

EvalFrame frame(double t, std::vector<Object> truths, std::vector<Object> estimates) {
  EvalFrame f;
  f.t = t;
  f.truths = std::move(truths);
  f.estimates = std::move(estimates);
  return f;
}

// Two people 10 m apart walking along x for n frames (0.1 m per frame).
Object person(int who, int k) {
  return obj(who, 0.1 * k, who == 1 ? 0.0 : 10.0);
}

}  // namespace

TEST_CASE("truth given as tracks scores perfectly", "[eval]") {
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 20; ++k)
    frames.push_back(
        frame(k * 0.1, {person(1, k), person(2, k)}, {obj(11, 0.1 * k, 0), obj(12, 0.1 * k, 10)}));
  const TrackingReport r = evaluateTracking({frames}, {});
  CHECK(r.clear.truths == 40);
  CHECK(r.clear.matches == 40);
  CHECK(r.clear.mota() == 1.0);
  CHECK(r.clear.motp() == 0.0);
  CHECK(r.clear.id_switches + r.clear.fragmentations + r.clear.false_positives == 0);
  REQUIRE(r.identity);
  CHECK(r.identity->idf1() == 1.0);
  REQUIRE(r.hota);
  CHECK(r.hota->hota() == Approx(1.0));
  CHECK(r.hota->detA() == Approx(1.0));
  CHECK(r.hota->assA() == Approx(1.0));
  CHECK(r.hota->locA() == Approx(1.0));
  CHECK(r.errors.rmse() == 0.0);
  CHECK_FALSE(r.nees);
}

TEST_CASE("an id swap between two distant people: one switch per track, IDF1 and HOTA by hand",
          "[eval]") {
  // Tracks 11/12 follow persons 1/2 for frames 0..5, then swap for frames 6..19.
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 20; ++k) {
    const bool swapped = k >= 6;
    frames.push_back(
        frame(k * 0.1, {person(1, k), person(2, k)},
              {obj(swapped ? 12 : 11, 0.1 * k, 0), obj(swapped ? 11 : 12, 0.1 * k, 10)}));
  }
  const TrackingReport r = evaluateTracking({frames}, {});
  CHECK(r.clear.id_switches == 2);
  CHECK(r.clear.correct == 38);
  CHECK(r.clear.mota() == Approx(1 - 2.0 / 40));
  // Best global pairing: 11↔2 and 12↔1, 14 frames each. IDTP 28, IDFP = IDFN = 40 − 28.
  REQUIRE(r.identity);
  CHECK(r.identity->idtp == 28);
  CHECK(r.identity->idfp == 12);
  CHECK(r.identity->idfn == 12);
  CHECK(r.identity->idf1() == Approx(0.7));
  // HOTA: every detection is a TP at every α (sim 1), so DetA = 1. Pairs (1,11), (2,12) have
  // 6 TPA each, (1,12), (2,11) 14; every id has 20 objects. AssA = Σ TPA² / (40 − TPA) / 40.
  const double ass = (2 * 36.0 / 34 + 2 * 196.0 / 26) / 40;
  REQUIRE(r.hota);
  CHECK(r.hota->detA() == Approx(1.0));
  CHECK(r.hota->assA() == Approx(ass));
  CHECK(r.hota->hota() == Approx(std::sqrt(ass)));
}

TEST_CASE("a track 0.8 m off is one miss and one false positive per frame", "[eval]") {
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 10; ++k) frames.push_back(frame(k, {obj(1, 0, 0)}, {obj(5, 0.8, 0)}));
  const TrackingReport r = evaluateTracking({frames}, {});
  CHECK(r.clear.misses == 10);
  CHECK(r.clear.false_positives == 10);
  CHECK(r.clear.matches == 0);
  CHECK(r.clear.mota() == Approx(-1.0));
  CHECK(std::isnan(r.clear.motp()));
  CHECK(r.identity->idf1() == 0.0);
  // At τ = 1.1 m the similarity is 3/11: a TP for α ≤ 0.25 (the first 5 of 19 α).
  TrackingOptions wide;
  wide.hota_distance = 1.1;
  const TrackingReport h = evaluateTracking({frames}, wide);
  CHECK(h.hota->detA() == Approx(5.0 / 19));
  CHECK(h.hota->assA() == Approx(5.0 / 19));
  CHECK(h.hota->locA() == Approx((5 * 3.0 / 11 + 14) / 19));  // hota.py: LocA 1 without TPs
}

TEST_CASE("fragmentations count interruptions between matches of a truth", "[eval]") {
  // Matched in frames 0-2, 5-6, 8-9; missed in 3-4 and 7: two fragmentations, no switch.
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 10; ++k) {
    const bool tracked = !(k == 3 || k == 4 || k == 7);
    frames.push_back(
        frame(k, {person(1, k)},
              tracked ? std::vector<Object>{obj(5, 0.1 * k, 0)} : std::vector<Object>{}));
  }
  ClearMotCounts c = clearMot(frames, {}).counts;
  CHECK(c.fragmentations == 2);
  CHECK(c.misses == 3);
  CHECK(c.id_switches == 0);
  // Misses before the first match and after the last one are not fragmentations.
  frames.clear();
  for (int k = 0; k < 10; ++k)
    frames.push_back(
        frame(k, {person(1, k)},
              k >= 3 && k <= 6 ? std::vector<Object>{obj(5, 0.1 * k, 0)} : std::vector<Object>{}));
  c = clearMot(frames, {}).counts;
  CHECK(c.fragmentations == 0);
  CHECK(c.misses == 6);
}

TEST_CASE("a kept correspondence wins over a closer track while within the threshold", "[eval]") {
  const std::vector<EvalFrame> frames = {
      frame(0, {obj(1, 0, 0)}, {obj(7, 0, 0)}),
      frame(1, {obj(1, 0, 0)}, {obj(7, 0.5, 0), obj(8, 0.05, 0)}),  // 7 kept, 8 is an FP
      frame(2, {obj(1, 0, 0)}, {obj(7, 0.8, 0), obj(8, 0.05, 0)}),  // 7 too far: 8, a switch
      frame(3, {obj(1, 0, 0)}, {obj(7, 0.1, 0), obj(8, 0.5, 0)}),   // 8 kept now
  };
  const ClearMotResult r = clearMot(frames, {});
  CHECK(r.counts.matches == 4);
  CHECK(r.counts.false_positives == 3);
  CHECK(r.counts.id_switches == 1);
  CHECK(r.counts.motp() == Approx((0 + 0.5 + 0.05 + 0.5) / 4));
  REQUIRE(r.pairs.size() == 4);
  CHECK(r.pairs[1].estimate.id == 7);
  CHECK(r.pairs[2].estimate.id == 8);
  CHECK(r.pairs[3].estimate.id == 8);
}

TEST_CASE("unscored truths absorb tracks but are never missed", "[eval]") {
  // Person 1 is hidden (unscored) in frames 2-4; track 5 coasts on it in 2-3, then nothing in 4.
  // Track 6 takes over in frame 5: judged against the memory (5), an ID switch.
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 7; ++k) {
    const bool hidden = k >= 2 && k <= 4;
    std::vector<Object> est;
    if (k <= 3) est.push_back(obj(5, 0.1 * k, 0));
    if (k >= 5) est.push_back(obj(6, 0.1 * k, 0));
    frames.push_back(frame(k, {obj(1, 0.1 * k, 0, !hidden)}, est));
  }
  const ClearMotResult r = clearMot(frames, {});
  CHECK(r.counts.truths == 4);
  CHECK(r.counts.misses == 0);
  CHECK(r.counts.false_positives == 0);
  CHECK(r.counts.unscored_matches == 2);
  CHECK(r.counts.matches == 4);
  CHECK(r.counts.id_switches == 1);
  CHECK(r.counts.fragmentations == 0);  // hidden frames are not gaps
  // IDF1 and HOTA drop the hidden truth and the tracks it absorbed.
  const auto scored = withoutUnscored(frames, r);
  CHECK(scored[2].truths.empty());
  CHECK(scored[2].estimates.empty());
  const IdentityCounts id = identity(scored, 0.75);
  CHECK(id.idtp == 2);  // 5↔1 and 6↔1 cover 2 frames each; only one pairing counts
  CHECK(id.idfn == 2);
  CHECK(id.idfp == 2);
}

TEST_CASE("visible_points below --min-visible make a truth row unscored", "[eval]") {
  const std::string dir = test::freshDir("eval_visible");
  test::writeFile(dir + "/truth.csv",
                  "t,id,x,y,visible_points\n1.0,1,0,0,0\n1.0,2,1,0,3\n1.0,3,2,0,\n");
  const ObjectTable t = readObjectTable(dir + "/truth.csv");
  auto scored = [&](long min_visible) {
    std::vector<bool> s;
    const auto slices = objectsByTime(t, CoordFrame::Fixed, min_visible);
    for (const Object& o : slices.at(0).objects) s.push_back(o.scored);
    return s;
  };
  CHECK(scored(1) == std::vector<bool>{false, true, true});  // empty column: scored
  CHECK(scored(5) == std::vector<bool>{false, false, true});
  CHECK(scored(0) == std::vector<bool>{true, true, true});
}

TEST_CASE("following mode scores one person and ignores false positives", "[eval]") {
  std::vector<EvalFrame> frames;
  for (int k = 0; k < 10; ++k) {
    std::vector<Object> est = {obj(2, 0.1 * k, 10), obj(9, 5, 5)};  // 2 on person 2, 9 clutter
    if (k < 8) est.push_back(obj(1, 0.1 * k + 0.1, 0));             // person 1 lost at the end
    frames.push_back(frame(k, {person(1, k), person(2, k)}, est));
  }
  TrackingOptions opt;
  opt.following = 1;
  const TrackingReport r = evaluateTracking({frames}, opt);
  CHECK(r.clear.truths == 10);
  CHECK(r.clear.matches == 8);
  CHECK(r.clear.misses == 2);
  CHECK(r.clear.false_positives == 0);
  CHECK(r.clear.unscored_matches == 10);  // track 2 on person 2
  CHECK(r.clear.mota() == Approx(0.8));
  CHECK(r.clear.motp() == Approx(0.1));
  CHECK_FALSE(r.identity);
  CHECK_FALSE(r.hota);
}

TEST_CASE("NEES of a known covariance and offset, and the chi-square regions", "[eval]") {
  CHECK(normalizedSquare(0.2, 0.1, 0.04, 0, 0.01) == Approx(2.0));
  // P = [0.05 0.02; 0.02 0.02], d = (0.1, 0.1): dᵀP⁻¹d = 0.0003 / 0.0006.
  CHECK(normalizedSquare(0.1, 0.1, 0.05, 0.02, 0.02) == Approx(0.5));
  CHECK(std::isnan(normalizedSquare(0.1, 0.1, 0.01, 0.02, 0.01)));  // not positive definite

  // Two-sided 95 % regions of the average of N χ²(2) values (tables: χ²₂, χ²₄, χ²₁₀₀).
  const ChiSquareBounds one = chiSquareBounds(2, 1);
  CHECK(one.lower == Approx(0.0506).epsilon(1e-3));
  CHECK(one.upper == Approx(7.378).epsilon(1e-3));
  const ChiSquareBounds two = chiSquareBounds(2, 2);
  CHECK(two.lower == Approx(0.4844 / 2).epsilon(1e-3));
  CHECK(two.upper == Approx(11.143 / 2).epsilon(1e-3));
  const ChiSquareBounds fifty = chiSquareBounds(2, 50);
  CHECK(fifty.lower == Approx(74.222 / 50).epsilon(1e-3));
  CHECK(fifty.upper == Approx(129.561 / 50).epsilon(1e-3));

  // End to end: a track 0.2 m east, 0.1 m north of the truth with P = diag(0.04, 0.01).
  std::vector<ObjectRow> rows(2);
  rows[1].x = 0.2;
  rows[1].y = 0.1;
  rows[1].cov_xx = 0.04;
  rows[1].cov_xy = 0;
  rows[1].cov_yy = 0.01;
  rows[1].nis = 3.5;
  Object t = obj(1, 0, 0), e = obj(4, 0.2, 0.1);
  t.row = &rows[0];
  e.row = &rows[1];
  const ClearMotResult cm = clearMot({frame(0, {t}, {e}), frame(1, {t}, {e})}, {});
  const auto nees = neesSamples(cm.pairs);
  REQUIRE(nees.size() == 2);
  CHECK(nees[0].value == Approx(2.0));
  const ConsistencyReport rep = consistency(nees, 2, 1);
  CHECK(rep.mean == Approx(2.0));
  CHECK(rep.fraction_inside == 1.0);
  CHECK(rep.mean_bounds.lower == Approx(chiSquareBounds(2, 2).lower));
  CHECK(nisSamples(cm.pairs)[1].value == 3.5);
}

TEST_CASE("Monte Carlo consistency averages each truth and frame over the runs", "[eval]") {
  // Truth 1, frame 0: runs give 1 and 9 (mean 5, inside [0.242, 5.572]); frame 1: 9 and 9
  // (mean 9, outside). Truth 2, frame 0: only one run matched it: 0.01 against the N=1 region.
  const std::vector<ConsistencySample> s = {
      {1, 0, 1.0}, {1, 0, 9.0}, {1, 1, 9.0}, {1, 1, 9.0}, {2, 0, 0.01}};
  const ConsistencyReport r = consistency(s, 2, 2);
  REQUIRE(r.points.size() == 3);
  CHECK(r.points[0].mean == 5.0);
  CHECK(r.points[0].n == 2);
  CHECK(r.points[0].inside);
  CHECK_FALSE(r.points[1].inside);
  CHECK(r.points[2].n == 1);
  CHECK_FALSE(r.points[2].inside);  // 0.01 < 0.0506
  CHECK(r.fraction_inside == Approx(1.0 / 3));
  CHECK(r.mean == Approx(28.01 / 5));
  CHECK(r.nominal_bounds.upper == Approx(11.143 / 2).epsilon(1e-3));
  REQUIRE(r.per_truth.size() == 2);
  CHECK(r.per_truth[0].mean == Approx(7.0));
  CHECK(r.per_truth[0].fraction_inside == Approx(0.5));
}

TEST_CASE("detection precision and recall with per-scan matching", "[eval]") {
  // Frame 0: truths (0,0), (1,0); detections 0.05 off the first, 0.3 off the second, clutter.
  // Frame 1: truth only (a miss). Frame 2: a detection only (an FP). Frame 3: an unscored
  // truth absorbs its detection.
  const std::vector<EvalFrame> frames = {
      frame(0, {obj(0, 0, 0), obj(1, 1, 0)}, {obj(0, 0.05, 0), obj(1, 1.3, 0), obj(2, 4, 4)}),
      frame(1, {obj(0, 0, 0)}, {}),
      frame(2, {}, {obj(0, 2, 2)}),
      frame(3, {obj(0, 0, 0, false)}, {obj(0, 0.02, 0)}),
  };
  const DetectionCounts c = detectionPR(frames, 0.1);
  CHECK(c.tp == 1);
  CHECK(c.fp == 3);
  CHECK(c.fn == 2);
  CHECK(c.unscored_matches == 1);
  CHECK(c.precision() == Approx(0.25));
  CHECK(c.recall() == Approx(1.0 / 3));
  CHECK(c.f1() == Approx(2.0 / 7));
  CHECK(c.meanDistance() == Approx(0.05));
}

TEST_CASE("frames are the union of truth and estimate times", "[eval]") {
  const std::vector<TimedObjects> truth = {{1.0, {obj(1, 0, 0)}}, {1.1, {obj(1, 0, 0)}}};
  const std::vector<TimedObjects> est = {{1.00005, {obj(3, 0, 0)}}, {1.2, {obj(3, 0, 0)}}};
  const auto f = alignFrames(truth, est);
  REQUIRE(f.size() == 3);
  CHECK(f[0].truths.size() == 1);
  CHECK(f[0].estimates.size() == 1);
  CHECK(f[1].estimates.empty());
  CHECK(f[2].truths.empty());
  CHECK(f[2].t == 1.2);
}

TEST_CASE("detections.csv reads with ids numbered within each frame", "[eval]") {
  const std::string dir = test::freshDir("eval_detections_table");
  test::writeFile(dir + "/d.csv",
                  "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta\n"
                  "1.0,0,1,2,1,2,0.9,,,\n1.0,0,3,4,3,4,0.8,0.1,0.2,0.1\n2.0,1,5,6,5,6,0.7,,,\n");
  const ObjectTable t = readDetectionTable(dir + "/d.csv");
  REQUIRE(t.rows.size() == 3);
  CHECK(t.rows[0].id == 0);
  CHECK(t.rows[1].id == 1);
  CHECK(t.rows[2].id == 0);
  CHECK(t.rows[1].alpha == 0.2);
  CHECK(std::isnan(t.rows[0].yaw));
  CHECK_THROWS_AS(readObjectTable(dir + "/d.csv"), ConfigError);  // tracks need an id
}

namespace {

// Matched pairs of one truth and one track per frame, from rows the caller owns: the track row
// `k` at (x, 0) with the given yaw, the truth row at the same place with yaw `truth_yaw`.
std::vector<MatchedPair> headingPairs(std::vector<ObjectRow>& rows,
                                      const std::vector<std::pair<double, double>>& yaws) {
  rows.assign(2 * yaws.size(), ObjectRow());
  std::vector<MatchedPair> pairs;
  for (std::size_t k = 0; k < yaws.size(); ++k) {
    rows[2 * k].yaw = yaws[k].first;       // truth
    rows[2 * k + 1].yaw = yaws[k].second;  // track
    MatchedPair p;
    p.frame = k;
    p.truth = obj(1, double(k), 0);
    p.estimate = obj(7, double(k), 0);
    p.truth.row = &rows[2 * k];
    p.estimate.row = &rows[2 * k + 1];
    pairs.push_back(p);
  }
  return pairs;
}

}  // namespace

TEST_CASE("heading RMSE: a constant offset, the wrap-around at pi, rows without yaw",
          "[eval][heading]") {
  std::vector<ObjectRow> rows;
  // The track faces 0.1 rad left of the person in every frame.
  const PairErrors constant = pairErrors(headingPairs(rows, {{0, 0.1}, {1, 1.1}, {-2, -1.9}}));
  CHECK(constant.heading_pairs == 3);
  CHECK(constant.headingRmse() == Approx(0.1));
  CHECK(constant.headingMae() == Approx(0.1));
  CHECK(constant.axisRmse() == Approx(0.1));  // under π/2: the axis error is the heading error
  // yaw 3.1 against −3.1: 0.0832 rad apart across ±π, not 6.2.
  const PairErrors wrap = pairErrors(headingPairs(rows, {{-3.1, 3.1}}));
  CHECK(wrap.headingRmse() == Approx(2 * M_PI - 6.2).epsilon(1e-9));
  CHECK(wrap.headingRmse() == Approx(0.083).margin(5e-4));
  CHECK(wrap.axisRmse() == Approx(2 * M_PI - 6.2).epsilon(1e-9));
  // Errors 0.3 and 0.4: RMSE √((0.09 + 0.16) / 2), MAE 0.35; a track row without yaw is skipped.
  const PairErrors mixed = pairErrors(headingPairs(rows, {{0, 0.3}, {0, -0.4}, {0, NAN}}));
  CHECK(mixed.pairs == 3);
  CHECK(mixed.heading_pairs == 2);
  CHECK(mixed.headingRmse() == Approx(std::sqrt(0.125)));
  CHECK(mixed.headingMae() == Approx(0.35));
  CHECK(mixed.axisRmse() == Approx(std::sqrt(0.125)));
  PairErrors sum = constant;
  sum += wrap;
  CHECK(sum.headingRmse() == Approx(std::sqrt((3 * 0.01 + std::pow(2 * M_PI - 6.2, 2)) / 4)));
  CHECK(sum.axisRmse() == Approx(std::sqrt((3 * 0.01 + std::pow(2 * M_PI - 6.2, 2)) / 4)));
  const PairErrors none = pairErrors(headingPairs(rows, {{0, NAN}}));
  CHECK(std::isnan(none.headingRmse()));
  CHECK(std::isnan(none.axisRmse()));
}

TEST_CASE("axis RMSE: the heading error modulo pi, front and back alike (P0 Table I)",
          "[eval][heading]") {
  std::vector<ObjectRow> rows;
  // The track faces backwards: heading error π, the axis is right.
  const PairErrors flip = pairErrors(headingPairs(rows, {{0.5, 0.5 + M_PI}}));
  CHECK(flip.heading_pairs == 1);
  CHECK(flip.headingRmse() == Approx(M_PI));
  CHECK(flip.axisRmse() == Approx(0).margin(1e-12));
  // d = π/2 + 0.1: e = d − π·round(d/π) = d − π = −(π/2 − 0.1).
  const PairErrors quarter = pairErrors(headingPairs(rows, {{0.2, 0.2 + M_PI / 2 + 0.1}}));
  CHECK(quarter.headingRmse() == Approx(M_PI / 2 + 0.1));
  CHECK(quarter.axisRmse() == Approx(M_PI / 2 - 0.1));
  // Across ±π: yaw −2 against 2, d = wrap(−4) = 2π − 4, e = d − π = π − 4.
  const PairErrors across = pairErrors(headingPairs(rows, {{2, -2}}));
  CHECK(across.headingRmse() == Approx(2 * M_PI - 4));
  CHECK(across.axisRmse() == Approx(4 - M_PI));
  // Pooled, over the same pairs as the heading RMSE; a row without yaw is skipped.
  const PairErrors both =
      pairErrors(headingPairs(rows, {{0.5, 0.5 + M_PI}, {0.2, 0.2 + M_PI / 2 + 0.1}, {0, NAN}}));
  CHECK(both.heading_pairs == 2);
  CHECK(both.headingRmse() == Approx(std::sqrt((M_PI * M_PI + std::pow(M_PI / 2 + 0.1, 2)) / 2)));
  CHECK(both.axisRmse() == Approx(std::sqrt(std::pow(M_PI / 2 - 0.1, 2) / 2)));
  PairErrors sum = flip;
  sum += quarter;
  sum += across;
  CHECK(sum.axisRmse() ==
        Approx(std::sqrt((std::pow(M_PI / 2 - 0.1, 2) + std::pow(4 - M_PI, 2)) / 3)));
}

TEST_CASE("body-axis MAE: the position error along and across the truth heading (P3 Table 1)",
          "[eval][heading]") {
  // One pair per entry: the truth at the origin facing `yaw`, the estimate offset by (dx, dy) in
  // the fixed frame. Sagittal = |(dx, dy)·(cos yaw, sin yaw)|, frontal = |(dx, dy)·(−sin, cos)|.
  struct Case {
    double yaw, dx, dy;
  };
  auto errors = [](std::vector<ObjectRow>& rows, const std::vector<Case>& cases) {
    rows.assign(2 * cases.size(), ObjectRow());
    std::vector<MatchedPair> pairs;
    for (std::size_t k = 0; k < cases.size(); ++k) {
      rows[2 * k].yaw = cases[k].yaw;  // truth at (0, 0); the track row has no yaw
      rows[2 * k + 1].x = cases[k].dx;
      rows[2 * k + 1].y = cases[k].dy;
      MatchedPair p;
      p.frame = k;
      p.truth = obj(1, 0, 0);
      p.estimate = obj(7, cases[k].dx, cases[k].dy);
      p.truth.row = &rows[2 * k];
      p.estimate.row = &rows[2 * k + 1];
      pairs.push_back(p);
    }
    return pairErrors(pairs);
  };
  std::vector<ObjectRow> rows;
  // Facing +y (90°): the 0.2 m along y is straight ahead, the 0.1 m along x to the side. The
  // track row has no yaw: the pair still counts (only the truth's heading is needed).
  const PairErrors up = errors(rows, {{M_PI / 2, 0.1, 0.2}});
  CHECK(up.body_pairs == 1);
  CHECK(up.heading_pairs == 0);
  CHECK(up.sagittalMae() == Approx(0.2));
  CHECK(up.frontalMae() == Approx(0.1));
  // Facing 45°: (0.3, 0.3) is 0.3·√2 ahead and nothing across; (0.3, −0.3) the other way round.
  // Facing 180°, (−0.5, 0): 0.5 ahead (the sign of the component does not matter).
  const PairErrors mixed =
      errors(rows, {{M_PI / 4, 0.3, 0.3}, {M_PI / 4, 0.3, -0.3}, {M_PI, -0.5, 0}});
  CHECK(mixed.body_pairs == 3);
  CHECK(mixed.sagittalMae() == Approx((0.3 * std::sqrt(2.0) + 0 + 0.5) / 3));
  CHECK(mixed.frontalMae() == Approx(0.3 * std::sqrt(2.0) / 3));
  // A truth without yaw is left out of the body-axis errors, not of the position errors.
  const PairErrors none = errors(rows, {{NAN, 0.1, 0.2}});
  CHECK(none.pairs == 1);
  CHECK(none.body_pairs == 0);
  CHECK(std::isnan(none.sagittalMae()));
  CHECK(std::isnan(none.frontalMae()));
  // Pooling adds the sums over the 1 + 3 + 0 body pairs.
  PairErrors sum = up;
  sum += mixed;
  sum += none;
  CHECK(sum.body_pairs == 4);
  CHECK(sum.sagittalMae() == Approx((0.2 + 0.3 * std::sqrt(2.0) + 0.5) / 4));
  CHECK(sum.frontalMae() == Approx((0.1 + 0.3 * std::sqrt(2.0)) / 4));
}

TEST_CASE("range bands: errors, semi-axes and model probabilities per distance from the sensor",
          "[eval][range]") {
  // Tracks at ranges 5, 8 (band 0-10), 15 (10-20), 35 and 50 (30-inf), one without a sensor
  // position (unbanded), one at 25 (20-30) without shape or probabilities.
  struct Spec {
    double range, dx, yaw, alpha, beta;
    std::vector<double> probs;
  };
  const std::vector<Spec> specs = {{5, 0.1, 0.1, 0.20, 0.10, {0.9, 0.1}},
                                   {8, 0.3, 0.3, 0.30, 0.14, {0.7, 0.3}},
                                   {15, 0.2, 0.0, 0.25, 0.12, {0.2, 0.8}},
                                   {35, 0.4, NAN, 0.22, 0.11, {0.5, 0.2, 0.3}},
                                   {50, 0.0, NAN, 0.26, 0.13, {0.1, 0.6, 0.3}},
                                   {NAN, 0.1, 0.1, 0.2, 0.1, {1, 0}},
                                   {25, 0.5, NAN, NAN, NAN, {}}};
  std::vector<ObjectRow> rows(2 * specs.size());
  std::vector<std::vector<double>> probs(rows.size());
  std::vector<MatchedPair> pairs;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const Spec& s = specs[k];
    ObjectRow& t = rows[2 * k];
    ObjectRow& e = rows[2 * k + 1];
    t.yaw = 0;
    e.sensor_x = s.range * 0.6;  // (0.6, 0.8) × range: the range is the hypotenuse
    e.sensor_y = s.range * 0.8;
    e.yaw = s.yaw;
    e.alpha = s.alpha;
    e.beta = s.beta;
    probs[2 * k + 1] = s.probs;
    MatchedPair p;
    p.frame = k;
    p.truth = obj(1, 0, 0);
    p.estimate = obj(7, s.dx, 0);
    p.truth.row = &t;
    p.estimate.row = &e;
    pairs.push_back(p);
  }
  const ModelProbsOf of = [&](const ObjectRow& r) -> const std::vector<double>* {
    const auto& v = probs[std::size_t(&r - rows.data())];
    return v.empty() ? nullptr : &v;
  };
  const RangeBandReport r = rangeBands(pairs, {0, 10, 20, 30}, of);
  REQUIRE(r.bands.size() == 4);
  CHECK(r.unbanded == 1);
  CHECK(r.models == 3);
  CHECK(r.bands[0].from == 0);
  CHECK(r.bands[0].to == 10);
  CHECK(std::isinf(r.bands[3].to));

  const RangeBand& near = r.bands[0];
  CHECK(near.errors.pairs == 2);
  CHECK(near.errors.rmse() == Approx(std::sqrt((0.01 + 0.09) / 2)));
  CHECK(near.errors.headingRmse() == Approx(std::sqrt((0.01 + 0.09) / 2)));
  CHECK(near.shape_rows == 2);
  CHECK(near.alphaMean() == Approx(0.25));
  CHECK(near.alpha_min == Approx(0.20));
  CHECK(near.alpha_max == Approx(0.30));
  CHECK(near.betaMean() == Approx(0.12));
  CHECK(near.probMean(0) == Approx(0.8));
  CHECK(near.probMean(1) == Approx(0.2));
  CHECK(std::isnan(near.probMean(2)));  // no row of the band has a third model

  CHECK(r.bands[1].errors.pairs == 1);
  CHECK(r.bands[1].probMean(1) == Approx(0.8));
  // 20-30: a match without shape, yaw or probabilities.
  CHECK(r.bands[2].errors.pairs == 1);
  CHECK(r.bands[2].errors.rmse() == Approx(0.5));
  CHECK(r.bands[2].shape_rows == 0);
  CHECK(std::isnan(r.bands[2].alphaMean()));
  CHECK(std::isnan(r.bands[2].errors.headingRmse()));
  CHECK(std::isnan(r.bands[2].probMean(0)));
  // 30-inf: two rows, three models each.
  const RangeBand& far = r.bands[3];
  CHECK(far.errors.pairs == 2);
  CHECK(far.errors.heading_pairs == 0);
  CHECK(far.alphaMean() == Approx(0.24));
  CHECK(far.beta_max == Approx(0.13));
  CHECK(far.probMean(0) == Approx(0.3));
  CHECK(far.probMean(1) == Approx(0.4));
  CHECK(far.probMean(2) == Approx(0.3));

  // Without a model-probability source, or with the first edge beyond the near rows.
  const RangeBandReport plain = rangeBands(pairs, {10, 30});
  CHECK(plain.models == 0);
  CHECK(plain.unbanded == 3);  // ranges 5, 8 and the one without a sensor position
  CHECK(plain.bands[0].errors.pairs == 2);
  CHECK(plain.bands[1].errors.pairs == 2);
}
