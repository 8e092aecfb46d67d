// Output contract: tracks.csv rows, run.json fields, stage statistics.
#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/object_table.h"
#include "pedtrack/outputs.h"
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
        "probs,status,nis");
  CHECK(rows[1] ==
        "1519637061.085268,7,3,1.0000,2.0000,2.0000,0.0000,0.00000,0.5000,0.0000,,,0.01,0,0.02,0."
        "0000,0.7000;0.3000,confirmed,1.25");
  CHECK(rows[2].find(",4,0.0000,0.0000,") != std::string::npos);
  CHECK(rows[2].find(",0.2500,0.1500,,,,") != std::string::npos);
  CHECK(rows[2].substr(rows[2].size() - 2) == ",,");  // no status, no nis
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
  f.detections = {a, b};
  {
    DetectionsCsvWriter w(dir + "/detections.csv");
    w.write(f);
  }
  const auto rows = lines(readFile(dir + "/detections.csv"));
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] == "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta");
  CHECK(rows[1] == "1519637061.500000,3,1.0000,2.0000,2.0000,0.0000,0.9000,,,");
  CHECK(rows[2] == "1519637061.500000,3,1.0000,1.0000,1.0000,0.0000,0.4000,0.50000,0.3000,0.2000");
  const ObjectTable t = readDetectionTable(dir + "/detections.csv");
  REQUIRE(t.rows.size() == 2);
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
