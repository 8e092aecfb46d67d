// `pedtrack montecarlo`: the scoring of runs together on synthetic tracks and truth (RMSE per
// frame, pooled NEES against its bounds, ID switches per run), the plots, and the command as a
// user runs it on a short simulation: files, report, parallel runs equal to serial ones, errors.
#include <mrpt/core/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "montecarlo_compare.h"
#include "montecarlo_plots.h"
#include "montecarlo_score.h"
#include "pedtrack/errors.h"
#include "plot.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
namespace fs = std::filesystem;

namespace {

const char* kTruthHeader = "t,frame,id,x,y,yaw,vx,vy,visible_points\n";
const char* kTracksHeader = "t,frame,track,x,y,vx,vy,cov_xx,cov_xy,cov_yy,nis\n";

// Person 1 walks along y = 0 for 10 frames at 10 Hz.
std::string truthCsv() {
  std::string s = kTruthHeader;
  for (int k = 0; k < 10; ++k)
    s += mrpt::format("%.6f,%d,1,%.4f,0,0,1,0,40\n", 100 + 0.1 * k, k, 0.1 * k);
  return s;
}

// One track `dx` east of the person, covariance diag(0.01, 0.01), nis 2; the track id becomes
// `second_id` from frame 5 (an ID switch) and frame `skip` has no track.
std::string tracksCsv(double dx, long second_id = 7, int skip = -1) {
  std::string s = kTracksHeader;
  for (int k = 0; k < 10; ++k) {
    if (k == skip) continue;
    s += mrpt::format("%.6f,%d,%ld,%.4f,0,1,0,0.01,0,0.01,2\n", 100 + 0.1 * k, k,
                      k < 5 ? 7L : second_id, 0.1 * k + dx);
  }
  return s;
}

// A short P4-like scene: one person on a circle in front of a torso-height scanner, 4 s at 5 Hz.
std::string shortScenario(const std::string& dir) {
  const std::string path = dir + "/short_circle.ini";
  writeFile(path,
            "[scenario]\ndescription = test circle\nduration = 4\nseed = 3\n\n"
            "[sensor]\nmodel = utm30lx\nz = 1.1\nrate = 5\n\n"
            "[person.1]\nx = 4\ny = -2\nyaw = 0\npath = circle\nradius = 2\nspeed = 1.0\n");
  return path;
}

std::string config(const std::string& name) {
  return std::string(PEDTRACK_SOURCE_DIR) + "/configs/" + name;
}

}  // namespace

TEST_CASE("montecarlo scoring: RMSE per frame, pooled NEES, ID switches per run", "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_score");
  writeFile(dir + "/truth.csv", truthCsv());
  writeFile(dir + "/a.csv", tracksCsv(0.1));
  writeFile(dir + "/b.csv", tracksCsv(-0.1, 7, 3));  // no track in frame 3
  writeFile(dir + "/c.csv", tracksCsv(0.2, 9));      // track 9 takes over at frame 5
  const std::string truth = dir + "/truth.csv";
  eval::TrackingOptions opt;
  const cli::MonteCarloScore s = cli::scoreMonteCarlo(
      {truth, truth, truth}, {dir + "/a.csv", dir + "/b.csv", dir + "/c.csv"}, opt);

  REQUIRE(s.runs.size() == 3);
  CHECK(s.track_rows == 29);
  CHECK(s.runs[0].id_switches == 0);
  CHECK(s.runs[1].id_switches == 0);
  CHECK(s.runs[2].id_switches == 1);
  CHECK(s.runsWithoutSwitch() == 2);
  REQUIRE(s.tracking);
  CHECK(s.tracking->runs == 3);
  CHECK(s.tracking->clear.id_switches == 1);
  CHECK(s.t0 == Approx(100));

  REQUIRE(s.points.size() == 10);
  const cli::FramePoint& p0 = s.points[0];
  CHECK(p0.truth_id == 1);
  CHECK(p0.frame == 0);
  CHECK(p0.n == 3);
  CHECK(p0.t == Approx(100));
  CHECK(p0.rmse_x == Approx(std::sqrt((0.01 + 0.01 + 0.04) / 3)));
  CHECK(p0.rmse_y == Approx(0).margin(1e-12));
  CHECK(p0.rmse == Approx(p0.rmse_x));
  // NEES dx²/0.01 = 1, 1, 4: average 2, inside the region of 3 runs' average.
  REQUIRE(p0.nees);
  CHECK(p0.nees->mean == Approx(2));
  CHECK(p0.nees->n == 3);
  CHECK(p0.nees->bounds.lower == Approx(1.2373 / 3).epsilon(1e-3));
  CHECK(p0.nees->bounds.upper == Approx(14.449 / 3).epsilon(1e-3));
  CHECK(p0.nees->inside);
  REQUIRE(p0.nis);
  CHECK(p0.nis->mean == Approx(2));
  // Frame 3: run b has no track; two runs remain.
  const cli::FramePoint& p3 = s.points[3];
  CHECK(p3.frame == 3);
  CHECK(p3.n == 2);
  CHECK(p3.t == Approx(100.3));
  CHECK(p3.rmse_x == Approx(std::sqrt((0.01 + 0.04) / 2)));
  CHECK(p3.nees->mean == Approx(2.5));

  REQUIRE(s.truths.size() == 1);
  const cli::TruthSummary& t = s.truths[0];
  CHECK(t.id == 1);
  CHECK(t.frames == 10);
  CHECK(t.matched_frames == 10);
  CHECK(t.nees_frames == 10);
  CHECK(t.nees_inside == 1);
  CHECK(t.nis_frames == 10);
  CHECK(t.rmse_max == Approx(p3.rmse));
  CHECK(t.rmse_mean == Approx((9 * p0.rmse + p3.rmse) / 10));

  SECTION("plots: NEES, NIS and RMSE per truth") {
    const auto files = cli::drawConsistencyPlots(dir, s, "synthetic");
    CHECK(files == std::vector<std::string>{"nees_1.png", "nis_1.png", "rmse_1.png"});
    for (const auto& f : files) {
      const cv::Mat img = cv::imread(dir + "/" + f);
      CHECK(img.cols == 900);
      CHECK(img.rows == 520);
    }
  }
}

TEST_CASE("montecarlo heading RMSE: per frame and pooled, wrapped at pi, skipped without yaw",
          "[montecarlo][heading]") {
  const std::string dir = freshDir("montecarlo_heading");
  // The person faces −3.1 rad; run a's track faces 3.1 (0.0832 rad off across ±π), run b's
  // −3.0 (0.1 rad off), run c's track rows have no yaw.
  std::string truth = "t,frame,id,x,y,yaw,visible_points\n";
  std::string a = "t,frame,track,x,y,yaw\n", b = a, c = "t,frame,track,x,y\n";
  for (int k = 0; k < 6; ++k) {
    const double t = 100 + 0.1 * k;
    truth += mrpt::format("%.6f,%d,1,%.4f,0,-3.1,40\n", t, k, 0.1 * k);
    a += mrpt::format("%.6f,%d,7,%.4f,0,3.1\n", t, k, 0.1 * k + 0.1);
    b += mrpt::format("%.6f,%d,7,%.4f,0,%s\n", t, k, 0.1 * k, k == 2 ? "" : "-3.0");
    c += mrpt::format("%.6f,%d,7,%.4f,0\n", t, k, 0.1 * k);
  }
  writeFile(dir + "/truth.csv", truth);
  writeFile(dir + "/a.csv", a);
  writeFile(dir + "/b.csv", b);
  writeFile(dir + "/c.csv", c);
  const std::string tr = dir + "/truth.csv";
  const cli::MonteCarloScore s = cli::scoreMonteCarlo(
      {tr, tr, tr}, {dir + "/a.csv", dir + "/b.csv", dir + "/c.csv"}, eval::TrackingOptions());
  const double wrap = 2 * M_PI - 6.2;
  REQUIRE(s.points.size() == 6);
  CHECK(s.points[0].n == 3);
  CHECK(s.points[0].heading_n == 2);
  CHECK(s.points[0].heading_rmse == Approx(std::sqrt((wrap * wrap + 0.01) / 2)));
  CHECK(s.points[2].heading_n == 1);  // run b's row of frame 2 has no yaw
  CHECK(s.points[2].heading_rmse == Approx(wrap));
  REQUIRE(s.tracking);
  CHECK(s.tracking->errors.heading_pairs == 11);
  CHECK(s.tracking->errors.headingRmse() == Approx(std::sqrt((6 * wrap * wrap + 5 * 0.01) / 11)));
  REQUIRE(s.truths.size() == 1);
  CHECK(s.truths[0].heading_frames == 6);
  CHECK(s.truths[0].heading_rmse_max == Approx(s.points[0].heading_rmse));

  const auto files = cli::drawConsistencyPlots(dir, s, "heading");
  CHECK(files == std::vector<std::string>{"rmse_1.png", "heading_1.png"});
  CHECK(cv::imread(dir + "/heading_1.png").cols == 900);

  // Only run c (no yaw): no heading values, no heading plot.
  const cli::MonteCarloScore none =
      cli::scoreMonteCarlo({tr}, {dir + "/c.csv"}, eval::TrackingOptions());
  CHECK(none.points[0].heading_n == 0);
  CHECK(std::isnan(none.points[0].heading_rmse));
  CHECK(none.truths[0].heading_frames == 0);
  CHECK(std::isnan(none.tracking->errors.headingRmse()));
  const std::string quiet = freshDir("montecarlo_heading_none");
  CHECK(cli::drawConsistencyPlots(quiet, none, "x") == std::vector<std::string>{"rmse_1.png"});
}

namespace {

// A montecarlo output directory written by hand: montecarlo.json with the compared figures and
// consistency.csv with truth 1 over frames 0-2 and 4 (frame 3 unmatched), `d` m and `h` rad off.
// An empty `axis` leaves "axis_rmse_rad" out, as in results written before it existed.
void handMadeResult(const std::string& dir, double rmse, const std::string& heading, double mota,
                    int switches, double d, const std::string& h, const std::string& axis = "") {
  fs::create_directories(dir);
  const std::string axis_key = axis.empty() ? "" : ", \"axis_rmse_rad\": " + axis;
  writeFile(dir + "/montecarlo.json",
            mrpt::format("{\n  \"mode\": \"montecarlo\",\n  \"runs\": 4,\n  \"runs_scored\": 3,\n"
                         "  \"tracking\": {\n  \"clear_mot\": {\"id_switches\": %d, \"mota\": "
                         "%g},\n  \"errors\": {\"position_rmse_m\": %g, \"heading_rmse_rad\": "
                         "%s%s}\n},\n  \"run_list\": [{\"mota\": 0.1}],\n  \"t0\": 100.000000\n}\n",
                         switches, mota, rmse, heading.c_str(), axis_key.c_str()));
  std::string csv =
      "truth_id,frame,t,n,nees_mean,nees_lower,nees_upper,nees_inside,nis_mean,nis_lower,"
      "nis_upper,nis_inside,rmse_x,rmse_y,rmse,heading_n,heading_rmse\n";
  for (int k : {0, 1, 2, 4})
    csv +=
        mrpt::format("1,%d,%.6f,3,,,,,,,,,,,%g,3,%s\n", k, 100.5 + 0.1 * k, d * (k + 1), h.c_str());
  writeFile(dir + "/consistency.csv", csv);
}

}  // namespace

TEST_CASE("montecarlo --compare: a table and error curves of several result directories",
          "[montecarlo][compare]") {
  const std::string dir = freshDir("montecarlo_compare");
  handMadeResult(dir + "/kf", 0.0523, "0.21", 0.9, 2, 0.05, "0.2", "0.12");
  handMadeResult(dir + "/imm", 0.031, "null", 0.95, 0, 0.03, "");  // no axis_rmse_rad: older

  const cli::CompareEntry kf = cli::readMonteCarloDir(dir + "/kf", "kf_bb");
  CHECK(kf.runs == 3);
  CHECK(kf.position_rmse_m == Approx(0.0523));
  CHECK(kf.heading_rmse_rad == Approx(0.21));
  CHECK(kf.axis_rmse_rad == Approx(0.12));
  CHECK(kf.mota == Approx(0.9));  // the pooled MOTA, not a run's
  REQUIRE(kf.id_switches);
  CHECK(*kf.id_switches == 2);
  CHECK(kf.t0 == Approx(100));
  REQUIRE(kf.curves.count(1));
  CHECK(kf.curves.at(1).frame == std::vector<std::size_t>{0, 1, 2, 4});
  CHECK(kf.curves.at(1).rmse[3] == Approx(0.25));
  const cli::CompareEntry imm = cli::readMonteCarloDir(dir + "/imm", "imm_shape");
  CHECK(std::isnan(imm.heading_rmse_rad));
  CHECK(std::isnan(imm.axis_rmse_rad));  // the key is absent
  CHECK(std::isnan(imm.curves.at(1).heading[0]));

  const std::string md = cli::compareMarkdown({kf, imm});
  CHECK(md ==
        "| label     | position RMSE (mm) | heading RMSE (rad) | axis RMSE (rad) |"
        "   MOTA | ID switches | runs |\n"
        "| :-------- | -----------------: | -----------------: | --------------: |"
        " -----: | ----------: | ---: |\n"
        "| kf_bb     |               52.3 |             0.2100 |          0.1200 |"
        " 0.9000 |           2 |    3 |\n"
        "| imm_shape |               31.0 |                  - |               - |"
        " 0.9500 |           0 |    3 |\n");
  const std::string plots = freshDir("montecarlo_compare_plots");
  CHECK(cli::drawCompareErrors(plots, {kf, imm}) == std::vector<std::string>{"errors_1.png"});
  const cv::Mat img = cv::imread(plots + "/errors_1.png");
  CHECK(img.cols == 900);
  CHECK(img.rows == 800);  // two stacked panels

  SECTION("the command: stdout, compare.md, the plot; errors in one line") {
    const std::string out = dir + "/out";
    const auto r = runHost({"montecarlo", "--compare", dir + "/kf", dir + "/imm", "--labels",
                            "kf_bb,imm_shape", "--out", out});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(readFile(out + "/compare.md") == md);
    CHECK_THAT(r.output, Catch::StartsWith(md));
    CHECK(fs::exists(out + "/errors_1.png"));
    // Labels default to the directory names.
    const auto unnamed = runHost({"montecarlo", "--compare", dir + "/kf/", "--out", out});
    CHECK_THAT(unnamed.output, Catch::Contains("| kf    |"));

    const auto missing = runHost({"montecarlo", "--compare", dir + "/kf", dir + "/nope", "--labels",
                                  "a,b", "--out", dir + "/out2"});
    CHECK(missing.exit_code == 2);
    CHECK(missing.output ==
          "error: pedtrack montecarlo --compare: '" + dir + "/nope': no such directory\n");
    const auto labels = runHost({"montecarlo", "--compare", dir + "/kf", dir + "/imm", "--labels",
                                 "a,b,c", "--out", dir + "/out2"});
    CHECK(labels.exit_code == 2);
    CHECK_THAT(labels.output, Catch::Contains("--labels names 3 labels for 2 directories"));
    CHECK(lines(labels.output).size() == 1);
    const auto not_mc =
        runHost({"montecarlo", "--compare", dir, "--labels", "a", "--out", dir + "/out2"});
    CHECK(not_mc.exit_code == 2);
    CHECK_THAT(not_mc.output, Catch::Contains("no montecarlo.json"));
    CHECK_FALSE(fs::exists(dir + "/out2"));  // nothing written
    const auto help = runHost({"montecarlo", "--compare", "--help"});
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.output, Catch::Contains("usage: pedtrack montecarlo --compare DIR1 DIR2"));
  }
}

TEST_CASE("montecarlo scoring without tracks, and unreadable files", "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_no_tracks");
  writeFile(dir + "/truth.csv", truthCsv());
  writeFile(dir + "/none.csv", kTracksHeader);
  const cli::MonteCarloScore s =
      cli::scoreMonteCarlo({dir + "/truth.csv"}, {dir + "/none.csv"}, eval::TrackingOptions());
  CHECK(s.track_rows == 0);
  CHECK_FALSE(s.tracking);
  CHECK(s.points.empty());
  REQUIRE(s.truths.size() == 1);
  CHECK(s.truths[0].frames == 10);
  CHECK(s.truths[0].matched_frames == 0);
  CHECK(cli::drawConsistencyPlots(dir, s, "x").empty());
  CHECK_THROWS_AS(
      cli::scoreMonteCarlo({dir + "/missing.csv"}, {dir + "/none.csv"}, eval::TrackingOptions()),
      ConfigError);
}

TEST_CASE("llr.png from a tracker's existence.csv, skipped without one", "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_llr");
  CHECK_FALSE(cli::drawLlrPlot(dir + "/existence.csv", dir + "/llr.png", "t"));
  CHECK_FALSE(fs::exists(dir + "/llr.png"));
  std::string csv = "t,frame,track,existence,llr,llr_confirm,llr_delete,status\n";
  for (int k = 0; k < 20; ++k) {
    csv += mrpt::format("%.6f,%d,1,0.5,%.3f,4.6,-4.6,%s\n", 100 + 0.2 * k, k, -1.4 + 0.6 * k,
                        k < 10 ? "tentative" : "confirmed");
    if (k < 5)
      csv += mrpt::format("%.6f,%d,2,0.1,%.3f,4.6,-4.6,tentative\n", 100 + 0.2 * k, k, -1.4 - k);
  }
  writeFile(dir + "/existence.csv", csv);
  REQUIRE(cli::drawLlrPlot(dir + "/existence.csv", dir + "/llr.png", "two tracks"));
  CHECK(cv::imread(dir + "/llr.png").cols == 900);
  writeFile(dir + "/bad.csv", "t,frame,track\n1,0,1\n");
  CHECK_THROWS_AS(cli::drawLlrPlot(dir + "/bad.csv", dir + "/bad.png", "t"), ConfigError);
}

TEST_CASE("plot axes: fitted ranges and pixels", "[montecarlo]") {
  const cli::plot::Axis a = cli::plot::fitAxis("x", {0.5, 2, NAN, 4}, false, true);
  CHECK(a.min == 0);
  CHECK(a.max > 4);
  CHECK(a.max < 4.5);
  const cli::plot::Axis l = cli::plot::fitAxis("y", {-1, 0.1, 10}, true);
  CHECK(l.log);
  CHECK(l.min < 0.1);
  CHECK(l.min > 0.05);
  const cli::plot::Axis empty = cli::plot::fitAxis("z", {});
  CHECK(empty.min == 0);
  CHECK(empty.max == 1);
  cli::plot::Plot p(400, 300, {"x", 0, 1}, {"y", 0.1, 10, true});
  const cv::Point lo = p.pixel(0, 0.1), mid = p.pixel(0.5, 1), hi = p.pixel(1, 10);
  CHECK(lo.x < mid.x);
  CHECK(mid.x < hi.x);
  CHECK(lo.y > mid.y);                                    // image rows grow downwards
  CHECK(mid.y - hi.y == Approx(lo.y - mid.y).margin(1));  // one decade each
}

TEST_CASE("montecarlo runs a pipeline on seeds of a scenario and writes the report",
          "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_cli");
  const std::string scenario = shortScenario(dir);
  const std::string out = dir + "/mc";
  const auto r = runHost({"montecarlo", config("detect_torso.ini"), scenario, "--runs", "3",
                          "--out", out, "--seed-base", "7", "--jobs", "2"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("3 runs of short_circle.ini through detect_torso.ini "
                                       "(seeds 7-9)"));
  CHECK_THAT(r.output, Catch::Contains("no tracks to score"));
  CHECK_THAT(r.output, Catch::Contains("montecarlo: 3 runs in"));  // progress on stderr
  for (int i = 0; i < 3; ++i) {
    const std::string run = out + mrpt::format("/run_%03d", i);
    CHECK(fs::exists(run + "/truth.csv"));
    CHECK(fs::exists(run + "/tracks.csv"));
    CHECK(fs::exists(run + "/detections.csv"));
    CHECK_FALSE(fs::exists(run + "/truth_points.bin"));  // point_truth = false
    CHECK_FALSE(fs::exists(run + "/point_labels.bin"));
  }
  // Different seeds, different scans.
  CHECK(readFile(out + "/run_000/detections.csv") != readFile(out + "/run_001/detections.csv"));
  const std::string json = readFile(out + "/montecarlo.json");
  CHECK(jsonValue(json, "runs") == 3);
  CHECK(jsonValue(json, "runs_scored") == 3);
  CHECK(jsonValue(json, "seed_base") == 7);
  CHECK(jsonValue(json, "track_rows") == 0);
  CHECK_THAT(json, Catch::Contains("\"no_tracks\": true"));
  CHECK_THAT(json, Catch::Contains("\"seed\": 9"));
  CHECK(lines(readFile(out + "/consistency.csv")).size() == 1);  // the header

  SECTION("--json prints montecarlo.json; runs on threads equal runs one at a time") {
    const std::string serial = dir + "/serial";
    const auto j = runHost({"montecarlo", config("detect_torso.ini"), scenario, "--runs", "3",
                            "--out", serial, "--seed-base", "7", "--jobs", "1", "--json", "-q"});
    REQUIRE(j.exit_code == 0);
    CHECK(j.output == readFile(serial + "/montecarlo.json"));
    for (int i = 0; i < 3; ++i)
      for (const char* f : {"/truth.csv", "/detections.csv", "/clusters.csv", "/tracks.csv"}) {
        const std::string run = mrpt::format("/run_%03d", i);
        CHECK(readFile(out + run + f) == readFile(serial + run + f));
      }
  }
}

TEST_CASE("montecarlo reports a failed run with its seed, scores the others, exits 1",
          "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_failed_run");
  const std::string out = dir + "/mc";
  fs::create_directories(out);
  writeFile(out + "/run_001", "");  // a file where run 1's directory goes
  const auto r = runHost({"montecarlo", config("detect_torso.ini"), shortScenario(dir), "--runs",
                          "2", "--out", out, "-q"});
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("error: run 1 (seed 2) failed:"));
  CHECK_THAT(r.output, Catch::Contains("2 runs of short_circle.ini through detect_torso.ini "
                                       "(seeds 1-2), 1 scored"));
  const std::string json = readFile(out + "/montecarlo.json");
  CHECK(jsonValue(json, "runs_scored") == 1);
  CHECK(jsonValue(json, "runs_failed") == 1);
  CHECK_THAT(json, Catch::Contains("\"seed\": 2, \"dir\": \"" + out +
                                   "/run_001\", \"status\": \"error\""));
}

TEST_CASE("montecarlo with a tracker: consistency.csv, plots and ID switches", "[montecarlo]") {
  const std::string pipeline = config("people_2d_torso.ini");
  const std::string dir = freshDir("montecarlo_tracker");
  const std::string out = dir + "/mc";
  const auto r =
      runHost({"montecarlo", pipeline, shortScenario(dir), "--runs", "3", "--out", out, "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.output, Catch::Contains("CLEAR MOT"));
  CHECK_THAT(r.output, Catch::Contains("of 3 runs (no ID switch)"));
  const auto rows = lines(readFile(out + "/consistency.csv"));
  REQUIRE(rows.size() > 5);
  CHECK(rows[0] ==
        "truth_id,frame,t,n,nees_mean,nees_lower,nees_upper,nees_inside,nis_mean,nis_lower,"
        "nis_upper,nis_inside,rmse_x,rmse_y,rmse,heading_n,heading_rmse");
  CHECK(fs::exists(out + "/nees_1.png"));
  CHECK(fs::exists(out + "/nis_1.png"));
  CHECK(fs::exists(out + "/rmse_1.png"));
  CHECK(fs::exists(out + "/heading_1.png"));  // imm_pdaf's tracks have yaw
  CHECK(fs::exists(out + "/llr.png"));        // imm_pdaf writes existence.csv
  const std::string json = readFile(out + "/montecarlo.json");
  CHECK_THAT(json, Catch::Contains("\"no_tracks\": false"));
  CHECK(jsonValue(json, "runs_without_switch") <= 3);
  CHECK(jsonValue(json, "nees_frames") > 5);
  const double heading = jsonValue(json, "heading_rmse_rad");
  CHECK(heading > 0);
  CHECK(heading < 1);
  // The pooled axis RMSE (heading error modulo π) is at tracking.errors.axis_rmse_rad.
  CHECK_THAT(json, Catch::Contains("\"axis_rmse_rad\": "));
  const double axis = jsonValue(json, "axis_rmse_rad");
  CHECK(axis >= 0);
  CHECK(axis <= heading + 1e-12);  // |d − π·round(d/π)| ≤ |d|
  CHECK(jsonValue(json, "heading_frames") > 5);
  CHECK_THAT(r.output, Catch::Contains("heading RMSE"));
  CHECK_THAT(r.output, Catch::Contains("axis RMSE (mod 180)"));

  SECTION("--compare puts this result next to itself") {
    const std::string cmp = dir + "/cmp";
    const auto c =
        runHost({"montecarlo", "--compare", out, out, "--labels", "first,second", "--out", cmp});
    INFO(c.output);
    REQUIRE(c.exit_code == 0);
    const auto rows = lines(readFile(cmp + "/compare.md"));
    REQUIRE(rows.size() == 4);
    CHECK_THAT(rows[2], Catch::StartsWith("| first "));
    CHECK_THAT(rows[3], Catch::StartsWith("| second "));
    CHECK(rows[2].substr(10) == rows[3].substr(10));
    CHECK_THAT(rows[2], Catch::Contains(mrpt::format(" %.4f |", heading)));
    CHECK_THAT(rows[0], Catch::Contains("| heading RMSE (rad) | axis RMSE (rad) |"));
    CHECK_THAT(rows[2], Catch::Contains(mrpt::format(" %.4f |", axis)));
    CHECK_THAT(c.output, Catch::Contains(readFile(cmp + "/compare.md")));
    CHECK(cv::imread(cmp + "/errors_1.png").rows == 800);
  }
}

TEST_CASE("montecarlo rejects bad arguments with exit code 2", "[montecarlo]") {
  const std::string dir = freshDir("montecarlo_errors");
  const std::string scenario = shortScenario(dir);
  const std::string pipeline = config("detect_torso.ini");
  const std::string out = dir + "/mc";
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"montecarlo", pipeline, scenario, "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return runHost(args);
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--runs", "0"}, "--runs: must be >= 1"},
      {{"--jobs", "0"}, "--jobs: must be >= 1"},
      {{"--threshold", "0"}, "--threshold: must be > 0"},
      {{"--bogus"}, "pedtrack montecarlo: unrecognised option '--bogus'"},
      {{"--set", "source.seed=3"}, "each run has its own seed; use --seed-base"},
      {{"--set", "segments.nope=1"}, "nope"},
      {{"--set", "source.truth=x.csv"}, "each run's truth.csv is written to and read from"},
  };
  for (const auto& [extra, message] : cases) {
    const auto r = run(extra);
    INFO(extra[0] << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains(message));
    CHECK(lines(r.output).size() == 1);
  }
  CHECK_FALSE(fs::exists(out));  // nothing written

  const auto no_out = runHost({"montecarlo", pipeline, scenario});
  CHECK(no_out.exit_code == 2);
  CHECK_THAT(no_out.output, Catch::Contains("--out"));
  const auto rawlog = runHost({"montecarlo", pipeline, dir + "/x.rawlog", "--out", out});
  CHECK(rawlog.exit_code == 2);
  CHECK_THAT(rawlog.output, Catch::Contains("a scenario file (.ini) is expected"));
  const auto missing = runHost({"montecarlo", pipeline, dir + "/none.ini", "--out", out});
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.output, Catch::Contains("none.ini': no such file"));

  const auto help = runHost({"montecarlo", "--help"});
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.output, Catch::Contains("usage: pedtrack montecarlo PIPELINE.ini SCENARIO.ini"));
  CHECK_THAT(help.output, Catch::Contains("--seed-base"));
}
