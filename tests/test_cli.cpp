// The host program as a user meets it: listings, bad input, a real run.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "test_support.h"

using namespace pedtrack::test;
namespace fs = std::filesystem;

namespace {
const std::string kSena = mrptDataset("2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog");
}

TEST_CASE("plugins lists every plugin with category and doc, and one plugin's parameters",
          "[cli]") {
  const auto list = runHost({"plugins"});
  CHECK(list.exit_code == 0);
  CHECK_THAT(list.output, Catch::Matches("(.|\n)*rawlog +sensor +Replays an MRPT rawlog(.|\n)*"));
  CHECK_THAT(list.output, Catch::Contains("mrpt_sensor"));
  const auto one = runHost({"plugins", "rawlog"});
  CHECK(one.exit_code == 0);
  for (const char* key : {"file", "rate", "sensor_label", "skip_bad"})
    CHECK_THAT(one.output, Catch::Contains(key));
  CHECK_THAT(one.output, Catch::Contains("{max, realtime}"));
  CHECK_THAT(one.output, Catch::Contains("(required)"));
  const auto bad = runHost({"plugins", "rawlgo"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("did you mean 'rawlog'?"));
}

TEST_CASE("docs/plugins.md, cli.md and scenarios.md are what `pedtrack docs` writes now",
          "[cli][docs]") {
#ifndef PEDTRACK_WITH_ROSBAG
  std::printf("SKIPPED: this build has no rosbag plugin; docs/plugins.md lists it\n");
  std::exit(77);
#endif
  const std::string dir = freshDir("cli_docs");
  // Only this build's plugins: no extra directories from the environment.
  const auto r =
      runShell("env -u PEDTRACK_PLUGIN_PATH '" + std::string(PEDTRACK_BIN) + "' docs --out '" +
               dir + "' --configs '" + PEDTRACK_SOURCE_DIR + "/configs'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(readFile(dir + "/plugins.md"),
             Catch::Contains("## voxel_ccl") && Catch::Contains("| `voxel` | double | m |"));
  CHECK_THAT(readFile(dir + "/cli.md"),
             Catch::Contains("## pedtrack run") && Catch::Contains("--live-queue"));
  CHECK_THAT(readFile(dir + "/scenarios.md"),
             Catch::Contains("## `[person.NAME]`") && Catch::Contains("`crowd.ini`"));
  for (const char* doc : {"plugins.md", "cli.md", "scenarios.md"}) {
    INFO("docs/" << doc << " is stale: run  build/bin/pedtrack docs");
    CHECK(readFile(std::string(PEDTRACK_SOURCE_DIR) + "/docs/" + doc) == readFile(dir + "/" + doc));
  }
}

TEST_CASE("bad pipelines exit 2 with one line and write nothing", "[cli]") {
  const std::string dir = freshDir("cli_bad");
  const std::string head = "[pipeline]\nstages = source\n[source]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "plugin = rawlgo\n",
       "[source] plugin: unknown plugin 'rawlgo' (did you mean 'rawlog'?)"},
      {head + "plugin = rawlog\nfile = " + kSena + "\nrat = max\n",
       "[source] rat: unknown key for plugin 'rawlog' (did you mean 'rate'?)"},
      {head + "plugin = rawlog\n", "[source] file: missing required key (the rawlog to replay)"},
      {head + "plugin = rawlog\nfile = " + kSena + "\nskip_bad = 3.5\n",
       "[source] skip_bad: '3.5' is not a boolean (expected true or false)"},
      {head + "plugin = mrpt_sensor\ndriver = CHokuyoURG\nidle_timeout = 1e9\n",
       "[source] idle_timeout: 1e9 is out of range [0, 3600] s"},
      {head + "plugin = rawlog\nfile = /data/missing.rawlog\n",
       "[source] file: file '/data/missing.rawlog' does not exist"},
  };
  int i = 0;
  for (const auto& [text, expected] : cases) {
    const std::string ini = dir + "/case" + std::to_string(i) + ".ini";
    const std::string out = dir + "/out" + std::to_string(i++);
    writeFile(ini, text);
    const auto r = runHost({"run", ini, "--out", out});
    INFO(text);
    CHECK(r.exit_code == 2);
    CHECK(r.output == "error: " + ini + ": " + expected + "\n");
    CHECK(lines(r.output).size() == 1);
    CHECK_FALSE(fs::exists(out));
  }
  // Command-line mistakes are bad input too.
  const auto missing_pipeline = runHost({"run", dir + "/nope.ini", "--out", dir + "/o"});
  CHECK(missing_pipeline.exit_code == 2);
  CHECK(missing_pipeline.output == "error: " + dir + "/nope.ini: pipeline file not found\n");
  const auto missing_input = runHost({"run", PEDTRACK_SOURCE_DIR "/configs/replay.ini", "--input",
                                      dir + "/nope.rawlog", "--out", dir + "/o"});
  CHECK(missing_input.exit_code == 2);
  CHECK_THAT(missing_input.output,
             Catch::Contains("[source] file: file '" + dir + "/nope.rawlog' does not exist"));
  CHECK(runHost({"run", "--bogus"}).exit_code == 2);
  CHECK(runHost({"frobnicate"}).exit_code == 2);
  CHECK_FALSE(fs::exists(dir + "/o"));
}

TEST_CASE("a run writes tracks.csv and run.json", "[cli]") {
  const std::string out = freshDir("cli_run") + "/out";
  const auto r = runHost({"run", PEDTRACK_SOURCE_DIR "/configs/replay.ini", "--out", out, "-q"});
  CHECK(r.exit_code == 0);
  CHECK(lines(readFile(out + "/tracks.csv")).size() == 1);  // header: no tracker in this pipeline
  const std::string json = readFile(out + "/run.json");
  CHECK(jsonNumber(json, "frames_read") == 225);
  CHECK(jsonNumber(json, "calls") == 225);
  CHECK(jsonNumber(json, "p99_ms") >= jsonNumber(json, "p50_ms"));
  const auto limited = runHost({"run", PEDTRACK_SOURCE_DIR "/configs/replay.ini", "--out", out,
                                "-q", "--max-frames", "10", "--set", "source.rate=max"});
  CHECK(limited.exit_code == 0);
  CHECK(jsonNumber(readFile(out + "/run.json"), "frames_read") == 10);
}

TEST_CASE("every subcommand has --help", "[cli]") {
  for (const char* cmd : {"run", "plugins", "import", "bench"}) {
    const auto r = runHost({cmd, "--help"});
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains(std::string("usage: pedtrack ") + cmd));
  }
}
