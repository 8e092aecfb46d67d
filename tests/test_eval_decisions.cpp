// Person / non-person decisions against the per-point truth (P2 Tables 1 and 2): a hand-made run
// of four frames with every kind of sample, matrices computed by hand; the tie rule; the
// `cluster` column of the CSV reader; and `pedtrack eval --decisions` on good and bad input.
#include <mrpt/core/format.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/eval/decisions.h"
#include "pedtrack/eval/object_table.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::eval;

namespace {

constexpr std::int32_t G = run_label::kGround, U = run_label::kUnclustered;

LabelFrame frame(std::uint64_t index, std::vector<std::int32_t> labels) {
  LabelFrame f;
  f.index = index;
  f.t = 1000 + 0.1 * double(index);
  f.labels = std::move(labels);
  return f;
}

// Persons 1, 2, 3; objects 1 (-1), 2 (-2); ground 0.
// Frame 0: c0 person 1 (4) + ground (1); c1 object 1; c2 person 2 (2) + object 2 (3): object;
//          c3 ground; c4 person 2, no detection; one person-1 point unclustered.
// Frame 1: c0 person 2; c1 person 1; c2 object 1.
// Frame 2: in the truth only (the run failed it).
// Frame 3: c0 person 1 and c1 object 2, no detections; person 3 hit but unclustered.
LabelFrame truth(int k) {
  switch (k) {
    case 0:
      return frame(0, {1, 1, 1, 1, 0, -1, -1, -1, 2, 2, -2, -2, -2, 0, 0, 0, 2, 2, 1, 0});
    case 1:
      return frame(1, {2, 2, 2, 1, 1, 1, -1, -1, 0});
    case 2:
      return frame(2, {1, 1, 0});
    default:
      return frame(3, {1, 1, -2, -2, 3});
  }
}
LabelFrame run(int k) {
  switch (k) {
    case 0:
      return frame(0, {0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 4, 4, U, G});
    case 1:
      return frame(1, {0, 0, 0, 1, 1, 1, 2, 2, G});
    default:
      return frame(3, {0, 0, 1, 1, U});
  }
}

// Frame 0: c0 0.9, c1 0.6, c2 0.3, c3 0.1. Frame 1: c0 0.7, c1 0.4 and again 0.45, c2 0.2, one
// detection without a cluster, one on cluster 7 (no points). Frame 2 (not in the run's labels):
// one detection.
std::string detectionsCsv(bool with_cluster = true) {
  std::string s = "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta";
  s += with_cluster ? ",cluster\n" : "\n";
  const std::vector<std::tuple<int, int, double>> rows = {
      {0, 0, 0.9},  {0, 1, 0.6}, {0, 2, 0.3},  {0, 3, 0.1}, {1, 0, 0.7}, {1, 1, 0.4},
      {1, 1, 0.45}, {1, 2, 0.2}, {1, -1, 0.8}, {1, 7, 0.9}, {2, 0, 0.9}};
  for (const auto& [f, c, score] : rows) {
    s += mrpt::format("%.6f,%d,1,2,1,2,%.2f,,,", 1000 + 0.1 * f, f, score);
    if (with_cluster) s += c >= 0 ? "," + std::to_string(c) : ",";
    s += "\n";
  }
  return s;
}

// Frame 0: confirmed on c0 and c2, tentative on c1. Frame 1: tentative on c0, confirmed on c1 and
// c2, confirmed coasting (no cluster). Frame 3: confirmed on c0 (which has no detection).
std::string tracksCsv() {
  std::string s = "t,frame,track,x,y,status,cluster\n";
  const std::vector<std::tuple<int, int, const char*, int>> rows = {
      {0, 1, "confirmed", 0},  {0, 2, "confirmed", 2}, {0, 3, "tentative", 1},
      {1, 4, "tentative", 0},  {1, 1, "confirmed", 1}, {1, 3, "confirmed", 2},
      {1, 2, "confirmed", -1}, {3, 1, "confirmed", 0}};
  for (const auto& [f, id, status, c] : rows)
    s += mrpt::format("%.6f,%d,%d,1,2,%s,", 1000 + 0.1 * f, f, id, status) +
         (c >= 0 ? std::to_string(c) : std::string()) + "\n";
  return s;
}

std::string writeRun(const std::string& tag) {
  const std::string dir = test::freshDir(tag);
  {
    LabelFileWriter t(dir + "/truth_points.bin", LabelKind::Truth);
    LabelFileWriter r(dir + "/point_labels.bin", LabelKind::Run);
    for (int k = 0; k < 4; ++k) {
      t.write(truth(k));
      if (k != 2) r.write(run(k));
    }
  }
  test::writeFile(dir + "/detections.csv", detectionsCsv());
  test::writeFile(dir + "/tracks.csv", tracksCsv());
  return dir;
}

DecisionInputs inputs(const std::string& dir) {
  return {dir + "/truth_points.bin", dir + "/point_labels.bin", dir + "/detections.csv",
          dir + "/tracks.csv"};
}

void checkMatrix(const DecisionMatrix& m, std::size_t tn, std::size_t fp, std::size_t fn,
                 std::size_t tp) {
  CHECK(m.tn == tn);
  CHECK(m.fp == fp);
  CHECK(m.fn == fn);
  CHECK(m.tp == tp);
}

}  // namespace

TEST_CASE("decisions: hand-made run, per cluster and per object", "[eval][decisions]") {
  const std::string dir = writeRun("eval_decisions");
  const DecisionReport r = evaluateDecisions(inputs(dir), DecisionOptions());
  CHECK(r.frames == 3);
  CHECK(r.truth_only_frames == 1);
  CHECK(r.frames_without_detections == 1);  // frame 3
  CHECK(r.clusters == 10);
  CHECK(r.clusters_scored == 7);
  CHECK(r.unscored_person == 2);     // frame 0 c4, frame 3 c0
  CHECK(r.unscored_nonperson == 1);  // frame 3 c1
  CHECK(r.scored_ground == 1);
  CHECK(r.detections == 10);
  CHECK(r.detections_without_cluster == 1);
  CHECK(r.detections_unknown_cluster == 1);
  CHECK(r.detections_duplicate == 1);
  CHECK(r.detection_frames_unmatched == 1);  // frame 2
  CHECK(r.track_rows_person == 6);
  CHECK(r.track_rows_without_cluster == 1);
  CHECK(r.track_clusters_unscored == 1);
  CHECK(r.min_score == Approx(0.1));
  CHECK(r.max_score == Approx(0.9));

  // (a) appearance: TP f0c0, f1c0; FN f1c1 (0.45); FP f0c1; TN f0c2, f0c3, f1c2.
  checkMatrix(r.per_cluster.appearance, 3, 1, 1, 2);
  // complete: TP f0c0, f1c1; FN f1c0 (tentative); FP f0c2, f1c2; TN f0c1 (tentative), f0c3.
  checkMatrix(r.per_cluster.complete, 2, 2, 1, 2);
  CHECK(r.per_cluster.appearance.detectionRate() == Approx(2.0 / 3));
  CHECK(r.per_cluster.appearance.falsePositiveRate() == Approx(0.25));
  CHECK(r.per_cluster.appearance.precision() == Approx(2.0 / 3));
  CHECK(r.per_cluster.appearance.accuracy() == Approx(5.0 / 7));
  CHECK(r.per_cluster.complete.falsePositiveRate() == Approx(0.5));

  // Per object: person 1 frames 0 (app, complete), 1 (complete); person 2 frame 1 (app);
  // object 1 frames 0 (app), 1 (complete); object 2 frame 0 (complete); person 3 never scored.
  REQUIRE(r.per_object.size() == 5);
  const std::vector<std::int32_t> ids = {1, 2, 3, -1, -2};
  const std::vector<std::array<std::size_t, 4>> want = {
      {3, 2, 1, 2}, {2, 1, 1, 0}, {1, 0, 0, 0}, {2, 2, 1, 1}, {2, 1, 0, 1}};
  for (std::size_t i = 0; i < ids.size(); ++i) {
    INFO("id " << ids[i]);
    CHECK(r.per_object[i].id == ids[i]);
    CHECK(r.per_object[i].hit_frames == want[i][0]);
    CHECK(r.per_object[i].frames == want[i][1]);
    CHECK(r.per_object[i].appearance_frames == want[i][2]);
    CHECK(r.per_object[i].complete_frames == want[i][3]);
  }
  CHECK(r.persons_never_scored == 1);
  CHECK(r.objects_never_scored == 0);
  // At least one frame: appearance persons 1, 2 and object 1; complete person 1, objects 1, 2.
  checkMatrix(r.per_object_any.appearance, 1, 1, 0, 2);
  checkMatrix(r.per_object_any.complete, 0, 2, 1, 1);
  // More than half of the frames: appearance person 2 only; complete person 1 and object 2.
  checkMatrix(r.per_object_majority.appearance, 2, 0, 1, 1);
  checkMatrix(r.per_object_majority.complete, 1, 1, 1, 1);

  // A lower Q_P passes f1c1 (0.45, the higher of its two detections).
  DecisionOptions o;
  o.q_person = 0.45;
  checkMatrix(evaluateDecisions(inputs(dir), o).per_cluster.appearance, 3, 1, 0, 3);
  // Tentative tracks decide instead: f0c1 (object 1) and f1c0 (person 2).
  o.person_status = "tentative";
  checkMatrix(evaluateDecisions(inputs(dir), o).per_cluster.complete, 3, 1, 2, 1);
}

TEST_CASE("decisions: majority owner ties, no tracks, ground-only clusters", "[eval][decisions]") {
  // c0: person 4 and object 1 two points each (tie: the person); c1: ground 2, object 3 1.
  const LabelFrame t = frame(0, {4, 4, -1, -1, 0, 0, -3});
  const LabelFrame rl = frame(0, {0, 0, 0, 0, 1, 1, 1});
  FrameDecisionInput in;
  in.detections = {{0, 0.2}, {1, 0.9}};
  DecisionReport r;
  scoreDecisionFrame(t, rl, in, DecisionOptions(), r);
  finishDecisions(r);
  checkMatrix(r.per_cluster.appearance, 0, 1, 1, 0);
  checkMatrix(r.per_cluster.complete, 1, 0, 1, 0);  // no tracks: nothing decided a person
  CHECK(r.scored_ground == 1);
  // Per object: person 4 owns c0; objects 1 and 3 were hit but own nothing; the ground is no
  // object.
  checkMatrix(r.per_object_any.appearance, 0, 0, 1, 0);
  CHECK(r.persons_never_scored == 0);
  CHECK(r.objects_never_scored == 2);
}

TEST_CASE("object tables keep the cluster column, and do without it", "[eval][decisions]") {
  const std::string dir = test::freshDir("eval_decisions_tables");
  test::writeFile(dir + "/d.csv", detectionsCsv());
  test::writeFile(dir + "/old.csv", detectionsCsv(false));
  const ObjectTable d = readDetectionTable(dir + "/d.csv");
  REQUIRE(d.rows.size() == 11);
  CHECK(d.rows[2].cluster == 2);
  CHECK(d.rows[8].cluster == -1);  // empty
  const ObjectTable old = readDetectionTable(dir + "/old.csv");
  CHECK_FALSE(old.hasColumn("cluster"));
  CHECK(old.rows[2].cluster == -1);
  // Without the column the decisions cannot be scored: one line naming file and column.
  const std::string run_dir = writeRun("eval_decisions_old");
  test::writeFile(run_dir + "/detections.csv", detectionsCsv(false));
  CHECK_THROWS_WITH(evaluateDecisions(inputs(run_dir), DecisionOptions()),
                    Catch::Contains("detections.csv: header lacks column 'cluster'"));
}

TEST_CASE("pedtrack eval --decisions: tables, JSON, bad input", "[eval][decisions][cli]") {
  const std::string dir = writeRun("eval_decisions_cli");
  auto r = test::runHost({"eval", "--decisions", dir});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("appearance (score >= 0.50)") != std::string::npos);
  CHECK(r.output.find("1 persons, 0 objects the scans hit") != std::string::npos);
  r = test::runHost({"eval", "--decisions", dir, "--json", "--q-person", "0.45"});
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("\"per_cluster\": {\"appearance\": {\"tn\": 3, \"fp\": 1, \"fn\": 0, "
                      "\"tp\": 3") != std::string::npos);

  const std::string bad = writeRun("eval_decisions_cli_bad");
  test::writeFile(bad + "/detections.csv", detectionsCsv(false));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--decisions", bad}, "detections.csv: header lacks column 'cluster'"},
      {{"--decisions", dir + "/nowhere"}, "no such run directory"},
      {{"--decisions", dir, "--truth-points", dir + "/none.bin"}, "none.bin: missing"},
      {{"--decisions", dir, "--truth-points", dir + "/point_labels.bin"}, "not a truth file"},
  };
  for (const auto& [args, expected] : cases) {
    std::vector<std::string> all = {"eval"};
    all.insert(all.end(), args.begin(), args.end());
    const auto b = test::runHost(all);
    INFO(b.output);
    CHECK(b.exit_code == 2);
    CHECK(b.output.find(expected) != std::string::npos);
    CHECK(test::lines(b.output).size() == 1);
  }
  // A run directory without the sim source's truth.
  const std::string no_truth = test::freshDir("eval_decisions_cli_no_truth");
  const auto b = test::runHost({"eval", "--decisions", no_truth});
  CHECK(b.exit_code == 2);
  CHECK(b.output.find(no_truth + "/truth_points.bin: missing") != std::string::npos);
}
