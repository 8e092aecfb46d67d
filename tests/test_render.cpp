// `pedtrack render`: pictures and videos of a run, checked pixel by pixel where it matters.
#include <mrpt/core/format.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "pedtrack/point_labels.h"
#include "render/palette.h"
#include "render/view.h"
#include "test_support.h"

using namespace pedtrack::test;
using namespace pedtrack::render;
using pedtrack::LabelFileWriter;
using pedtrack::LabelFrame;
using pedtrack::LabelKind;
namespace fs = std::filesystem;

namespace {

const std::string kSena = mrptDataset("2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog");
const std::string kVlp16 = mrptDataset("test_velodyne_VLP16.rawlog");
constexpr int kFrame = 10, kSize = 600;
constexpr double kRange = 6;

struct Object {
  long id;
  double dx, dy;  // offset from the sensor at kFrame (m, fixed frame)
};
const Object kTrackA{3, 2.0, 1.0}, kTrackB{7, -1.5, -2.0};
const Object kTruthA{1, 2.1, 1.1}, kTruthB{2, 3.0, -2.5}, kDetection{-1, -2.0, 2.0};

cv::Vec3b bgr(const cv::Scalar& s) {
  return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

std::size_t countColor(const cv::Mat& img, const cv::Scalar& color) {
  const cv::Vec3b c = bgr(color);
  std::size_t n = 0;
  for (int v = 0; v < img.rows; ++v)
    for (int u = 0; u < img.cols; ++u) n += img.at<cv::Vec3b>(v, u) == c;
  return n;
}

/// The SENA log's frames 8-10 with two tracks and two true people around the sensor at frame 10.
struct Fixture {
  std::string dir, tracks, truth, empty_tracks, detections;
  double t = 0, sx = 0, sy = 0;
  // Each test case has its own folder: ctest runs them in parallel.
  explicit Fixture(const std::string& tag) {
    dir = freshDir("render_" + tag);
    const auto frames = readAllFrames(
        "[pipeline]\nstages = source\n[source]\nplugin = rawlog\n"
        "file = " +
        kSena + "\n");
    REQUIRE(frames.size() == 225);
    const auto& f = frames[kFrame];
    t = f.t, sx = f.sensor_pose.x(), sy = f.sensor_pose.y();
    std::string tr =
        "t,frame,track,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,cov_xx,cov_xy,"
        "cov_yy,score,model_probs,status\n";
    for (int k = kFrame - 2; k <= kFrame; ++k) {
      const double back = 0.3 * (kFrame - k);  // both walk +x at 0.3 m per frame
      const auto& fk = frames[k];
      tr += mrpt::format("%.6f,", fk.t) + std::to_string(k) + "," + std::to_string(kTrackA.id) +
            mrpt::format(",%.4f,%.4f,0,0,0.3,1.0,0.2,", sx + kTrackA.dx - back, sy + kTrackA.dy) +
            "0.25,0.15,0.04,0.01,0.02,0.9,,confirmed\n";
      tr += mrpt::format("%.6f,", fk.t) + std::to_string(k) + "," + std::to_string(kTrackB.id) +
            mrpt::format(",%.4f,%.4f,0,0,0,-0.8,0.5,,,,,,0.5,,tentative\n", sx + kTrackB.dx - back,
                         sy + kTrackB.dy);
    }
    tracks = dir + "/tracks.csv";
    writeFile(tracks, tr);
    std::string gt =
        "t,frame,id,x,y,sensor_x,sensor_y,yaw,vx,vy,alpha,beta,height,visible_points,"
        "left_leg_x,left_leg_y,right_leg_x,right_leg_y\n";
    for (const Object& o : {kTruthA, kTruthB}) {
      const double x = sx + o.dx, y = sy + o.dy;
      gt += mrpt::format("%.6f,", t) + std::to_string(kFrame) + "," + std::to_string(o.id) +
            mrpt::format(",%.4f,%.4f,0,0,0,1,0,", x, y) + "0.25,0.15,1.75,40," +
            mrpt::format("%.4f,%.4f,", x + 0.05, y + 0.12) +
            mrpt::format("%.4f,%.4f\n", x - 0.05, y - 0.12);
    }
    truth = dir + "/truth.csv";
    writeFile(truth, gt);
    empty_tracks = dir + "/empty_tracks.csv";
    writeFile(empty_tracks, "t,frame,track,x,y,sensor_x,sensor_y,yaw,vx,vy\n");
    detections = dir + "/detections.csv";
    writeFile(detections, "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta\n" +
                              mrpt::format("%.6f,10,%.4f,%.4f,0,0,0.8,,,\n", t, sx + kDetection.dx,
                                           sy + kDetection.dy));
  }
  View view() const {
    View v;
    v.cx = sx, v.cy = sy, v.half_range = kRange, v.size = kSize;
    return v;
  }
  std::vector<std::string> args(const std::string& out, int size = kSize) const {
    return {"render",
            "--rawlog",
            kSena,
            "--tracks",
            tracks,
            "--truth",
            truth,
            "--out",
            out,
            "--size",
            std::to_string(size),
            "--range",
            mrpt::format("%g", kRange),
            "--center",
            mrpt::format("%.6f,%.6f", sx, sy),
            "-q"};
  }
};

}  // namespace

TEST_CASE("a PNG of one frame draws points, each track in its colour, and the truth", "[render]") {
  const Fixture fx("frame");
  const std::string out = fx.dir + "/frame.png";
  auto args = fx.args(out);
  args.insert(args.end(), {"--frame", std::to_string(kFrame), "--detections", fx.detections});
  const auto r = runHost(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const cv::Mat img = cv::imread(out, cv::IMREAD_COLOR);
  REQUIRE(!img.empty());
  CHECK(img.cols == kSize);
  CHECK(img.rows == kSize);

  const View view = fx.view();
  for (const Object& o : {kTrackA, kTrackB}) {
    const cv::Point p = view.pixel(fx.sx + o.dx, fx.sy + o.dy);
    INFO("track " << o.id << " at pixel " << p);
    CHECK(img.at<cv::Vec3b>(p) == bgr(trackColor(o.id)));
  }
  CHECK(trackColor(kTrackA.id) != trackColor(kTrackB.id));
  // The scan has 308 points, about 30 of them inside this 12 m wide view (2x2 px each).
  CHECK(countColor(img, colors::kPoint) > 60);
  // Truth B and the detection stand alone: truth-green outline and detection-yellow cross.
  const cv::Point g = view.pixel(fx.sx + kTruthB.dx, fx.sy + kTruthB.dy);
  const cv::Point d = view.pixel(fx.sx + kDetection.dx, fx.sy + kDetection.dy);
  int green = 0, yellow = 0;
  for (int v = -20; v <= 20; ++v)
    for (int u = -20; u <= 20; ++u) {
      const cv::Vec3b c = img.at<cv::Vec3b>(g + cv::Point(u, v));
      green += c[1] > 150 && c[0] < 150 && c[2] < 150;
      const cv::Vec3b e = img.at<cv::Vec3b>(d + cv::Point(u, v));
      yellow += e[1] > 150 && e[2] > 150 && e[0] < 120;
    }
  CHECK(green > 20);
  CHECK(yellow > 15);
}

TEST_CASE("a PNG without --frame overlays every path on the last frame", "[render]") {
  const Fixture fx("overlay");
  const std::string out = fx.dir + "/overlay.png";
  auto args = fx.args(out);
  args.insert(args.end(), {"--max-frames", std::to_string(kFrame + 1)});  // frame 10 is the last
  const auto r = runHost(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const cv::Mat img = cv::imread(out, cv::IMREAD_COLOR);
  REQUIRE(img.cols == kSize);
  REQUIRE(img.rows == kSize);
  // Each track's path ends at its last position with a dot in its colour.
  for (const Object& o : {kTrackA, kTrackB})
    CHECK(img.at<cv::Vec3b>(fx.view().pixel(fx.sx + o.dx, fx.sy + o.dy)) == bgr(trackColor(o.id)));
  CHECK(countColor(img, colors::kPoint) > 60);

  // Default view (fitted) and an empty tracks file are fine too.
  const std::string out2 = fx.dir + "/overlay_default.png";
  const auto r2 =
      runHost({"render", "--rawlog", kSena, "--tracks", fx.empty_tracks, "--out", out2, "-q"});
  INFO(r2.output);
  CHECK(r2.exit_code == 0);
  CHECK(cv::imread(out2).cols == 900);
}

TEST_CASE("an MP4 has one video frame per rawlog frame", "[render]") {
  const Fixture fx("mp4");
  const std::string out = fx.dir + "/video.mp4";
  auto args = fx.args(out, 400);
  args.insert(args.end(), {"--max-frames", "40"});
  const auto r = runHost(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  cv::VideoCapture cap(out);
  REQUIRE(cap.isOpened());
  CHECK(cap.get(cv::CAP_PROP_FRAME_WIDTH) == 400);
  CHECK(cap.get(cv::CAP_PROP_FRAME_HEIGHT) == 400);
  CHECK(std::abs(cap.get(cv::CAP_PROP_FRAME_COUNT) - 40) <= 1);
  int read = 0;
  cv::Mat f;
  while (cap.read(f)) {
    CHECK(f.cols == 400);
    ++read;
  }
  CHECK(std::abs(read - 40) <= 1);
}

TEST_CASE("a Velodyne VLP-16 frame renders its 3D points, ground apart", "[render]") {
  const Fixture fx("vlp16");
  const std::string out = fx.dir + "/vlp16.png";
  const auto r = runHost({"render", "--rawlog", kVlp16, "--tracks", fx.empty_tracks, "--out", out,
                          "--frame", "0", "--range", "20", "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const cv::Mat img = cv::imread(out, cv::IMREAD_COLOR);
  REQUIRE(img.cols == 900);
  CHECK(countColor(img, colors::kPoint) > 2000);
  CHECK(countColor(img, colors::kGround) > 2000);
}

TEST_CASE("bad render input exits 2 with one line naming the option or file", "[render]") {
  const Fixture fx("errors");
  const std::string out = fx.dir + "/bad.png";
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::string nope = fx.dir + "/nope.rawlog";
  const std::vector<Case> cases = {
      {{"--rawlog", nope, "--tracks", fx.tracks, "--out", out}, "--rawlog '" + nope + "'"},
      {{"--rawlog", kSena, "--tracks", fx.dir + "/no.csv", "--out", out}, "--tracks '"},
      {{"--rawlog", kSena, "--tracks", fx.tracks, "--truth", fx.dir + "/no.csv", "--out", out},
       "--truth '"},
      {{"--rawlog", kSena, "--tracks", fx.tracks, "--out", fx.dir + "/x.gif"},
       "unknown extension '.gif' (expected .png or .mp4)"},
      {{"--rawlog", kSena, "--tracks", fx.tracks, "--out", out, "--center", "3;4"},
       "--center '3;4'"},
      {{"--rawlog", kSena, "--tracks", fx.tracks, "--out", out, "--frame", "9999"},
       "has only 225 frames"},
      {{"--rawlog", kSena, "--tracks", fx.tracks}, "out"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"render"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = runHost(args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(lines(r.output).size() == 1);
    CHECK_THAT(r.output,
               Catch::StartsWith("error: pedtrack render: ") && Catch::Contains(c.expected));
  }
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(fx.dir + "/x.gif"));
}

TEST_CASE("the simulated crowd renders to a PNG and the C-path to an MP4", "[render][sim]") {
  const std::string dir = freshDir("render_sim");
  const std::string scen = std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/";
  // Under the sanitizers (scripts/check.sh), where the simulator runs ~40 times slower, the
  // scenarios' first seconds: crowd frame 40 of 5 s, the C-path's first 3 s.
  const std::string crowd_s = kSanitized ? "5" : "30", frame = kSanitized ? "40" : "150";
  const std::string c_path_s = kSanitized ? "3" : "14";
  REQUIRE(runHost({"sim", scen + "crowd.ini", "--duration", crowd_s, "--out", dir + "/crowd", "-q"})
              .exit_code == 0);
  const auto png =
      runHost({"render", "--rawlog", dir + "/crowd/sim.rawlog", "--truth", dir + "/crowd/truth.csv",
               "--frame", frame, "--out", dir + "/crowd.png", "-q"});
  REQUIRE(png.exit_code == 0);
  const cv::Mat img = cv::imread(dir + "/crowd.png");
  REQUIRE(!img.empty());
  CHECK(img.cols == 900);
  // Truth outlines are drawn in the truth colour: plenty of such pixels for 20 people.
  CHECK(countColor(img, colors::kTruth) > 100);
  CHECK(countColor(img, colors::kPoint) > 1000);

  REQUIRE(
      runHost({"sim", scen + "p0_c_path.ini", "--duration", c_path_s, "--out", dir + "/c", "-q"})
          .exit_code == 0);
  const std::string mp4 = dir + "/c_path.mp4";
  REQUIRE(runHost({"render", "--rawlog", dir + "/c/sim.rawlog", "--truth", dir + "/c/truth.csv",
                   "--out", mp4, "--size", "600", "--range", "4", "-q"})
              .exit_code == 0);
  cv::VideoCapture cap(mp4);
  REQUIRE(cap.isOpened());
  int frames = 0, width = 0;
  cv::Mat f;
  while (cap.read(f)) {
    if (!frames) width = f.cols;
    ++frames;
  }
  CHECK(std::abs(frames - 10 * std::stoi(c_path_s)) <= 1);
  CHECK(width == 600);
}

TEST_CASE("torso ellipses put alpha across the heading and beta along it", "[render]") {
  // An empty simulated room (a 2D scan that hits nothing) and one true torso at (3, 0) facing +x
  // with alpha 1.0 m and beta 0.3 m: the outline passes (3, ±1.0) and (3 ± 0.3, 0), not (4, 0).
  const std::string dir = freshDir("render_axes");
  writeFile(dir + "/s.ini",
            "[scenario]\nduration = 0.1\n[sensor]\nmodel = utm30lx\nz = 1.0\nyaw = 180\n");
  REQUIRE(runHost({"sim", dir + "/s.ini", "--out", dir, "-q"}).exit_code == 0);
  const auto rows = lines(readFile(dir + "/truth.csv"));
  REQUIRE(rows.size() == 1);  // nobody in the scenario: header only
  const double t = 1700000000.0;
  writeFile(dir + "/truth.csv", rows[0] + "\n" + mrpt::format("%.6f,0,1,3,0,3,0,", t) +
                                    "0,0,0,1.0,0.3,1.7,0,3,0.1,3,-0.1,3,0\n");
  const std::string out = dir + "/axes.png";
  REQUIRE(
      runHost({"render", "--rawlog", dir + "/sim.rawlog", "--truth", dir + "/truth.csv", "--frame",
               "0", "--out", out, "--size", "400", "--range", "5", "--center", "0,0", "-q"})
          .exit_code == 0);
  const cv::Mat img = cv::imread(out);
  REQUIRE(img.cols == 400);
  View v;
  v.cx = 0, v.cy = 0, v.half_range = 5, v.size = 400;
  // Outlines are anti-aliased: count pixels that are mostly truth-green near the point.
  auto truthNear = [&](double x, double y) {
    const cv::Point p = v.pixel(x, y);
    int n = 0;
    for (int dv = -2; dv <= 2; ++dv)
      for (int du = -2; du <= 2; ++du) {
        const cv::Vec3b c = img.at<cv::Vec3b>(p.y + dv, p.x + du);
        n += c[1] > 120 && c[1] > c[0] + 50 && c[1] > c[2] + 50;
      }
    return n;
  };
  CHECK(truthNear(3, 1.0) > 0);
  CHECK(truthNear(3, -1.0) > 0);
  CHECK(truthNear(3.3, 0) > 0);
  CHECK(truthNear(4.0, 0) == 0);
}

TEST_CASE("point labels colour clusters, ground and removed points; truth labels each person",
          "[render][labels]") {
  const Fixture fx("labels");
  const auto frames = readAllFrames(
      "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = " + kSena + "\n");
  const std::size_t n = frames[kFrame].cloud().size();
  REQUIRE(n > 100);
  // Frame 10: the first third removed, the second third cluster 5, the rest unclustered; and a
  // truth file calling the first half person 4, the rest objects.
  const std::string run = fx.dir + "/point_labels.bin", truth = fx.dir + "/truth_points.bin";
  {
    LabelFileWriter r(run, LabelKind::Run), t(truth, LabelKind::Truth);
    LabelFrame rf, tf;
    rf.index = tf.index = kFrame;
    for (std::size_t i = 0; i < n; ++i) {
      rf.labels.push_back(i < n / 3       ? pedtrack::run_label::kRemoved
                          : i < 2 * n / 3 ? 5
                                          : pedtrack::run_label::kUnclustered);
      tf.labels.push_back(i < n / 2 ? 4 : -2);
    }
    r.write(rf);
    t.write(tf);
  }
  const std::string out = fx.dir + "/run.png", out_truth = fx.dir + "/truth.png";
  auto args = [&](const std::string& labels, const std::string& png) {
    return std::vector<std::string>{
        "render",   "--rawlog", kSena,     "--frame", std::to_string(kFrame),
        "--labels", labels,     "--range", "40",      "--out",
        png,        "-q"};
  };
  REQUIRE(runHost(args(run, out)).exit_code == 0);
  const cv::Mat img = cv::imread(out, cv::IMREAD_COLOR);
  CHECK(countColor(img, clusterColor(5)) > 50);
  CHECK(countColor(img, colors::kRemoved) > 50);
  CHECK(countColor(img, colors::kPoint) > 50);
  REQUIRE(runHost(args(truth, out_truth)).exit_code == 0);
  const cv::Mat t = cv::imread(out_truth, cv::IMREAD_COLOR);
  CHECK(countColor(t, clusterColor(4)) > 50);
  CHECK(countColor(t, colors::kPoint) > 50);
  CHECK(countColor(t, colors::kRemoved) == 0);
  // --run DIR takes the labels (and tracks) from a run's folder.
  const std::string out_run = fx.dir + "/from_run.png";
  REQUIRE(runHost({"render", "--rawlog", kSena, "--run", fx.dir, "--frame", std::to_string(kFrame),
                   "--out", out_run, "--range", "40", "-q"})
              .exit_code == 0);
  CHECK(countColor(cv::imread(out_run, cv::IMREAD_COLOR), clusterColor(5)) > 50);
  // A label file that is not one: one line, exit 2.
  writeFile(fx.dir + "/bad.bin", "garbage");
  const auto bad = runHost({"render", "--rawlog", kSena, "--labels", fx.dir + "/bad.bin", "--out",
                            fx.dir + "/x.png", "-q"});
  CHECK(bad.exit_code == 2);
  CHECK(lines(bad.output).size() == 1);
}
