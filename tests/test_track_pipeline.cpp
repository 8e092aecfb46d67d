// Trackers end to end: the shipped tracking pipelines on simulated P4 and P2 scenes, scored by
// `pedtrack eval`, and their configuration errors.
#include <algorithm>
#include <catch2/catch.hpp>
#include <sstream>

#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

std::string evalTracks(const std::string& dir) {
  const auto ev =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/tracks.csv", "--json"});
  INFO(ev.output);
  REQUIRE(ev.exit_code == 0);
  return ev.output;
}

// A number inside the JSON object that follows `"section": {`.
double jsonIn(const std::string& json, const std::string& section, const std::string& key) {
  const auto at = json.find("\"" + section + "\": {");
  REQUIRE(at != std::string::npos);
  return jsonNumber(json.substr(at), key);
}

}  // namespace

TEST_CASE("people_2d_torso.ini tracks P4's crossing through the occlusion", "[track]") {
  const std::string dir = freshDir("track_p4_crossing");
  const auto r =
      runHost({"run", kConfigs + "people_2d_torso.ini", "--input",
               kConfigs + "scenarios/p4_crossing.ini", "--out", dir, "-q", "--no-point-labels"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto rows = lines(readFile(dir + "/tracks.csv"));
  REQUIRE(rows.size() > 100);
  // Every row: a covariance, an existence score, three model probabilities and its status.
  for (std::size_t i = 1; i < rows.size(); ++i) {
    INFO(rows[i]);
    std::vector<std::string> f;
    std::stringstream ss(rows[i]);
    for (std::string c; std::getline(ss, c, ',');) f.push_back(c);
    REQUIRE(f.size() >= 18);
    CHECK(std::stod(f[12]) > 0);                              // cov_xx
    CHECK(std::stod(f[14]) > 0);                              // cov_yy
    CHECK(std::stod(f[15]) > 0.9);                            // existence of a confirmed track
    CHECK(std::count(f[16].begin(), f[16].end(), ';') == 2);  // CV, CT+, CT-
    CHECK(f[17] == "confirmed");
  }
  CHECK(lines(readFile(dir + "/existence.csv"))[0] ==
        "t,frame,track,existence,llr,llr_confirm,llr_delete,status");
  const std::string ev = evalTracks(dir);
  // Measured (seed 5): MOTA 0.96, no ID switch.
  CHECK(jsonNumber(ev, "mota") >= 0.85);
  CHECK(jsonNumber(ev, "id_switches") == 0);
  CHECK(jsonNumber(ev, "motp_m") <= 0.15);
}

TEST_CASE("people_3d_motion.ini: the EKF motion stage cuts appearance false positives", "[track]") {
  const std::string dir = freshDir("track_p2_motion");
  const auto r = runHost(
      {"run", kConfigs + "people_3d_motion.ini", "--out", dir, "-q", "--max-frames", "100"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto d = runHost({"eval", "--decisions", dir, "--json"});
  INFO(d.output);
  REQUIRE(d.exit_code == 0);
  const std::string per_cluster = d.output.substr(d.output.find("\"per_cluster\""));
  const double fp_appearance = jsonIn(per_cluster, "appearance", "false_positive_rate");
  const double fp_complete = jsonIn(per_cluster, "complete", "false_positive_rate");
  // Measured on crowd.ini (100 frames): 18.1 % by appearance, 14.5 % with the motion stage.
  CHECK(fp_complete < fp_appearance);
  CHECK(jsonIn(per_cluster, "complete", "detection_rate") >= 0.75);
  CHECK(jsonNumber(evalTracks(dir), "mota") >= 0.3);
}

TEST_CASE("tracker parameters are validated before the first frame", "[track]") {
  const auto bad = runHost({"run", kConfigs + "people_2d_torso.ini", "--set",
                            "track.transition=0.5 0.5 0.5 0.5", "--max-frames", "1", "-q"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("[track] transition: 3 models (CV and one per turn "
                                         "rate) need 9 numbers (row by row), got 4"));
  const auto row = runHost({"run", kConfigs + "people_2d_torso.ini", "--set",
                            "track.transition=0.9 0.2 0  0 1 0  0 0 1", "--max-frames", "1", "-q"});
  CHECK(row.exit_code == 2);
  CHECK_THAT(row.output, Catch::Contains("transition row 1 is not a probability distribution"));
  const auto range = runHost({"run", kConfigs + "people_3d_motion.ini", "--set", "track.q_min=0.7",
                              "--max-frames", "1", "-q"});
  CHECK(range.exit_code == 2);
  CHECK_THAT(range.output, Catch::Contains("[track] q_min: must not exceed q_person"));
}
