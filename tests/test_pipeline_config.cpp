// Pipeline files: validation against the plugins' declarations, overrides, preprocessing.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>

#include "pedtrack/errors.h"
#include "pedtrack/pipeline_config.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kSena = mrptDataset("2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog");

PipelineConfig parse(const std::string& text, const PipelineOverrides& ov = {}) {
  return PipelineConfig::fromText(text, "p.ini", ov, testRegistry());
}

std::string errorOf(const std::string& text, const PipelineOverrides& ov = {}) {
  try {
    parse(text, ov);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

std::string source(const std::string& extra) {
  return "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = " + kSena + "\n" + extra;
}

}  // namespace

TEST_CASE("a valid pipeline gets declared defaults", "[config]") {
  const auto cfg = parse(source("rate = realtime   ; paced\n"));
  REQUIRE(cfg.stages.size() == 1);
  CHECK(cfg.stages[0].descriptor->name == "rawlog");
  CHECK(cfg.stages[0].params.getString("rate") == "realtime");
  CHECK(cfg.stages[0].params.getBool("skip_bad") == false);
  CHECK(cfg.stages[0].params.getString("file") == kSena);
}

TEST_CASE("every kind of bad pipeline names file, section and key", "[config]") {
  CHECK(errorOf("[pipeline]\nstages = source\n[source]\nplugin = rawlgo\n") ==
        "p.ini: [source] plugin: unknown plugin 'rawlgo' (did you mean 'rawlog'?)");
  CHECK(errorOf(source("skip_bd = true\n")) ==
        "p.ini: [source] skip_bd: unknown key for plugin 'rawlog' (did you mean 'skip_bad'?)");
  CHECK(errorOf("[pipeline]\nstages = source\n[source]\nplugin = rawlog\n") ==
        "p.ini: [source] file: missing required key (the rawlog to replay)");
  CHECK(errorOf(source("skip_bad = sometimes\n")) ==
        "p.ini: [source] skip_bad: 'sometimes' is not a boolean (expected true or false)");
  CHECK(errorOf("[pipeline]\nstages = src\n[src]\nplugin = mrpt_sensor\ndriver = "
                "CHokuyoURG\nidle_timeout = -3\n") ==
        "p.ini: [src] idle_timeout: -3 is out of range [0, 3600] s");
  CHECK(errorOf(
            "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = /nope/walk.rawlog\n") ==
        "p.ini: [source] file: file '/nope/walk.rawlog' does not exist");
  CHECK(errorOf("[pipeline]\nstages = source trakc\n[source]\nplugin = rawlog\nfile = " + kSena +
                "\n[track]\nplugin = rawlog\n") ==
        "p.ini: [pipeline] stages: no section [trakc] (did you mean [track]?)");
  CHECK(errorOf("[source]\nplugin = rawlog\n").find("no [pipeline] section") != std::string::npos);
  CHECK(errorOf("[pipeline]\nstages = a b\n[a]\nplugin = rawlog\nfile = " + kSena +
                "\n[b]\nplugin = rawlog\nfile = " + kSena + "\n") ==
        "p.ini: [b] plugin: 'rawlog' is a sensor; only the first stage may be one");
  // Odometry sets the robot's pose: after a classifier had placed detections with the old one it
  // would rewrite the frame under them.
  CHECK(errorOf(source("").replace(source("").find("stages = source"), 15,
                                   "stages = source seg cls odo") +
                "[seg]\nplugin = scan_segments\n[cls]\nplugin = svm\nmodel = " +
                PEDTRACK_SOURCE_DIR + "/models/legs_svm.yml\n[odo]\nplugin = scan_odometry\n") ==
        "p.ini: [odo] plugin: 'scan_odometry' sets the robot's pose and must run before [cls] (a "
        "classifier, which places what it finds in the fixed frame)");
  // A key that moved to another plugin says where it went.
  CHECK_THAT(
      errorOf(source("").replace(source("").find("stages = source"), 15, "stages = source track") +
              "[track]\nplugin = leg_people\nscan_odometry = on\n"),
      Catch::Contains("[track] scan_odometry: no longer a key of plugin 'leg_people': "
                      "scan matching is a stage of its own"));
  CHECK_NOTHROW(
      parse(source("").replace(source("").find("stages = source"), 15, "stages = source seg odo") +
            "[seg]\nplugin = scan_segments\n[odo]\nplugin = scan_odometry\n"));
}

TEST_CASE("relative files resolve against the pipeline file's folder", "[config]") {
  const std::string dir = freshDir("config_relative");
  writeFile(dir + "/walk.rawlog", readFile(kSena));
  writeFile(dir + "/p.ini",
            "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = walk.rawlog\n");
  const auto cfg = PipelineConfig::load(dir + "/p.ini", {}, testRegistry());
  CHECK(cfg.stages[0].params.getString("file") == dir + "/walk.rawlog");
  CHECK_THROWS_WITH(PipelineConfig::load(dir + "/missing.ini", {}, testRegistry()),
                    dir + "/missing.ini: pipeline file not found");
}

TEST_CASE("set overrides, and input replaces the source", "[config]") {
  PipelineOverrides ov;
  ov.sets = {"source.rate=realtime", "source.sensor_label = LASER"};
  auto cfg = parse(source(""), ov);
  CHECK(cfg.stages[0].params.getString("rate") == "realtime");
  CHECK(cfg.stages[0].params.getString("sensor_label") == "LASER");
  CHECK(cfg.ini->read_string("source", "rate", "") == "realtime");

  ov.sets = {"source.rte=max"};
  CHECK(errorOf(source(""), ov) ==
        "p.ini: [source] rte: unknown key for plugin 'rawlog' (did you mean 'rate'?)");
  ov.sets = {"nodot=1"};
  CHECK(errorOf(source(""), ov) == "--set 'nodot=1': expected section.key=value");

  PipelineOverrides in;
  in.input = mrptDataset("rot_scan_2d.rawlog");
  cfg = parse("[pipeline]\nstages = source\n[source]\nplugin = mrpt_sensor\ndriver = CHokuyoURG\n",
              in);
  CHECK(cfg.stages[0].descriptor->name == "rawlog");
  CHECK(cfg.stages[0].params.getString("file") == in.input);
  in.topic = "/scan";
  CHECK(errorOf(source(""), in) == "--topic: only a .bag input has topics ('" + in.input + "')");
}

TEST_CASE("a source plugin override keeps the keys it declares; a stage is appended once",
          "[config]") {
  // `pedtrack ros` swaps the source and appends its publisher this way.
  PipelineOverrides ov;
  ov.source_plugin = "mrpt_sensor";
  ov.sets = {"source.driver=CHokuyoURG", "source.idle_timeout=3"};
  ov.append_stage = {"band", "height_band"};
  auto cfg = parse(source("skip_bad = true\n"), ov);
  REQUIRE(cfg.stages.size() == 2);
  CHECK(cfg.stages[0].descriptor->name == "mrpt_sensor");
  CHECK(cfg.stages[0].params.getDouble("idle_timeout") == 3);
  CHECK(cfg.ini->read_string("source", "file", "") == "");  // rawlog's keys are gone
  CHECK(cfg.ini->read_string("source", "skip_bad", "") == "");
  CHECK(cfg.stages[1].section == "band");
  CHECK(cfg.stages[1].descriptor->name == "height_band");
  CHECK(cfg.ini->read_string("pipeline", "stages", "") == "source band");
  // A section of that name is taken: the stage gets another; a stage of that plugin: none.
  cfg = parse(source("[band]\nplugin = height_band\n"), ov);
  CHECK(cfg.stages.size() == 2);
  CHECK(cfg.stages[1].section == "band_height_band");
  ov.sets.push_back("pipeline.stages=source band");
  cfg = parse(source("[band]\nplugin = height_band\n"), ov);
  REQUIRE(cfg.stages.size() == 2);
  CHECK(cfg.stages[1].section == "band");
}

TEST_CASE("environment variables expand; unknown ones are named", "[config]") {
  setenv("PEDTRACK_TEST_DATASETS", "/usr/share/mrpt/datasets", 1);
  const auto cfg = parse(
      "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = "
      "${PEDTRACK_TEST_DATASETS}/rot_scan_2d.rawlog\n");
  CHECK(cfg.stages[0].params.getString("file") == mrptDataset("rot_scan_2d.rawlog"));
  CHECK(
      errorOf("[pipeline]\nstages = source\n\n[source]\nfile = ${PEDTRACK_NOT_SET_ANYWHERE}/x\n") ==
      "p.ini:5: ${PEDTRACK_NOT_SET_ANYWHERE} is neither @define'd in the file nor set in the "
      "environment");
  // --input replaces the source's keys: an unset variable there is not needed (a shipped
  // config whose default input is under $PEDTRACK_DATA, run on the user's own file).
  PipelineOverrides ov;
  ov.input = mrptDataset("rot_scan_2d.rawlog");
  const auto replaced = parse(
      "[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = ${PEDTRACK_NOT_SET_X}/x\n",
      ov);
  CHECK(replaced.stages[0].params.getString("file") == mrptDataset("rot_scan_2d.rawlog"));
}

TEST_CASE("every shipped pipeline in configs/ validates", "[config]") {
  const std::string data = sharedDataDir();
  if (!data.empty()) setenv("PEDTRACK_DATA", data.c_str(), 1);
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(PEDTRACK_SOURCE_DIR "/configs")) {
    if (e.path().extension() != ".ini") continue;
    const std::string text = readFile(e.path().string());
    if (data.empty() && text.find("${PEDTRACK_DATA}") != std::string::npos) {
      WARN("skipped " << e.path() << ": needs ../shared/data");
      continue;
    }
    INFO(e.path());
    CHECK_NOTHROW(PipelineConfig::load(e.path().string(), {}, testRegistry()));
    ++checked;
  }
  CHECK(checked >= 3);
}
