// configs/people_3d_mhe.ini end to end: P0's MHE-MLESAC (mhe_mlesac) on P0's C-path, scored by
// `pedtrack eval`, and its run.json counters.
#include <catch2/catch.hpp>

#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

}  // namespace

TEST_CASE("people_3d_mhe.ini tracks P0's C-path walker with MHE-MLESAC", "[mhe][pipeline]") {
  const std::string dir = freshDir("mhe_c_path");
  // The walking part (the first 4 s), P0's parameters.
  const auto r = runHost({"run", kConfigs + "people_3d_mhe.ini", "--input",
                          kConfigs + "scenarios/p0_c_path.ini", "--max-frames", "40", "--out", dir,
                          "-q", "--no-point-labels"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string run = readFile(dir + "/run.json");
  // Every frame from the 10th on is an MHE window (the first H are the KF's); Ipopt succeeded.
  CHECK(jsonValue(run, "mhe_windows") >= 25);
  CHECK(jsonValue(run, "mhe_candidates") >= 25 * 90);
  CHECK(jsonValue(run, "ipopt_failed") == 0);
  CHECK(jsonValue(run, "kf_fallbacks") == 0);
  const auto e =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/tracks.csv", "--json"});
  INFO(e.output);
  REQUIRE(e.exit_code == 0);
  // Measured over these frames (the walk and the start of the turn, the hardest part): one
  // track, MOTA 0.97, position RMSE 0.066 m, axis and heading RMSE 0.256 rad (the whole run:
  // 0.036 m, 0.145 rad over 20 seeds, see README). Before the torso band and the facing rule:
  // 0.06-0.08 m and 0.75-1.0 rad heading.
  CHECK(jsonNumber(e.output, "mota") >= 0.9);
  CHECK(jsonNumber(e.output, "position_rmse_m") <= 0.08);
  CHECK(jsonNumber(e.output, "axis_rmse_rad") <= 0.33);
  CHECK(jsonNumber(e.output, "heading_rmse_rad") <= 0.33);  // the facing side is right too
}

TEST_CASE("mhe_mlesac's RANSAC-only comparison reports the KF alongside", "[mhe][pipeline]") {
  const std::string dir = freshDir("mhe_ransac_only");
  const auto r = runHost({"run", kConfigs + "people_3d_mhe.ini", "--input",
                          kConfigs + "scenarios/p0_c_path.ini", "--max-frames", "40", "--out", dir,
                          "-q", "--no-point-labels", "--set", "track.ransac_only=true"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string run = readFile(dir + "/run.json");
  CHECK(jsonValue(run, "mhe_windows") == 0);
  CHECK(jsonValue(run, "ipopt_solves") == 0);
  const auto e =
      runHost({"eval", "--truth", dir + "/truth.csv", "--tracks", dir + "/tracks.csv", "--json"});
  REQUIRE(e.exit_code == 0);
  CHECK(jsonNumber(e.output, "mota") >= 0.9);
}

TEST_CASE("mhe_mlesac parameters are validated before the first frame", "[mhe][pipeline]") {
  const std::string dir = freshDir("mhe_bad");
  for (const std::string& set : {"track.horizon=1", "track.system_noise=0.1,0.1",
                                 "track.selection=best", "track.q=0,0,10,10,0,0"}) {
    const auto r =
        runHost({"run", kConfigs + "people_3d_mhe.ini", "--out", dir, "-q", "--set", set});
    INFO(set << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("[track]") != std::string::npos);
  }
}
