// The segmentation pipelines end to end, as a user runs them: simulate, run the shipped configs,
// score with `pedtrack eval`; and the real data (MRPT's VLP-16 sample, the leg_tracker bags).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "pedtrack/point_labels.h"
#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

// A number of the JSON output, the first `"key": ` after `within` (a key of a nested object).
double json(const std::string& text, const std::string& key, const std::string& within = "") {
  const std::size_t from = within.empty() ? 0 : text.find("\"" + within + "\":");
  REQUIRE(from != std::string::npos);
  const std::size_t k = text.find("\"" + key + "\": ", from);
  REQUIRE(k != std::string::npos);
  return std::stod(text.substr(k + key.size() + 4));
}

// Simulates `scenario` into DIR, runs segment_3d.ini on it and returns `pedtrack eval --json`.
// Under the sanitizers only its first `sanitized_seconds`.
std::string segment3d(const std::string& scenario, const std::string& tag,
                      double sanitized_seconds) {
  const std::string dir = freshDir(tag);
  std::vector<std::string> sim{"sim", kConfigs + "scenarios/" + scenario, "--out", dir, "-q"};
  if (kSanitized) sim.insert(sim.end(), {"--duration", std::to_string(sanitized_seconds)});
  REQUIRE(runHost(sim).exit_code == 0);
  const auto run = runHost({"run", kConfigs + "segment_3d.ini", "--input", dir + "/sim.rawlog",
                            "--out", dir + "/run", "-q"});
  REQUIRE(run.exit_code == 0);
  const auto ev = runHost({"eval", "--truth-points", dir + "/truth_points.bin", "--labels",
                           dir + "/run/point_labels.bin", "--json"});
  REQUIRE(ev.exit_code == 0);
  UNSCOPED_INFO(ev.output);
  return ev.output;
}

// Ground returns within 10 m (horizontally) of the sensor over the first frames of a scenario:
// the data segment_3d.ini's IRLS fits.
std::size_t nearGround(const std::string& text, int frames) {
  sim::Simulator s(sim::scenarioFromText(text, "t.ini"));
  sim::SimFrame f;
  std::size_t n = 0;
  for (int k = 0; k < frames && s.next(f); ++k) {
    Frame frame;
    frame.observations.push_back(f.observations.back());
    const auto& c = frame.cloud();
    for (std::size_t i = 0; i < c.size(); ++i) {
      float x, y, z;
      c.getPoint(i, x, y, z);
      n += f.point_truth[i] == truth_label::kGround && std::hypot(x, y) <= 10.0;
    }
  }
  return n;
}

}  // namespace

TEST_CASE("ground tilted 5 deg: plane within 1 deg, >= 99 % of ground and <= 1 % of people removed",
          "[segmentation]") {
  const std::string r = segment3d("tilted_ground.ini", "seg_tilted", 5);
  CHECK(json(r, "plane_frames") == (kSanitized ? 50 : 200));
  CHECK(json(r, "plane_angle_max_deg") < 1.0);
  CHECK(json(r, "ground_removed") >= 0.99);
  CHECK(json(r, "person_as_ground") <= 0.01);
}

TEST_CASE("ground tilted 5 deg and half hidden by a crowd: the seed mesh holds the plane",
          "[segmentation]") {
  // Half hidden: the crowd removes at least half of the ground returns IRLS fits (within 10 m).
  std::string text = readFile(kConfigs + "scenarios/tilted_ground_crowd.ini");
  const std::string open = text.substr(0, text.find("[crowd]"));
  const int frames = kSanitized ? 5 : 20;
  const std::size_t with = nearGround(text, frames), without = nearGround(open, frames);
  INFO("ground returns within 10 m: " << with << " with the crowd, " << without << " without");
  CHECK(with <= without / 2);
  const std::string r = segment3d("tilted_ground_crowd.ini", "seg_tilted_crowd", 2);
  CHECK(json(r, "plane_angle_max_deg") < 1.0);
  CHECK(json(r, "ground_removed") >= 0.99);
  CHECK(json(r, "person_as_ground") <= 0.01);
}

TEST_CASE("20-person crowd, static robot: isolated people are one cluster in >= 98 % of frames",
          "[segmentation]") {
  const std::string r = segment3d("crowd.ini", "seg_crowd", 8);
  CHECK(json(r, "samples", "isolated") > (kSanitized ? 500 : 2000));
  CHECK(json(r, "correct", "isolated") >= 0.98);
  // Merges with other people happen only where people come close (reported for all people).
  CHECK(json(r, "merged_person", "isolated") <= 0.005);
  CHECK(json(r, "split", "people") <= 0.02);
}

TEST_CASE("20-person crowd, moving robot: isolated people are one cluster in >= 98 % of frames",
          "[segmentation]") {
  const std::string r = segment3d("crowd_moving_robot.ini", "seg_crowd_moving", 8);
  CHECK(json(r, "samples", "isolated") > (kSanitized ? 500 : 2000));
  CHECK(json(r, "correct", "isolated") >= 0.98);
  CHECK(json(r, "ground_removed") >= 0.99);
}

TEST_CASE("leg circles on simulated leg-height scans: detection rate, centre and radius",
          "[segmentation][legs]") {
  const std::string dir = freshDir("seg_legs_sim");
  // segment_2d.ini simulates P3's scenario 4 (URG-04LX at 0.4 m) by default.
  REQUIRE(runHost({"run", kConfigs + "segment_2d.ini", "--out", dir, "-q"}).exit_code == 0);
  const auto ev = runHost({"eval", "--truth", dir + "/truth.csv", "--detections",
                           dir + "/clusters.csv", "--legs", "--json"});
  REQUIRE(ev.exit_code == 0);
  INFO(ev.output);
  CHECK(json(ev.output, "recall") >= 0.85);
  CHECK(json(ev.output, "precision") >= 0.95);
  CHECK(json(ev.output, "mean_distance_m") <= 0.03);
  const auto legs = readCsv(dir + "/clusters.csv");
  REQUIRE(legs.at("leg_radius").size() > 300);
  double sum = 0;
  for (double r : legs.at("leg_radius")) {
    CHECK(r >= 0.03);
    CHECK(r <= 0.07);
    sum += r;
  }
  // The algebraic fit of P3 shrinks short noisy arcs: the legs are 5.5 cm.
  CHECK(sum / legs.at("leg_radius").size() == Approx(0.055).margin(0.015));
  // Pairs are mutual.
  const auto& pair = legs.at("pair");
  const auto& frame = legs.at("frame");
  for (std::size_t i = 0; i < pair.size(); ++i)
    if (pair[i] >= 0) {
      std::size_t first = i;
      while (first > 0 && frame[first - 1] == frame[i]) --first;
      CHECK(pair[first + std::size_t(pair[i])] == double(i - first));
    }
}

TEST_CASE("leg circles on the leg_tracker bags: labelled legs found, false legs counted",
          "[segmentation][legs]") {
  const std::string data = sharedDataDir();
  requireData(data.empty() ? "" : data + "/leg_tracker/positive_6_extracted.bag");
  const std::string dir = freshDir("seg_legs_bags");
  double tp = 0, fn = 0;
  for (const char* b : {"positive_6_extracted.bag", "positive_7_extracted.bag"}) {
    const std::string bag = data + "/leg_tracker/" + b;
    REQUIRE(runHost({"run", kConfigs + "segment_2d.ini", "--input", bag, "--topic",
                     "/training_scan", "--out", dir + "/" + b, "-q"})
                .exit_code == 0);
    const auto ev = runHost(
        {"eval", "--truth", bag, "--detections", dir + "/" + b + "/clusters.csv", "--json"});
    REQUIRE(ev.exit_code == 0);
    tp += json(ev.output, "tp");
    fn += json(ev.output, "fn");
  }
  INFO("labelled legs with a circle within 0.1 m: " << tp << " of " << tp + fn);
  CHECK(tp / (tp + fn) >= 0.80);
  const std::string neg = data + "/leg_tracker/negative_2.bag";
  REQUIRE(runHost({"run", kConfigs + "segment_2d.ini", "--input", neg, "--topic", "/left_scan",
                   "--out", dir + "/negative", "-q"})
              .exit_code == 0);
  const auto ev = runHost({"eval", "--truth", neg, "--topic", "/left_scan", "--labels-topic",
                           "none", "--detections", dir + "/negative/clusters.csv", "--json"});
  REQUIRE(ev.exit_code == 0);
  INFO(ev.output);
  CHECK(json(ev.output, "tp") == 0);
  CHECK(json(ev.output, "frames") > 400);
  // Geometry alone: furniture legs and door frames look like legs (the classifier's work).
  CHECK(json(ev.output, "false_positives_per_frame") < 20);
}

TEST_CASE("MRPT's real VLP-16 frame through segment_3d.ini, rendered", "[segmentation][real]") {
  const std::string dir = freshDir("seg_real_vlp16");
  REQUIRE(runHost({"run", kConfigs + "segment_3d.ini", "--out", dir, "-q"}).exit_code == 0);
  const auto clusters = readCsv(dir + "/clusters.csv");
  CHECK(clusters.at("points").size() > 30);
  LabelFileReader labels(dir + "/point_labels.bin");
  LabelFrame f;
  REQUIRE(labels.next(f));
  CHECK(f.labels.size() == 22591);
  std::size_t ground = 0, clustered = 0;
  for (std::int32_t l : f.labels) {
    ground += l == run_label::kGround;
    clustered += l >= 0;
  }
  // The sample's robot frame is its sensor's: the ground is found ~2.1 m below it (its lowest
  // ring meets the ground 8 m out; nearer stand cars and bushes at -1.2 m).
  REQUIRE(f.plane.valid);
  CHECK(f.plane.nz > 0.99);
  CHECK(-f.plane.d / f.plane.nz == Approx(-2.15).margin(0.2));
  // The ground rings near the plane (the terrain is not one plane: farther rings that leave it by
  // more than 5 cm stay as clusters).
  CHECK(ground > f.labels.size() / 10);
  CHECK(clustered > 3000);
  const std::string png = dir + "/vlp16.png";
  const auto r = runHost({"render", "--rawlog", mrptDataset("test_velodyne_VLP16.rawlog"), "--run",
                          dir, "--frame", "0", "--range", "25", "--out", png, "-q"});
  REQUIRE(r.exit_code == 0);
  const cv::Mat img = cv::imread(png);
  REQUIRE(!img.empty());
  // Ground grey and several cluster colours are drawn.
  int grey = 0;
  std::map<int, int> hues;
  for (int v = 0; v < img.rows; ++v)
    for (int u = 0; u < img.cols; ++u) {
      const cv::Vec3b p = img.at<cv::Vec3b>(v, u);
      grey += p == cv::Vec3b(120, 120, 120);
      if (std::max({p[0], p[1], p[2]}) == 255 && std::min({p[0], p[1], p[2]}) > 60)
        ++hues[p[0] / 32 * 64 + p[1] / 32 * 8 + p[2] / 32];
    }
  CHECK(grey > 1000);
  CHECK(hues.size() > 5);
}

TEST_CASE("the shipped segmentation configs run on their built-in inputs", "[segmentation]") {
  for (const char* cfg : {"segment_3d.ini", "segment_2d.ini"}) {
    const std::string dir = freshDir(std::string("seg_config_") + cfg);
    const auto r = runHost({"run", kConfigs + cfg, "--out", dir, "--max-frames", "20", "-q"});
    INFO(cfg << ": " << r.output);
    CHECK(r.exit_code == 0);
    CHECK(readFile(dir + "/run.json").find("\"status\": \"ok\"") != std::string::npos);
    CHECK(readFile(dir + "/clusters.csv").size() > 100);
  }
}
