// Output contract: tracks.csv, detections.csv and clusters.csv rows, run labels, run.json fields,
// stage statistics.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "pedtrack/eval/object_table.h"
#include "pedtrack/outputs.h"
#include "pedtrack/point_labels.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

TEST_CASE("stage statistics use nearest-rank percentiles", "[outputs]") {
  StageStats s("track", "imm_pdaf");
  for (int i = 1; i <= 100; ++i) s.add(i);
  CHECK(s.calls() == 100);
  CHECK(s.mean() == Approx(50.5));
  CHECK(s.percentile(50) == 50);
  CHECK(s.percentile(99) == 99);
  CHECK(s.max() == 100);
  StageStats empty("x", "y");
  CHECK(empty.percentile(50) == 0);
}

TEST_CASE(
    "stage statistics of a long run stay exact in calls, mean and max, within 0.25 % in "
    "percentiles",
    "[outputs]") {
  // 200,000 samples (past the exact window): a deterministic spread over 0.01–100 ms.
  StageStats s("track", "leg_people");
  std::vector<double> all;
  double sum = 0;
  for (int i = 0; i < 200000; ++i) {
    const double ms = 0.01 * std::pow(1e4, std::fmod(i * 0.6180339887, 1.0));
    s.add(ms);
    all.push_back(ms);
    sum += ms;
  }
  CHECK(s.calls() == 200000);
  CHECK(s.mean() == Approx(sum / 200000).epsilon(1e-12));
  CHECK(s.max() == *std::max_element(all.begin(), all.end()));
  std::sort(all.begin(), all.end());
  for (double p : {1.0, 50.0, 99.0, 99.9}) {
    const double exact = all[std::size_t(std::ceil(p / 100 * all.size())) - 1];
    CHECK(s.percentile(p) == Approx(exact).epsilon(0.0025));
  }
}

TEST_CASE("tracks.csv has the contract's columns and sensor-frame coordinates", "[outputs]") {
  const std::string dir = freshDir("outputs_csv");
  Frame f;
  f.index = 7;
  f.t = 1519637061.085268;
  // Sensor 1 m ahead of the origin, turned 90° left: a person at fixed (1, 2) is 2 m ahead of it.
  f.sensor_pose = mrpt::poses::CPose3D(1, 0, 0.5, M_PI / 2, 0, 0);
  Track a;
  a.id = 3;
  a.x = 1;
  a.y = 2;
  a.vx = 0.5;
  a.has_cov = true;
  a.cov_xx = 0.01;
  a.cov_yy = 0.02;
  a.model_probs = {0.7, 0.3};
  a.status = "confirmed";
  a.nis = 1.25;
  a.cluster = 5;
  a.box = {0.1, 1.7, 0.6, 0.8};
  Track b;
  b.id = 4;
  b.has_shape = true;
  b.alpha = 0.25;
  b.beta = 0.15;
  f.tracks = {a, b};
  {
    TracksCsvWriter w(dir + "/tracks.csv");
    w.write(f);
  }
  const auto rows = lines(readFile(dir + "/tracks.csv"));
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] ==
        "t,frame,track,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,cov_xx,cov_xy,cov_yy,score,model_"
        "probs,status,nis,cluster,z,h,w,l");
  CHECK(rows[1] ==
        "1519637061.085268,7,3,1.0000,2.0000,2.0000,0.0000,0.00000,0.5000,0.0000,,,0.01,0,0.02,0."
        "0000,0.7000;0.3000,confirmed,1.25,5,0.1000,1.7000,0.6000,0.8000");
  CHECK(rows[2].find(",4,0.0000,0.0000,") != std::string::npos);
  CHECK(rows[2].find(",0.2500,0.1500,,,,") != std::string::npos);
  // No status, no nis, no cluster, no box.
  CHECK(rows[2].substr(rows[2].size() - 7) == ",,,,,,,");
  // The reader gets every column back.
  const ObjectTable t = readObjectTable(dir + "/tracks.csv");
  REQUIRE(t.rows.size() == 2);
  CHECK(t.rows[0].nis == 1.25);
  CHECK(t.rows[0].sensor_x == 2.0);
  CHECK(std::isnan(t.rows[1].nis));
}

TEST_CASE("detections.csv rows carry both frames and the shape when known", "[outputs]") {
  const std::string dir = freshDir("outputs_detections");
  Frame f;
  f.index = 3;
  f.t = 1519637061.5;
  f.sensor_pose = mrpt::poses::CPose3D(1, 0, 0.5, M_PI / 2, 0, 0);
  Detection a;
  a.x = 1;
  a.y = 2;
  a.score = 0.9;
  Detection b;
  b.x = 1;
  b.y = 1;
  b.score = 0.4;
  b.yaw = 0.5;
  b.alpha = 0.3;
  b.beta = 0.2;
  b.cluster = 2;
  Detection c;
  c.x = 3;
  c.score = 2.5;
  c.yaw = 1;
  c.box = {0.05, 1.7, 0.6, 0.8};
  f.detections = {a, b, c};
  {
    DetectionsCsvWriter w(dir + "/detections.csv");
    w.write(f);
  }
  const auto rows = lines(readFile(dir + "/detections.csv"));
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta,cluster,z,h,w,l");
  CHECK(rows[1] == "1519637061.500000,3,1.0000,2.0000,2.0000,0.0000,0.9000,,,,,,,,");
  CHECK(rows[2] ==
        "1519637061.500000,3,1.0000,1.0000,1.0000,0.0000,0.4000,0.50000,0.3000,0.2000,2,,,,");
  // A 3D detector's box: its heading is the yaw, without a torso ellipse.
  CHECK(rows[3] ==
        "1519637061.500000,3,3.0000,0.0000,0.0000,-2.0000,2.5000,1.00000,0.0000,0.0000,,0.0500,"
        "1.7000,0.6000,0.8000");
  const ObjectTable t = readDetectionTable(dir + "/detections.csv");
  REQUIRE(t.rows.size() == 3);
  CHECK(t.rows[1].id == 1);
  CHECK(t.rows[1].beta == 0.2);
}

TEST_CASE("run.json carries frame counts and per-stage timing", "[outputs]") {
  const std::string dir = freshDir("outputs_json");
  RunSummary s;
  s.pipeline = "configs/a \"b\".ini";
  s.frames_read = 10;
  s.frames_processed = 9;
  s.frames_failed = 1;
  s.wall_time_s = 0.5;
  s.stages.emplace_back("source", "rawlog");
  s.stages.back().add(2.0);
  s.stages.back().add(4.0);
  writeRunJson(dir + "/run.json", s);
  const std::string j = readFile(dir + "/run.json");
  CHECK(j.find("\"pipeline\": \"configs/a \\\"b\\\".ini\"") != std::string::npos);
  CHECK(jsonNumber(j, "frames_read") == 10);
  CHECK(jsonNumber(j, "frames_processed") == 9);
  CHECK(jsonNumber(j, "frames_per_second") == Approx(18));
  CHECK(jsonNumber(j, "mean_ms") == Approx(3));
  CHECK(jsonNumber(j, "p99_ms") == Approx(4));
  CHECK(j.find("\"name\": \"source\", \"plugin\": \"rawlog\", \"calls\": 2") != std::string::npos);
}

TEST_CASE("clusters.csv: both frames, extent, pair and a column per named feature", "[outputs]") {
  const std::string dir = freshDir("outputs_clusters");
  Frame f;
  f.index = 4;
  f.t = 1700000000.25;
  f.robot_pose = mrpt::poses::CPose3D(10, 0, 0, M_PI / 2, 0, 0);
  f.sensor_pose = f.robot_pose + mrpt::poses::CPose3D(0, 0, 1, 0, 0, 0);
  f.cluster_feature_names =
      std::make_shared<const std::vector<std::string>>(std::vector<std::string>{"h", "w"});
  Cluster a;
  a.indices = {0, 1, 2};
  a.cx = 2;  // 2 m ahead of the robot, which faces +y: fixed (10, 2)
  a.cz = 0.9;
  a.size_x = 0.4;
  a.size_y = 0.3;
  a.size_z = 1.7;
  a.features = {1.75, 0.5};
  a.pair = 1;
  Cluster b;
  b.indices = {3};
  b.cy = -1;
  f.clusters = {a, b};
  {
    ClustersCsvWriter w(dir + "/clusters.csv", f);
    w.write(f);
    // A later frame naming its features in another order: matched by name.
    f.cluster_feature_names =
        std::make_shared<const std::vector<std::string>>(std::vector<std::string>{"w", "other"});
    f.clusters = {a};
    w.write(f);
  }
  const auto rows = lines(readFile(dir + "/clusters.csv"));
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == "t,frame,cluster,points,x,y,z,sensor_x,sensor_y,size_x,size_y,size_z,pair,h,w");
  auto fields = [](const std::string& row) {
    std::vector<std::string> v;
    std::stringstream s(row);
    for (std::string x; std::getline(s, x, ',');) v.push_back(x);
    if (!row.empty() && row.back() == ',') v.push_back("");
    return v;
  };
  auto num = [](const std::string& x) { return std::stod(x); };
  const auto r1 = fields(rows[1]), r2 = fields(rows[2]), r3 = fields(rows[3]);
  REQUIRE(r1.size() == 15);
  CHECK(r1[0] == "1700000000.250000");
  CHECK(r1[1] == "4");
  CHECK(r1[3] == "3");
  CHECK(num(r1[4]) == Approx(10).margin(1e-4));  // fixed frame
  CHECK(num(r1[5]) == Approx(2).margin(1e-4));
  CHECK(num(r1[6]) == Approx(0.9));             // fixed-frame z (the robot is at z = 0)
  CHECK(num(r1[7]) == Approx(2).margin(1e-4));  // sensor frame: 2 m ahead
  CHECK(num(r1[8]) == Approx(0).margin(1e-4));
  CHECK(r1[9] == "0.400");
  CHECK(r1[11] == "1.700");
  CHECK(r1[12] == "1");
  CHECK(r1[13] == "1.75");
  CHECK(r1[14] == "0.5");
  CHECK(num(r2[4]) == Approx(11).margin(1e-4));  // 1 m to the robot's right: +x
  CHECK(num(r2[8]) == Approx(-1).margin(1e-4));
  CHECK(r2[12] == "-1");
  CHECK(r2[13].empty());
  CHECK(r2[14].empty());
  CHECK(r3[13].empty());    // h: not named by the later frame
  CHECK(r3[14] == "1.75");  // w: that frame's first value
  // The detections reader reads it too (eval --detections clusters.csv).
  CHECK(readDetectionTable(dir + "/clusters.csv").rows.size() == 3);
}

TEST_CASE("run labels: ground and removed points, then each cluster's index", "[outputs]") {
  Frame f;
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->aperture = 1;
  scan->resizeScan(6);
  for (int i = 0; i < 6; ++i) {
    scan->setScanRange(i, 2);
    scan->setScanRangeValidity(i, true);
  }
  f.observations.push_back(scan);
  CHECK(runLabels(f).labels == std::vector<std::int32_t>(6, run_label::kUnclustered));
  f.labels()[0] = PointLabel::Ground;
  f.labels()[1] = PointLabel::Removed;
  Cluster c;
  c.indices = {3, 4};
  f.clusters = {Cluster(), c};
  f.ground.valid = true;
  const LabelFrame l = runLabels(f);
  CHECK(l.labels == std::vector<std::int32_t>{run_label::kGround, run_label::kRemoved,
                                              run_label::kUnclustered, 1, 1,
                                              run_label::kUnclustered});
  CHECK(l.plane.valid);
}
