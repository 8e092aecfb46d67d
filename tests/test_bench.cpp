// `pedtrack bench`: the stage bench's cloud resampling and CSV (what `--suite` reads), the
// suite's option errors, and `--suite --quick` end to end: every section of the report, its
// plots, a leaderboard row for every tracker, the soak table.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>

#include "bench_suite.h"
#include "test_support.h"

using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> c;
  std::size_t a = 0;
  for (std::size_t b; (b = line.find(',', a)) != std::string::npos; a = b + 1)
    c.push_back(line.substr(a, b - a));
  c.push_back(line.substr(a));
  return c;
}

}  // namespace

TEST_CASE("bench --pipeline --points resamples every cloud and writes its figures as CSV",
          "[bench]") {
  const std::string dir = freshDir("bench_points");
  for (long n : {2000L, 60000L}) {
    const std::string csv = dir + "/stages_" + std::to_string(n) + ".csv";
    const auto r = runHost({"bench", "--pipeline", kConfigs + "people_3d_vlp16.ini", "--frames",
                            "3", "--repeat", "1", "--points", std::to_string(n), "--csv", csv});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto rows = lines(readFile(csv));
    // Header, the six stages after the source, then "all stages".
    REQUIRE(rows.size() == 1 + 5 + 1);
    CHECK(rows[0] ==
          "stage,plugin,p50_ms,p99_ms,mean_ms,max_ms,frames,points,clusters,tracks,failed");
    CHECK(cells(rows[1])[1] == "irls_ground");
    CHECK(cells(rows.back())[0] == "all stages");
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const auto c = cells(rows[i]);
      REQUIRE(c.size() == 11);
      CHECK(std::stod(c[2]) <= std::stod(c[5]));  // p50 <= max
      CHECK(std::stod(c[6]) == 3);                // frames cached
      CHECK(std::stod(c[7]) == Approx(n));        // every cloud has exactly n points
      CHECK(std::stol(c[10]) == 0);               // no frame failed
    }
    CHECK_THAT(r.output, Catch::Contains(std::to_string(n) + " points each"));
  }
}

TEST_CASE("bench option errors are one line with exit 2", "[bench]") {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"bench", "--suite", "--soak-seconds", "0"},
           {"bench", "--suite", "--jobs", "0"},
           {"bench", "--suite", "--jobs=-1"},  // Boost would make it 2^64 threads
           {"bench", "--suite", "--source", "/nonexistent"},
           {"bench", "--pipeline", kConfigs + "people_3d_vlp16.ini", "--points", "-5"}}) {
    const auto r = runHost(args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(lines(r.output).size() == 1);
  }
}

TEST_CASE("bench --suite --quick writes every section of the report with its plots", "[bench]") {
#ifdef PEDTRACK_SANITIZED
  std::puts("skipped: the timing suite runs ~70 pipelines; it is checked in the Release build");
  std::exit(77);
#endif
  const std::string dir = freshDir("bench_suite");
  const std::string report = dir + "/BENCHMARKS.md";
  // An earlier report: its generated part is replaced, its part measured by hand kept.
  const std::string hand = std::string(pedtrack::cli::kHandMeasuredMarker) +
                           "\n\n## Figures measured by hand\n\nkept as it is\n";
  writeFile(report, "# old generated part\n\n" + hand);
  const auto r = runHost({"bench", "--suite", "--quick", "--report", report, "--work",
                          dir + "/work", "--source", PEDTRACK_SOURCE_DIR});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string md = readFile(report);
  for (const char* s :
       {"# pedtrack benchmarks", "| commit |", "| CPU |", "| compiler |", "## Speed per pipeline",
        "2D leg pipeline ≥ 2,000 scans/s", "## Cost against points and people per frame",
        "## Accuracy of every tracker on every scenario", "## Soak", "RSS at the end",
        "P0 Table I: 78.0 mm", "P3 Table 1: orientation MAE 11.5°"})
    CHECK_THAT(md, Catch::Contains(s));
  // Every tracker has rows, and none failed.
  for (const char* t : {"`imm_shape`", "`kf_bb`", "`kf_circle`", "`mhe_mlesac`", "`ekf_motion`",
                        "`imm_pdaf`", "`imm_pdaf, P4 preset`", "`leg_people`", "`leg_pose`"})
    CHECK_THAT(md, Catch::Contains("| " + std::string(t) + " | "));
  CHECK_THAT(md, !Catch::Contains("error:"));
  CHECK_THAT(md, !Catch::Contains("# old generated part"));
  CHECK(md.size() >= hand.size());
  CHECK(md.compare(md.size() - hand.size(), hand.size(), hand) == 0);
  // leg_pose runs only where there is one person.
  CHECK_THAT(md, !Catch::Contains("| `legs_crowd_10` | `leg_pose` |"));
  CHECK_THAT(md, Catch::Contains("| `p3_s4_random` | `leg_pose` |"));
  for (const char* png : {"cost_vs_points.png", "cost_vs_people.png", "soak_rss.png"}) {
    const std::string path = dir + "/docs/bench/" + png;
    CHECK(std::filesystem::exists(path));
    CHECK(std::filesystem::file_size(path) > 10000);
    CHECK_THAT(md, Catch::Contains(std::string("docs/bench/") + png));
  }
}
