// `pedtrack eval` as a user runs it: tables, JSON, Monte Carlo runs, errors, and detections
// against the labelled legs of a leg_tracker training bag.
#include <mrpt/core/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "test_support.h"
#ifdef PEDTRACK_WITH_ROSBAG
#include <geometry_msgs/PoseArray.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#endif

using namespace pedtrack::test;

namespace {

const char* kTruthHeader =
    "t,frame,id,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,height,visible_points,left_leg_x,"
    "left_leg_y,right_leg_x,right_leg_y\n";
const char* kTracksHeader =
    "t,frame,track,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,cov_xx,cov_xy,cov_yy,score,"
    "model_probs,status,nis\n";

// Person 1 walks along y = 0, person 2 along y = 5, 10 frames at 10 Hz, legs ±0.1 m in y.
// Person 1 is hidden (visible_points 0) in the last frame. sensor_x = x + 1.
std::string truthCsv() {
  std::string s = kTruthHeader;
  for (int k = 0; k < 10; ++k)
    for (int id = 1; id <= 2; ++id) {
      const double t = 100 + 0.1 * k, x = 0.1 * k, y = id == 1 ? 0 : 5;
      const int visible = id == 1 && k == 9 ? 0 : 50;
      s += mrpt::format(
          "%.6f,%d,%d,%.4f,%.4f,%.4f,%.4f,0,1,0,0.25,0.15,1.7,%d,%.4f,%.4f,%.4f,%.4f\n", t, k, id,
          x, y, x + 1, y, visible, x, y + 0.1, x, y - 0.1);
    }
  return s;
}

// Tracks 7 and 8 on persons 1 and 2, `dx` east of them in x (sensor_x stays exact), with
// covariance diag(0.01, 0.01) and nis 2.
std::string tracksCsv(double dx) {
  std::string s = kTracksHeader;
  for (int k = 0; k < 10; ++k)
    for (int id = 1; id <= 2; ++id) {
      const double t = 100 + 0.1 * k, x = 0.1 * k, y = id == 1 ? 0 : 5;
      s += mrpt::format("%.6f,%d,%d,%.4f,%.4f,%.4f,%.4f,0,1,0,,,0.01,0,0.01,0.9,,confirmed,2\n", t,
                        k, id + 6, x + dx, y, x + 1, y);
    }
  return s;
}

}  // namespace

TEST_CASE("eval prints CLEAR MOT, identity, HOTA and NEES as a table and as JSON", "[eval_cli]") {
  const std::string dir = freshDir("eval_cli_table");
  writeFile(dir + "/truth.csv", truthCsv());
  writeFile(dir + "/tracks.csv", tracksCsv(0.1));
  const auto text =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/tracks.csv"});
  INFO(text.output);
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.output, Catch::Contains("MOTA                1.0000"));
  CHECK_THAT(text.output, Catch::Contains("MOTP                0.1000 m"));
  CHECK_THAT(text.output, Catch::Contains("IDF1                1.0000"));
  CHECK_THAT(text.output, Catch::Contains("NEES (2 dof, 1 run, 19 samples)"));

  const auto js =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/tracks.csv", "--json"});
  REQUIRE(js.exit_code == 0);
  const std::string& j = js.output;
  // 19 scored truths: person 1 is hidden in the last frame and absorbs track 7 there.
  CHECK(jsonValue(j, "truths") == 19);
  CHECK(jsonValue(j, "unscored_matches") == 1);
  CHECK(jsonValue(j, "mota") == 1);
  CHECK(jsonValue(j, "motp_m") == Approx(0.1));
  CHECK(jsonValue(j, "position_rmse_m") == Approx(0.1));
  CHECK(jsonValue(j, "speed_mae_mps") == 0);
  CHECK(jsonValue(j, "idf1") == 1);
  // sim = 1 − 0.1/0.75 ≈ 0.867: every pair is a TP for α ≤ 0.85, 17 of the 19 α.
  CHECK(jsonValue(j, "hota") == Approx(17.0 / 19));
  CHECK(jsonValue(j, "loca") == Approx((17 * (1 - 0.1 / 0.75) + 2) / 19));
  CHECK(jsonValue(j, "nees_mean") == Approx(1.0));  // 0.1² / 0.01
  CHECK(jsonValue(j, "nees_point_upper") == Approx(7.378).epsilon(1e-3));
  CHECK(jsonValue(j, "nis_mean") == Approx(2.0));
  CHECK(j.find("\"following\": null") != std::string::npos);
}

TEST_CASE("eval options: sensor frame, threshold, following, Monte Carlo runs", "[eval_cli]") {
  const std::string dir = freshDir("eval_cli_options");
  writeFile(dir + "/truth.csv", truthCsv());
  writeFile(dir + "/off.csv", tracksCsv(0.8));
  const std::string truth = dir + "/truth.csv", off = dir + "/off.csv";
  auto json = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"eval", "--truth", truth, "--tracks", off, "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = runHost(args);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return r.output;
  };
  const std::string fixed = json({});
  CHECK(jsonValue(fixed, "misses") == 19);
  CHECK(jsonValue(fixed, "false_positives") == 20);  // 0.8 m is too far even to be absorbed
  CHECK(jsonValue(fixed, "mota") == Approx(1 - 39.0 / 19));
  // sensor_x/sensor_y of the tracks are exact.
  CHECK(jsonValue(json({"--frame", "sensor"}), "mota") == 1);
  CHECK(jsonValue(json({"--threshold", "0.85"}), "motp_m") == Approx(0.8));
  const std::string follow = json({"--following", "2", "--threshold", "0.85"});
  CHECK(jsonValue(follow, "truths") == 10);
  CHECK(jsonValue(follow, "false_positives") == 0);
  CHECK(follow.find("\"identity\": null") != std::string::npos);
  // Two runs: the same truth twice, tracks 0.1 m and 0.8 m off.
  writeFile(dir + "/good.csv", tracksCsv(0.1));
  const auto mc = runHost({"eval", "--truth", truth, "--tracks", dir + "/good.csv", "--truth",
                           truth, "--tracks", off, "--json"});
  REQUIRE(mc.exit_code == 0);
  CHECK(jsonValue(mc.output, "runs") == 2);
  CHECK(jsonValue(mc.output, "truths") == 38);
  CHECK(jsonValue(mc.output, "matches") == 19);
  CHECK(jsonValue(mc.output, "nees_point_upper") == Approx(11.143 / 2).epsilon(1e-3));
}

TEST_CASE("eval scores detections against truth legs", "[eval_cli]") {
  const std::string dir = freshDir("eval_cli_detections");
  writeFile(dir + "/truth.csv", truthCsv());
  // Frame 0 only: one detection 5 cm from person 1's left leg, one 30 cm from its right leg.
  writeFile(dir + "/det.csv",
            "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta\n"
            "100.000000,0,0.05,0.1,1.05,0.1,0.9,,,\n100.000000,0,0.3,-0.1,1.3,-0.1,0.8,,,\n");
  const auto r = runHost({"eval", "--truth", dir + "/truth.csv", "--detections", dir + "/det.csv",
                          "--legs", "--json"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(jsonValue(r.output, "tp") == 1);
  CHECK(jsonValue(r.output, "fp") == 1);
  CHECK(jsonValue(r.output, "fn") == 37);  // 40 legs, 2 of them hidden in the last frame
  CHECK(jsonValue(r.output, "precision") == Approx(0.5));
  CHECK(jsonValue(r.output, "mean_distance_m") == Approx(0.05));
  const auto text =
      runHost({"eval", "--truth", dir + "/truth.csv", "--detections", dir + "/det.csv", "--legs"});
  CHECK_THAT(text.output, Catch::Contains("precision           0.5000"));
}

TEST_CASE("eval rejects bad input with one line and exit 2", "[eval_cli]") {
  const std::string dir = freshDir("eval_cli_errors");
  writeFile(dir + "/truth.csv", truthCsv());
  writeFile(dir + "/tracks.csv", tracksCsv(0.1));
  std::string bad = tracksCsv(0.1);
  bad.replace(bad.find("\n100.000000,0,7,0.1000") + 16, 6, "abc");
  writeFile(dir + "/bad.csv", bad);
  std::string nan_id = tracksCsv(0.1);
  nan_id.replace(nan_id.find("\n100.000000,0,7,") + 14, 1, "nan");
  writeFile(dir + "/nan.csv", nan_id);
  std::string short_row = tracksCsv(0.1);
  short_row.replace(short_row.find(",confirmed,2\n"), 12, "");
  writeFile(dir + "/short.csv", short_row);
  const std::string truth = dir + "/truth.csv";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--truth", dir + "/missing.csv", "--tracks", dir + "/tracks.csv"},
       "error: " + dir + "/missing.csv: cannot open (no such file?)"},
      {{"--truth", truth, "--tracks", dir + "/bad.csv"},
       "error: " + dir + "/bad.csv:2: column 'x': 'abc' is not a number"},
      {{"--truth", truth, "--tracks", dir + "/tracks.csv", "--treshold", "1"},
       "error: pedtrack eval: unrecognised option '--treshold' (see `pedtrack eval --help`)"},
      {{"--truth", truth, "--tracks", dir + "/tracks.csv", "--frame", "robot"},
       "error: pedtrack eval: --frame: 'robot' is not one of fixed, sensor (see `pedtrack eval "
       "--help`)"},
      {{"--truth", truth},
       "error: pedtrack eval: give either --tracks or --detections (see "
       "`pedtrack eval --help`)"},
      {{"--truth", truth, "--tracks", dir + "/nan.csv"},
       "error: " + dir + "/nan.csv:2: column 'track': 'nan' is not finite"},
      {{"--truth", truth, "--tracks", dir + "/short.csv"},
       "error: " + dir + "/short.csv:2: expected 19 columns, found 17"},
  };
  for (const auto& [args, expected] : cases) {
    std::vector<std::string> all = {"eval"};
    all.insert(all.end(), args.begin(), args.end());
    const auto r = runHost(all);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output == expected + "\n");
  }
}

#ifdef PEDTRACK_WITH_ROSBAG
TEST_CASE("eval scores detections against the labelled legs of a leg_tracker bag", "[eval_cli]") {
  const std::string bag_path = sharedDataDir() + "/leg_tracker/positive_6_extracted.bag";
  requireData(sharedDataDir().empty() ? std::string() : bag_path);
  // The labels as leg_tracker's trainer reads them: the unstamped PoseArray before each scan.
  struct Scan {
    double t;
    std::vector<std::pair<double, double>> legs;
  };
  std::vector<Scan> scans;
  {
    rosbag::Bag bag(bag_path);
    rosbag::View view(bag, rosbag::TopicQuery(std::vector<std::string>{"/training_scan",
                                                                       "/leg_cluster_positions"}));
    std::vector<std::pair<double, double>> pending;
    for (const auto& m : view) {
      if (auto a = m.instantiate<geometry_msgs::PoseArray>()) {
        pending.clear();
        for (const auto& p : a->poses) pending.emplace_back(p.position.x, p.position.y);
      } else if (auto s = m.instantiate<sensor_msgs::LaserScan>()) {
        scans.push_back({s->header.stamp.toSec(), pending});
        pending.clear();
      }
    }
  }
  REQUIRE(scans.size() == 187);
  const std::string dir = freshDir("eval_cli_bag");
  // Each leg moved `off` metres away from the nearest other leg of its scan (or radially), so
  // the shifted point stays nearest to its own leg.
  auto write = [&](double off) {
    std::string s = "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta\n";
    std::size_t legs = 0;
    for (std::size_t k = 0; k < scans.size(); ++k)
      for (std::size_t i = 0; i < scans[k].legs.size(); ++i, ++legs) {
        const auto [x, y] = scans[k].legs[i];
        double ax = x, ay = y, best = 1e9;
        for (std::size_t o = 0; o < scans[k].legs.size(); ++o) {
          const double d = std::hypot(x - scans[k].legs[o].first, y - scans[k].legs[o].second);
          if (o != i && d < best)
            best = d, ax = x - scans[k].legs[o].first, ay = y - scans[k].legs[o].second;
        }
        const double n = std::hypot(ax, ay);
        const double px = x + off * ax / n, py = y + off * ay / n;
        char buf[200];
        std::snprintf(buf, sizeof buf, "%.6f,%zu,%.4f,%.4f,%.4f,%.4f,1,,,\n", scans[k].t, k, px, py,
                      px, py);
        s += buf;
      }
    writeFile(dir + "/detections.csv", s);
    return legs;
  };
  auto eval = [&]() {
    const auto r =
        runHost({"eval", "--truth", bag_path, "--detections", dir + "/detections.csv", "--json"});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return r.output;
  };
  const std::size_t legs = write(0.05);
  CHECK(legs == 303);
  std::string j = eval();
  CHECK(jsonValue(j, "frames") == 187);
  CHECK(jsonValue(j, "truth_points") == 303);
  CHECK(jsonValue(j, "precision") == 1);
  CHECK(jsonValue(j, "recall") == 1);
  CHECK(jsonValue(j, "mean_distance_m") == Approx(0.05).margin(1e-4));
  write(0.15);
  j = eval();
  CHECK(jsonValue(j, "precision") == 0);
  CHECK(jsonValue(j, "recall") == 0);
  CHECK(jsonValue(j, "fp") == 303);

  // Tracks against the same labels: one track on each labelled leg (ids by the leg's place in
  // its scan), and one on nothing, 30 m away, in every scan.
  std::string tracks = "t,frame,track,x,y,sensor_x,sensor_y,status\n";
  std::size_t most = 0;
  for (std::size_t k = 0; k < scans.size(); ++k) {
    char buf[200];
    for (std::size_t i = 0; i < scans[k].legs.size(); ++i) {
      const auto [x, y] = scans[k].legs[i];
      std::snprintf(buf, sizeof buf, "%.6f,%zu,%zu,%.4f,%.4f,%.4f,%.4f,confirmed\n", scans[k].t, k,
                    i + 1, x, y, x, y);
      tracks += buf;
    }
    most = std::max(most, scans[k].legs.size());
    std::snprintf(buf, sizeof buf, "%.6f,%zu,999,30,30,30,30,confirmed\n", scans[k].t, k);
    tracks += buf;
  }
  writeFile(dir + "/tracks.csv", tracks);
  const auto r = runHost({"eval", "--truth", bag_path, "--tracks", dir + "/tracks.csv", "--json"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(jsonValue(r.output, "threshold_m") == Approx(0.35));
  CHECK(jsonValue(r.output, "labelled_legs") == 303);
  CHECK(jsonValue(r.output, "legs_covered") == 303);
  CHECK(jsonValue(r.output, "track_rows") == 303 + 187);
  CHECK(jsonValue(r.output, "rows_near_no_leg") == 187);
  CHECK(jsonValue(r.output, "tracks") == double(most + 1));
  CHECK(jsonValue(r.output, "tracks_on_no_person") == 1);
  // The labels are in the laser frame.
  const auto fixed =
      runHost({"eval", "--truth", bag_path, "--tracks", dir + "/tracks.csv", "--frame", "fixed"});
  CHECK(fixed.exit_code == 2);
}
#endif

TEST_CASE("eval scores a simulated run: the truth as tracks, then a shifted copy", "[eval_cli]") {
  const std::string dir = freshDir("eval_sim");
  REQUIRE(runHost({"sim", std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/p4_crossing.ini",
                   "--out", dir, "-q"})
              .exit_code == 0);
  // Tracks = the truth with ids 100+, shifted `dx` m in x, in tracks.csv layout.
  auto tracksFrom = [&](double dx, const std::string& path) {
    std::string s = kTracksHeader;
    const auto rows = lines(readFile(dir + "/truth.csv"));
    for (std::size_t i = 1; i < rows.size(); ++i) {
      double t, x, y, sx, sy, yaw, vx, vy, a, b;
      int frame, id;
      REQUIRE(std::sscanf(rows[i].c_str(), "%lf,%d,%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &t,
                          &frame, &id, &x, &y, &sx, &sy, &yaw, &vx, &vy, &a, &b) == 12);
      s +=
          mrpt::format("%.6f,%d,%d,%.4f,%.4f,%.4f,%.4f,%.5f,%.4f,%.4f,%.4f,%.4f,,,,1,,confirmed,\n",
                       t, frame, id + 100, x + dx, y, sx, sy, yaw, vx, vy, a, b);
    }
    writeFile(path, s);
  };
  tracksFrom(0, dir + "/exact.csv");
  tracksFrom(0.2, dir + "/shifted.csv");
  const auto exact =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/exact.csv", "--json"});
  REQUIRE(exact.exit_code == 0);
  CHECK(jsonValue(exact.output, "mota") == 1);
  CHECK(jsonValue(exact.output, "motp_m") == 0);
  CHECK(jsonValue(exact.output, "id_switches") == 0);
  CHECK(jsonValue(exact.output, "idf1") == 1);
  // Rows with no return (the far person hidden for 5 frames, the near one still outside the
  // field of view) are unscored: their tracks are absorbed, neither valid nor false positives.
  int hidden = 0;
  for (const auto& row : lines(readFile(dir + "/truth.csv"))) {
    std::size_t pos = 0;
    for (int c = 0; c < 13; ++c) pos = row.find(',', pos) + 1;
    hidden += row.compare(pos, 2, "0,") == 0;
  }
  CHECK(hidden >= 5);
  CHECK(jsonValue(exact.output, "unscored_matches") == hidden);
  const auto shifted =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/shifted.csv", "--json"});
  REQUIRE(shifted.exit_code == 0);
  CHECK(jsonValue(shifted.output, "mota") == 1);
  CHECK(jsonValue(shifted.output, "motp_m") == Approx(0.2).margin(1e-4));
  CHECK(jsonValue(shifted.output, "position_rmse_m") == Approx(0.2).margin(1e-4));
  // Beyond a 0.15 m threshold every scored truth is missed and every track is a false positive.
  const auto strict = runHost({"eval", "--truth", dir + "/truth.csv", "--tracks",
                               dir + "/shifted.csv", "--threshold", "0.15", "--json"});
  CHECK(jsonValue(strict.output, "mota") < -0.9);
}

namespace {

// One person and one track over 8 frames; the track's sensor range (sensor_x, sensor_y = 0)
// puts frames 0-1 in 0-10 m, 2-3 in 10-20, 4 in 20-30, 5-6 in 30+ and frame 7 in no band (no
// sensor position). Per band: position errors dx, heading errors (truth yaw, track yaw), alpha,
// beta and model_probs as listed.
std::pair<std::string, std::string> bandedPair() {
  struct Row {
    const char* sensor_x;
    double range, dx, yaw_true, yaw;
    const char *alpha, *beta, *probs;
  };
  const Row rows[] = {
      {"5", 5, 0.1, 0, 0.1, "0.20", "0.10", "0.9;0.05;0.05"},
      {"8", 8, 0.3, 0, -0.3, "0.30", "0.14", "0.7;0.2;0.1"},
      {"12", 12, 0.2, -3.1, 3.1, "0.25", "0.12", "0.2;0.7;0.1"},
      {"18", 18, -0.2, -3.1, 3.1, "0.25", "0.12", "0.2;0.7;0.1"},
      {"25", 25, 0, 0, 0, "", "", ""},
      {"31", 31, 0.1, 0, 0, "0.22", "0.11", "0.1;0.1;0.8"},
      {"40", 40, 0.1, 0, 0, "0.26", "0.13", "0.3;0.1;0.6"},
      {"", 45, 0.1, 0, 0, "0.5", "0.5", "1;0;0"},
  };
  std::string truth = kTruthHeader, tracks = kTracksHeader;
  for (int k = 0; k < 8; ++k) {
    const Row& r = rows[k];
    const double t = 100 + 0.1 * k;
    truth += mrpt::format("%.6f,%d,1,%.4f,0,%.4f,0,%.4f,1,0,0.25,0.15,1.7,50,,,,\n", t, k, r.range,
                          r.range, r.yaw_true);
    tracks += mrpt::format("%.6f,%d,7,%.4f,0,%s,%s,%.4f,1,0,%s,%s,,,,0.9,%s,confirmed,\n", t, k,
                           r.range + r.dx, r.sensor_x, *r.sensor_x ? "0" : "", r.yaw, r.alpha,
                           r.beta, r.probs);
  }
  return {truth, tracks};
}

// The i-th object of "bands" in the JSON output.
std::string band(const std::string& json, int i) {
  std::size_t p = json.find("\"bands\": [");
  for (int k = 0; k <= i; ++k) p = json.find("{\"from_m\"", p + 1);
  return json.substr(p, json.find('}', json.find("\"model_probs\"", p)) - p + 1);
}

}  // namespace

TEST_CASE("eval --range-bins: errors, semi-axes and model probabilities per distance band",
          "[eval_cli][range]") {
  const std::string dir = freshDir("eval_cli_range_bins");
  const auto [truth, tracks] = bandedPair();
  writeFile(dir + "/truth.csv", truth);
  writeFile(dir + "/tracks.csv", tracks);
  const std::vector<std::string> base = {"eval", "--truth", dir + "/truth.csv", "--tracks",
                                         dir + "/tracks.csv"};
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = runHost(args);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return r.output;
  };
  const double wrap = 2 * M_PI - 6.2;  // 3.1 against −3.1

  const std::string json = run({"--range-bins", "0,10,20,30", "--json"});
  CHECK(jsonValue(json, "unbanded") == 1);
  CHECK_THAT(json, Catch::Contains("\"models\": [\"prob_1\", \"prob_2\", \"prob_3\"]"));
  const std::string b0 = band(json, 0), b1 = band(json, 1), b2 = band(json, 2), b3 = band(json, 3);
  CHECK(jsonValue(b0, "from_m") == 0);
  CHECK(jsonValue(b0, "to_m") == 10);
  CHECK(jsonValue(b0, "pairs") == 2);
  CHECK(jsonValue(b0, "position_rmse_m") == Approx(std::sqrt(0.05)));
  CHECK(jsonValue(b0, "heading_rmse_rad") == Approx(std::sqrt(0.05)));
  CHECK(jsonValue(b0, "alpha_mean_m") == Approx(0.25));
  CHECK(jsonValue(b0, "alpha_min_m") == Approx(0.20));
  CHECK(jsonValue(b0, "alpha_max_m") == Approx(0.30));
  CHECK(jsonValue(b0, "beta_mean_m") == Approx(0.12));
  CHECK(jsonValue(b0, "prob_1") == Approx(0.8));
  CHECK(jsonValue(b0, "prob_2") == Approx(0.125));
  CHECK(jsonValue(b0, "prob_3") == Approx(0.075));
  CHECK(jsonValue(b1, "pairs") == 2);
  CHECK(jsonValue(b1, "position_rmse_m") == Approx(0.2));
  CHECK(jsonValue(b1, "heading_rmse_rad") == Approx(wrap).epsilon(1e-4));
  CHECK(jsonValue(b1, "prob_2") == Approx(0.7));
  CHECK(jsonValue(b2, "pairs") == 1);
  CHECK(jsonValue(b2, "shape_rows") == 0);
  CHECK_THAT(b2, Catch::Contains("\"alpha_mean_m\": null"));
  CHECK_THAT(b2, Catch::Contains("\"prob_1\": null"));
  CHECK_THAT(b3, Catch::Contains("\"to_m\": null"));
  CHECK(jsonValue(b3, "pairs") == 2);
  CHECK(jsonValue(b3, "alpha_mean_m") == Approx(0.24));
  CHECK(jsonValue(b3, "prob_3") == Approx(0.7));
  // The pooled heading RMSE of every match: 0.1, 0.3, 2 × wrap, 4 × 0 over 8 pairs.
  CHECK(jsonValue(json, "heading_rmse_rad") ==
        Approx(std::sqrt((0.01 + 0.09 + 2 * wrap * wrap) / 8)).epsilon(1e-4));
  // Every heading error is under π/2: the axis RMSE (modulo π) is the same.
  CHECK(jsonValue(json, "axis_rmse_rad") ==
        Approx(std::sqrt((0.01 + 0.09 + 2 * wrap * wrap) / 8)).epsilon(1e-4));
  CHECK(jsonValue(json, "axis_rmse_deg") ==
        Approx(std::sqrt((0.01 + 0.09 + 2 * wrap * wrap) / 8) * 180 / M_PI).epsilon(1e-4));

  const std::string text = run({"--range-bins", "0,10,20,30", "--model-names", "ellipse,box,cog"});
  CHECK_THAT(text, Catch::Contains("heading RMSE        0.1193 rad"));
  CHECK_THAT(text, Catch::Contains("\n  heading RMSE        0.1193 rad = 6.83 deg\n"
                                   "  axis RMSE (mod 180) 0.1193 rad = 6.83 deg\n"));
  CHECK_THAT(text, Catch::Contains("7 of 8 matches in a band"));
  CHECK_THAT(text, Catch::Matches("(.|\n)*range \\(m\\) .* ellipse +box +cog\n(.|\n)*"));
  CHECK_THAT(text, Catch::Contains("  0 - 10             2     0.2236   0.2236 rad    0.250   "
                                   "0.200   0.300    0.120   0.100   0.140    0.8000    0.1250    "
                                   "0.0750\n"));
  CHECK_THAT(text, Catch::Contains("  30 - inf           2     0.1000   0.0000 rad    0.240"));
  // Default off: the usual report only.
  CHECK(run({}).find("By distance") == std::string::npos);
  // A band edge list of one: everything from 20 m on.
  CHECK(jsonValue(run({"--range-bins", "20", "--json"}), "unbanded") == 5);

  SECTION("--shape-plot with bounds") {
    const std::string png = dir + "/shape.png";
    const std::string out = run({"--shape-plot", png, "--shape-bounds", "0.2,0.3,0.1,0.2"});
    CHECK_THAT(out, Catch::Contains("shape plot: " + png + " (6 matched track rows"));
    CHECK(readFile(png).substr(1, 3) == "PNG");
  }

  SECTION("bad options: one line, exit 2") {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--range-bins", "0,20,10"}, "--range-bins: the edges must increase ('0,20,10')"},
        {{"--range-bins", "0,x"}, "--range-bins: 'x' is not a distance >= 0 m"},
        {{"--model-names", "a,b"}, "--model-names needs --range-bins"},
        {{"--shape-plot", dir + "/s.png", "--shape-bounds", "0.1,0.2,0.3"},
         "--shape-bounds: expected amin,amax,bmin,bmax (4 numbers in m)"},
        {{"--shape-bounds", "0.1,0.2,0.1,0.2"}, "--shape-bounds needs --shape-plot"},
    };
    for (const auto& [extra, message] : cases) {
      std::vector<std::string> args = base;
      args.insert(args.end(), extra.begin(), extra.end());
      const auto r = runHost(args);
      INFO(r.output);
      CHECK(r.exit_code == 2);
      CHECK_THAT(r.output, Catch::StartsWith("error: pedtrack eval: ") && Catch::Contains(message));
      CHECK(lines(r.output).size() == 1);
    }
    const auto det = runHost({"eval", "--truth", dir + "/truth.csv", "--detections",
                              dir + "/tracks.csv", "--range-bins", "0,10"});
    CHECK(det.exit_code == 2);
    CHECK_THAT(det.output, Catch::Contains("--range-bins applies to --tracks only"));
  }
}
