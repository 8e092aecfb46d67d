// Classifiers end to end: the shipped detection pipelines with the shipped models, `pedtrack
// train` and `pedtrack eval --model` on held-out simulated scenes and on leg_tracker's real bags.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <sstream>

#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";
const std::string kModels = std::string(PEDTRACK_SOURCE_DIR) + "/models/";

// `pedtrack eval --model ... --json` for one model: its numbers.
std::string evalModel(const std::string& model, const std::vector<std::string>& data) {
  std::vector<std::string> args{"eval", "--model", model, "--json"};
  args.insert(args.end(), data.begin(), data.end());
  const auto r = runHost(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  return r.output;
}

std::string withoutCreated(const std::string& text) {
  return std::regex_replace(text, std::regex("created: [^\n]*\n"), "");
}

}  // namespace

TEST_CASE("detect_3d.ini: the k-NN model scores clusters into detections of people", "[classify]") {
  const std::string dir = freshDir("classify_detect3d");
  const auto r = runHost({"run", kConfigs + "detect_3d.ini", "--out", dir, "--max-frames", "40",
                          "-q", "--no-point-labels"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto rows = lines(readFile(dir + "/detections.csv"));
  REQUIRE(rows.size() > 100);
  CHECK(rows[0] == "t,frame,x,y,sensor_x,sensor_y,score,yaw,alpha,beta,cluster,z,h,w,l");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double score = std::stod(rows[i].substr([&] {
      std::size_t p = 0;
      for (int c = 0; c < 6; ++c) p = rows[i].find(',', p) + 1;
      return p;
    }()));
    REQUIRE(score >= 0.5);  // Q >= Q_P
    REQUIRE(score <= 1.0);
  }
  const auto ev = runHost({"eval", "--truth", dir + "/truth.csv", "--detections",
                           dir + "/detections.csv", "--threshold", "0.5", "--json"});
  INFO(ev.output);
  REQUIRE(ev.exit_code == 0);
  // Measured on this held-out scene (seed 301, people up to 25 m): recall 0.80, precision 0.71.
  CHECK(jsonNumber(ev.output, "recall") >= 0.75);
  CHECK(jsonNumber(ev.output, "precision") >= 0.65);
}

TEST_CASE("detect_torso.ini: SVM detections carry the torso ellipse", "[classify]") {
  const std::string dir = freshDir("classify_torso");
  const auto r = runHost({"run", kConfigs + "detect_torso.ini", "--out", dir, "--max-frames", "40",
                          "-q", "--no-point-labels"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto rows = lines(readFile(dir + "/detections.csv"));
  REQUIRE(rows.size() > 100);
  std::size_t shaped = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> f;
    std::stringstream is(rows[i]);
    for (std::string v; std::getline(is, v, ',');) f.push_back(v);
    shaped += f.size() > 8 && !f[8].empty();  // the alpha column
  }
  CHECK(shaped > rows.size() / 2);
}

TEST_CASE("pedtrack train: deterministic for a seed, and the model it writes is used",
          "[classify]") {
  const std::string dir = freshDir("classify_train");
  std::vector<std::string> args{"train",
                                "knn",
                                "--pipeline",
                                kConfigs + "detect_3d.ini",
                                "--sim",
                                kConfigs + "scenarios/classify_scene.ini",
                                "--frame-step",
                                "20",
                                "--min-range",
                                "1",
                                "--max-range",
                                "20",
                                "--features",
                                "h w d v lambda rho",
                                "--max-prototypes",
                                "300",
                                "-q"};
  args.insert(args.end(), {"--out", dir + "/a.yml"});
  const auto ra = runHost(args);
  INFO(ra.output);
  REQUIRE(ra.exit_code == 0);
  const std::string ma = readFile(dir + "/a.yml");
  const auto rb = runHost(args);
  REQUIRE(rb.exit_code == 0);
  CHECK(withoutCreated(ma) == withoutCreated(readFile(dir + "/a.yml")));
  CHECK(ma.find("command: \"pedtrack train knn") != std::string::npos);
  CHECK(ma.find("features:") != std::string::npos);
  const auto run = runHost({"run", kConfigs + "detect_3d.ini", "--set",
                            "classify.model=" + dir + "/a.yml", "--max-frames", "5", "-q"});
  CHECK(run.exit_code == 0);
}

TEST_CASE("pedtrack eval --save-scores: each sample's label and score, as the confusion counts",
          "[classify]") {
  const std::string dir = freshDir("classify_scores");
  const auto r = runHost(
      {"eval", "--model", kModels + "person3d_knn.yml", "--pipeline", kConfigs + "detect_3d.ini",
       "--sim", kConfigs + "scenarios/classify_scene.ini", "--frame-step", "30", "--save-samples",
       dir + "/samples.csv", "--save-scores", dir + "/scores.csv", "--json", "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto samples = readCsv(dir + "/samples.csv");
  const auto scores = readCsv(dir + "/scores.csv");
  REQUIRE(scores.count("label"));
  REQUIRE(scores.count("score_0"));
  REQUIRE(scores.at("label") == samples.at("label"));
  double tp = 0, fp = 0;
  for (std::size_t i = 0; i < scores.at("label").size(); ++i) {
    const double q = scores.at("score_0")[i];
    REQUIRE((q >= 0 && q <= 1));
    if (q >= 0.5) (scores.at("label")[i] == 1 ? tp : fp) += 1;
  }
  CHECK(tp == jsonNumber(r.output, "tp"));
  CHECK(fp == jsonNumber(r.output, "fp"));
}

TEST_CASE("a corrupt, truncated or wrong-version model stops the run with exit 2", "[classify]") {
  const std::string dir = freshDir("classify_bad_model");
  const std::string good = readFile(kModels + "person3d_knn.yml");
  writeFile(dir + "/truncated.yml", good.substr(0, good.size() / 3));
  writeFile(dir + "/garbage.yml", "%YAML:1.0\n---\nformat: [unclosed\n");
  std::string v2 = good;
  v2.replace(v2.find("version: 1"), 10, "version: 2");
  writeFile(dir + "/v2.yml", v2);
  for (const char* bad : {"truncated.yml", "garbage.yml", "v2.yml"}) {
    const std::string path = dir + "/" + bad;
    const auto r = runHost({"run", kConfigs + "detect_3d.ini", "--set", "classify.model=" + path,
                            "--max-frames", "1", "-q"});
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(path) != std::string::npos);
    CHECK(lines(r.output).size() == 1);
  }
  const auto t =
      runHost({"train", "knn", "--samples", dir + "/garbage.yml", "--out", dir + "/x.yml"});
  CHECK(t.exit_code == 2);
}

TEST_CASE("held-out simulated 3D scenes: k-NN and SVM confusion and AUC", "[classify]") {
  const std::string data = kConfigs + "training/person3d_test.ini";
  // Under the sanitizers one model: the scenes are simulated again for each (minutes there).
  for (const char* m : {"person3d_knn.yml", "person3d_svm.yml"}) {
    if (kSanitized && std::string(m) == "person3d_svm.yml") continue;
    const std::string out = evalModel(kModels + m, {"--dataset", data});
    INFO(m << ": " << out);
    CHECK(jsonNumber(out, "persons") > 2000);
    CHECK(jsonNumber(out, "auc") >= 0.92);
    CHECK(jsonNumber(out, "detection_rate") >= 0.88);
    CHECK(jsonNumber(out, "false_positive_rate") <= 0.18);
  }
}

TEST_CASE("held-out simulated torso scans: P4's torso SVM", "[classify]") {
  const std::string out =
      evalModel(kModels + "torso_svm.yml", {"--dataset", kConfigs + "training/torso_test.ini"});
  CHECK(jsonNumber(out, "auc") >= 0.95);
  CHECK(jsonNumber(out, "detection_rate") >= 0.88);
  CHECK(jsonNumber(out, "false_positive_rate") <= 0.08);
}

TEST_CASE("real legs: leg_tracker positives 6-7 and the second half of negative_2.bag",
          "[classify][data]") {
#ifndef PEDTRACK_WITH_ROSBAG
  WARN("built without ROS bag support: real legs not scored");
  return;
#endif
  requiredDataFileExported("leg_tracker/negative_2.bag");
  for (const char* m : {"legs_knn.yml", "legs_svm.yml"}) {
    const std::string out =
        evalModel(kModels + m, {"--dataset", kConfigs + "training/legs_test.ini"});
    INFO(m << ": " << out);
    CHECK(jsonNumber(out, "persons") == 688);  // every labelled leg of bags 6-7 is a segment
    CHECK(jsonNumber(out, "auc") >= 0.88);
  }
}

TEST_CASE("beam_steps: legs learnt again from thinned scans stand in for legs farther away",
          "[classify][data]") {
  const std::string dir = freshDir("classify_beam_steps");
  // root: the folder holding leg_tracker/ as the dataset file writes it.
  auto dataset = [&](const std::string& steps, const std::string& file,
                     const std::string& root = "${PEDTRACK_DATA}") {
    std::ofstream(dir + "/" + file) << "[dataset]\npipeline = " << kConfigs
                                    << "detect_legs.ini\nframe_step = 5\nbeam_steps = " << steps
                                    << "\n[recording.pos6]\nkind = positive\nfile = " << root
                                    << "/leg_tracker/positive_6_extracted.bag\n"
                                       "topic = /training_scan\n"
                                       "labels_topic = /leg_cluster_positions\n"
                                       "[recording.neg]\nkind = negative\nfile = "
                                    << root
                                    << "/leg_tracker/negative_2.bag\n"
                                       "topic = /left_scan\npart = 0 0.05\n";
    return dir + "/" + file;
  };
  // A step that is no whole number is one line naming the key, before any input is read (so
  // the recordings need not exist, and PEDTRACK_DATA need not be set).
  const auto bad =
      runHost({"train", "svm", dataset("1 2.5", "bad.ini", dir), "--out", dir + "/bad.yml", "-q"});
  INFO(bad.output);
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("[dataset] beam_steps: 2.5 is no whole step") != std::string::npos);
#ifndef PEDTRACK_WITH_ROSBAG
  WARN("built without ROS bag support: beam_steps not run on a recording");
  return;
#endif
  requiredDataFileExported("leg_tracker/positive_6_extracted.bag");
  // The persons' distance feature, as saved with the samples.
  auto personDistances = [&](const std::string& steps) {
    const std::string csv = dir + "/samples_" + std::to_string(steps.size()) + ".csv";
    const auto r = runHost({"train", "knn", dataset(steps, "d.ini"), "--out", dir + "/m.yml",
                            "--save-samples", csv, "-q"});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto cols = readCsv(csv);
    REQUIRE(cols.count("label"));
    REQUIRE(cols.count("distance"));
    std::vector<double> out;
    for (std::size_t i = 0; i < cols.at("label").size(); ++i)
      if (cols.at("label")[i] == 1) out.push_back(cols.at("distance")[i]);
    return out;
  };
  const auto recorded = personDistances("1");
  const auto thinned = personDistances("1 3");
  REQUIRE(!recorded.empty());
  const double reach = *std::max_element(recorded.begin(), recorded.end());
  // The thinned copies add legs, some of them beyond any recorded one (a leg thinned by 3 keeps
  // 3 or more returns only where it had 9, so not every leg has a copy).
  CHECK(thinned.size() > recorded.size());
  CHECK(*std::max_element(thinned.begin(), thinned.end()) > reach);
}
