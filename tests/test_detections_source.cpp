// The `detections` source: a detector's KITTI boxes (camera frame) into the robot frame, a
// detections.csv replayed, kitti_tracks.txt written back and scored by `pedtrack eval`, bad input
// refused naming file and line; on the shared data, imm_pdaf behind PointRCNN on sequence 0017.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "pedtrack/errors.h"
#include "pedtrack/eval/kitti_mot.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
namespace fs = std::filesystem;

namespace {

// A camera 700 px focal, the Velodyne's axes turned into the camera's (x right = -y, y down =
// -z, z forward = x), no offset: a Velodyne point (X, Y, Z) is the camera point (-Y, -Z, X).
const char* kCalib =
    "P2: 700 0 600 0 0 700 180 0 0 0 1 0\nR0_rect: 1 0 0 0 1 0 0 0 1\n"
    "Tr_velo_to_cam: 0 -1 0 0 0 0 -1 0 1 0 0 0\n";

std::string pipeline(const std::string& file, const std::string& extra = "") {
  return "[pipeline]\nstages = source\n[source]\nplugin = detections\nfile = " + file + "\n" +
         extra;
}

// A pedestrian walking across, 10 m ahead, at 1 m/s: camera x from -1 m, bottom at y = 1.73.
std::string walker(int frames, bool labels) {
  std::string out;
  for (int f = 0; f < frames; ++f) {
    const double x = -1 + 0.1 * f;
    out += labels ? mrpt::format("%d 7 Pedestrian 0 0 0 0 0 0 0 1.7 0.6 0.8 %.3f 1.73 10 0\n", f, x)
                  : mrpt::format("%d,1,0,0,0,0,5,1.7,0.6,0.8,%.3f,1.73,10,0,0\n", f, x);
  }
  return out;
}

}  // namespace

TEST_CASE("KITTI detections replay in the robot frame with their boxes", "[detections]") {
  const std::string dir = freshDir("detections_kitti");
  writeFile(dir + "/calib.txt", kCalib);
  // Frame 1 has none; a car is not replayed; frames = 4 adds an empty frame 3.
  writeFile(dir + "/dets.txt",
            "0,1,0,0,0,0,0,1.7,0.6,0.8,1,1.73,10,0,0\n0,2,0,0,0,0,3,1.5,1.8,4,5,1.73,20,0,0\n"
            "2,1,0,0,0,0,2,1.6,0.5,0.9,2,1.73,8,1.5707963,0\n");
  const auto frames =
      readAllFrames(pipeline(dir + "/dets.txt", "calib = " + dir + "/calib.txt\nframes = 4\n"));
  REQUIRE(frames.size() == 4);
  CHECK(frames[1].t - frames[0].t == Approx(0.1));
  REQUIRE(frames[0].detections.size() == 1);
  CHECK(frames[1].detections.empty());
  CHECK(frames[3].detections.empty());
  const Detection& d = frames[0].detections[0];
  // Camera (1, 1.73, 10) is Velodyne (10, -1, -1.73): on the road, 1.73 m under the scanner.
  CHECK(d.x == Approx(10));
  CHECK(d.y == Approx(-1));
  CHECK(d.box.z == Approx(0).margin(1e-9));
  CHECK(d.box.h == Approx(1.7));
  CHECK(d.box.w == Approx(0.6));
  CHECK(d.box.l == Approx(0.8));
  CHECK(d.score == 0);                // the detector's own
  CHECK(d.yaw == Approx(-M_PI / 2));  // rotation_y 0: the length along the camera's x
  CHECK(frames[2].detections[0].yaw == Approx(-M_PI).margin(1e-6));
  CHECK(frames[2].detections[0].score == 2);
  CHECK(frames[0].sensor_pose.z() == Approx(1.73));
}

TEST_CASE("bad detection files are refused naming file, line or key", "[detections]") {
  const std::string dir = freshDir("detections_bad");
  writeFile(dir + "/calib.txt", kCalib);
  writeFile(dir + "/short.txt", "0,1,0,0,0,0,0,1.7,0.6\n");
  CHECK_THROWS_WITH(readAllFrames(pipeline(dir + "/short.txt", "calib = " + dir + "/calib.txt\n")),
                    Catch::Contains("short.txt: line 1: expected 15 comma-separated values"));
  writeFile(dir + "/nan.txt",
            "0,1,0,0,0,0,0,1.7,0.6,0.8,1,1.73,10,0,0\n0,1,0,0,0,0,x,1,1,1,1,1,1,0,0\n");
  CHECK_THROWS_WITH(readAllFrames(pipeline(dir + "/nan.txt", "calib = " + dir + "/calib.txt\n")),
                    Catch::Contains("nan.txt: line 2: score 'x' is not a finite number"));
  writeFile(dir + "/ok.txt", "0,1,0,0,0,0,0,1.7,0.6,0.8,1,1.73,10,0,0\n");
  CHECK_THROWS_WITH(readAllFrames(pipeline(dir + "/ok.txt")), Catch::Contains("calib"));
}

TEST_CASE("score_logistic turns the detector's scores into probabilities", "[detections]") {
  const std::string dir = freshDir("detections_logistic");
  writeFile(dir + "/calib.txt", kCalib);
  writeFile(dir + "/d.txt",
            "0,1,0,0,0,0,0,1.7,0.6,0.8,1,1.73,10,0,0\n"
            "0,1,0,0,0,0,2,1.7,0.6,0.8,3,1.73,10,0,0\n");
  const std::string stages = "[pipeline]\nstages = source calibrate\n";
  const std::string source =
      "[source]\nplugin = detections\nfile = d.txt\ncalib = " + dir + "/calib.txt\n";
  writeFile(dir + "/p.ini",
            stages + source + "[calibrate]\nplugin = score_logistic\na = 1.5\nb = -1\n");
  const auto run = runHost({"run", dir + "/p.ini", "--out", dir + "/out", "-q"});
  REQUIRE(run.exit_code == 0);
  const auto rows = lines(readFile(dir + "/out/detections.csv"));
  REQUIRE(rows.size() == 3);
  // 1 / (1 + exp(-(1.5 s - 1))): s = 0 -> 0.2689, s = 2 -> 0.8808.
  CHECK(rows[1].find(",0.2689,") != std::string::npos);
  CHECK(rows[2].find(",0.8808,") != std::string::npos);
  writeFile(dir + "/bad.ini", stages + source + "[calibrate]\nplugin = score_logistic\na = 1\n");
  const auto bad = runHost({"run", dir + "/bad.ini", "-q"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("[calibrate] b"));
}

TEST_CASE("a detections.csv replays its frames", "[detections]") {
  const std::string dir = freshDir("detections_csv");
  writeFile(dir + "/d.csv",
            "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta,cluster,z,h,w,l\n"
            "5.0,0,1,2,1,2,0.9,,,,,,,,\n5.1,1,1.1,2,1.1,2,0.8,0.3,,,,0.1,1.7,0.6,0.8\n"
            "5.1,1,4,4,4,4,0.2,,,,,,,,\n5.4,4,1,1,1,1,0.5,,,,,,,,\n");
  const auto frames = readAllFrames(pipeline(dir + "/d.csv"));
  // Frames 2 and 3 had no detections (no rows): they come back empty, 0.1 s apart.
  REQUIRE(frames.size() == 5);
  CHECK(frames[2].detections.empty());
  CHECK(frames[3].t == Approx(5.3));
  CHECK(frames[4].detections.size() == 1);
  CHECK(frames[0].t == Approx(5.0));
  REQUIRE(frames[1].detections.size() == 2);
  CHECK(frames[1].detections[0].x == Approx(1.1));
  CHECK(frames[1].detections[0].box.h == Approx(1.7));
  CHECK_FALSE(frames[0].detections[0].box.known());
  writeFile(dir + "/tracks.csv", "t,frame,track,x,y,score\n5.0,0,1,1,2,0.5\n");
  CHECK_THROWS_WITH(readAllFrames(pipeline(dir + "/tracks.csv")),
                    Catch::Contains("tracks.csv: line 1: a 'track' column"));
  writeFile(dir + "/bad.csv", "t,frame,x,y,score\n5.0,0,1,2\n");
  CHECK_THROWS_WITH(readAllFrames(pipeline(dir + "/bad.csv")),
                    Catch::Contains("bad.csv: line 2: 4 values for 5 columns"));
}

TEST_CASE("tracks behind KITTI detections come back as kitti_tracks.txt and score",
          "[detections]") {
  const std::string dir = freshDir("detections_roundtrip");
  writeFile(dir + "/calib.txt", kCalib);
  writeFile(dir + "/0001.txt", walker(20, false));
  writeFile(dir + "/labels.txt", walker(20, true));
  const std::string ini = dir + "/p.ini";
  writeFile(ini,
            "[pipeline]\nstages = source track\n[source]\nplugin = detections\nfile = x\n"
            "[track]\nplugin = imm_pdaf\n");
  // --input of a .txt selects the detections source.
  const auto run = runHost({"run", ini, "--input", dir + "/0001.txt", "--set",
                            "source.calib=" + dir + "/calib.txt", "--out", dir + "/run", "-q"});
  REQUIRE(run.exit_code == 0);
  const auto rows = eval::readKittiTrackFile(dir + "/run/kitti_tracks.txt");
  REQUIRE(rows.size() >= 15);
  for (const auto& r : rows) {
    CHECK(r.type == "pedestrian");
    CHECK(r.box.z == Approx(10).margin(0.1));
    CHECK(r.box.y == Approx(1.73).margin(0.01));
    CHECK(r.box.h == Approx(1.7).margin(1e-3));
    CHECK(r.y2 - r.y1 == Approx(1.7 * 700 / (10 - 0.4)).margin(15));
  }
  CHECK(rows.back().box.x == Approx(0.9).margin(0.1));
  const auto ev = runHost({"eval", "--truth", dir + "/labels.txt", "--calib", dir + "/calib.txt",
                           "--tracks", dir + "/run/kitti_tracks.txt", "--json"});
  REQUIRE(ev.exit_code == 0);
  CHECK(jsonValue(ev.output, "id_switches") == 0);
  CHECK(jsonValue(ev.output, "false_positives") == 0);
  CHECK(jsonValue(ev.output, "true_positives") == double(rows.size()));
  CHECK(jsonValue(ev.output, "motp") > 0.8);
  CHECK(jsonValue(ev.output, "hota") > 0.5);
  // One matching rule, one sequence's results for one label file.
  const auto both = runHost({"eval", "--truth", dir + "/labels.txt", "--tracks",
                             dir + "/run/kitti_tracks.txt", "--iou", "0.5", "--distance", "1"});
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.output, Catch::Contains("--iou and --distance"));
  const auto folder = runHost({"eval", "--truth", dir, "--tracks", dir + "/run/kitti_tracks.txt"});
  CHECK(folder.exit_code == 2);
  CHECK_THAT(folder.output, Catch::Contains("one sequence's results"));
  // imm_pdaf reading scores as probabilities refuses a raw score of 5, frame by frame.
  const auto raw = runHost({"run", ini, "--input", dir + "/0001.txt", "--set",
                            "source.calib=" + dir + "/calib.txt", "--set", "track.score_prior=0.2",
                            "--out", dir + "/raw"});
  CHECK_THAT(raw.output, Catch::Contains("detection score 5.000000 is no probability"));
  CHECK(jsonValue(readFile(dir + "/raw/run.json"), "frames_failed") == 20);
}

TEST_CASE("imm_pdaf behind PointRCNN on KITTI sequence 0017", "[detections][data]") {
  const std::string data = sharedDataDir() + "/kitti_tracking";
  requireData(data);
  const std::string out = freshDir("kitti_0017");
  const auto run =
      runHost({"run", std::string(PEDTRACK_SOURCE_DIR) + "/configs/kitti_pedestrians.ini",
               "--input", data + "/pointrcnn_pedestrian/0017.txt", "--set",
               "source.calib=" + data + "/calib/0017.txt", "--out", out + "/0017", "-q"});
  REQUIRE(run.exit_code == 0);
  const auto ev = runHost({"eval", "--truth", data + "/label_02", "--calib", data + "/calib",
                           "--tracks", out, "--json"});
  REQUIRE(ev.exit_code == 0);
  // Measured: sAMOTA 0.892, MOTA 0.839 (BENCHMARKS.md, "KITTI tracking by detection").
  CHECK(jsonValue(ev.output, "samota") > 0.85);
  CHECK(jsonValue(ev.output, "mota") > 0.8);
}
