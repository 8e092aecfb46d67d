// The leg-height pipeline end to end: configs/people_2d_legs.ini on simulated leg-height scenes
// scored by `pedtrack eval`, on leg_tracker's demo bag (no odometry: scan matching runs by
// itself) and configs/negative_2_merged.ini on the wheelchair bag that has no people; person
// following marks one person; leg_pose (configs/leg_pose_p3.ini) on P3's scenario 1 over seeds.
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <vector>

#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

// Distinct track ids of a tracks.csv (the third column).
std::set<std::string> trackIds(const std::string& csv) {
  std::set<std::string> ids;
  const auto rows = lines(readFile(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto a = rows[i].find(',');
    const auto b = rows[i].find(',', a + 1);
    const auto c = rows[i].find(',', b + 1);
    if (c != std::string::npos) ids.insert(rows[i].substr(b + 1, c - b - 1));
  }
  return ids;
}

// people_2d_legs.ini on a shipped scenario with `sets` as --set overrides, into a fresh run
// directory `name`; the host must succeed. Returns the directory.
std::string runScenario(const std::string& name, const std::string& scenario,
                        const std::vector<std::string>& sets = {}) {
  const std::string dir = freshDir(name);
  std::vector<std::string> args{"run", kConfigs + "people_2d_legs.ini", "--set",
                                "source.scenario=" + kConfigs + "scenarios/" + scenario};
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  args.insert(args.end(), {"--out", dir, "-q"});
  const auto r = runHost(args);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  return dir;
}

// Seeds a P3 heading figure is measured over under the sanitizers (scripts/check.sh), where
// leg_pose runs ~20 times slower: the same code paths on a few seeds there, the figure itself
// checked over every seed in the Release build (this file is labelled `full_length`).
constexpr int kSanitizedP3Runs = 4;

// leg_pose_p3.ini over `runs` seeds from `seed_base` of a shipped P3 scenario (`pedtrack
// montecarlo`; kSanitizedP3Runs of them under the sanitizers); the host must succeed. Returns
// montecarlo.json.
std::string p3MonteCarlo(const std::string& scenario, int runs, int seed_base) {
  if (kSanitized) runs = kSanitizedP3Runs;
  const std::string dir = freshDir(scenario + "_montecarlo");
  const auto r =
      runHost({"montecarlo", kConfigs + "leg_pose_p3.ini",
               kConfigs + "scenarios/" + scenario + ".ini", "--runs", std::to_string(runs),
               "--seed-base", std::to_string(seed_base), "--out", dir, "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string json = readFile(dir + "/montecarlo.json");
  // A heading that has lost the walker is off by ~90° on average; the few seeds run under the
  // sanitizers must at least follow them.
  if (kSanitized) CHECK(jsonNumber(json, "heading_mae_deg") < 45);
  return json;
}

}  // namespace

TEST_CASE("people_2d_legs.ini keeps a person who stands still for 60 s on one track",
          "[legs][pipeline]") {
  const std::string dir = runScenario("legs_standing", "legs_standing_60s.ini");
  // Measured: one track from 5.4 to 75.8 s, MOTA 0.976, no ID switch, no false positive.
  const std::string stander = evalRunJson(dir, {"--following", "1"});
  CHECK(jsonNumber(stander, "mota") >= 0.9);
  CHECK(jsonNumber(stander, "id_switches") == 0);
  CHECK(jsonNumber(evalRunJson(dir), "false_positives") <= 10);
  // The simulator gives odometry (a standing scanner's), so the scan_odometry stage (mode auto)
  // stays off.
  CHECK(readFile(dir + "/run.json").find("scan_matches") == std::string::npos);
}

TEST_CASE("a person hidden 12 s behind a pillar comes back on the track they left with",
          "[legs][pipeline]") {
  // Tracked for 5 s before hiding, so kept 5 s unseen in plain view; hidden, up to
  // max_coast_occluded (30 s). Measured: no ID switch (seeds 1-12 and 100-111 of the scenario:
  // 0, against one in every run with max_coast_occluded = 0).
  const std::string dir = runScenario("legs_pillar", "legs_pillar_12s.ini");
  const std::string hider = evalRunJson(dir, {"--following", "1"});
  CHECK(jsonNumber(hider, "id_switches") == 0);
  CHECK(jsonNumber(hider, "mota") >= 0.8);
  CHECK(jsonNumber(evalRunJson(dir), "false_positives") <= 10);
}

TEST_CASE("a person who waits in the scanner's blind spot comes back on their track",
          "[legs][pipeline]") {
  // In view ~4 s (tracked ~3 s, so kept ~3 s unseen in plain view), then ~8.5 s where no scanner
  // looks. Measured (seeds 1-20 of the scenario): no ID switch in any run, MOTA 0.91; with
  // track.out_of_view=false an ID switch in every run (MOTA 0.84).
  const std::string dir = runScenario("legs_behind", "legs_behind_scanner.ini");
  const std::string walker = evalRunJson(dir, {"--following", "1"});
  CHECK(jsonNumber(walker, "id_switches") == 0);
  CHECK(jsonNumber(walker, "mota") >= 0.85);
  const std::string off =
      runScenario("legs_behind_off", "legs_behind_scanner.ini", {"track.out_of_view=false"});
  CHECK(jsonNumber(evalRunJson(off, {"--following", "1"}), "id_switches") == 1);
}

TEST_CASE("person following marks the person standing in front, and only them",
          "[legs][pipeline]") {
  // legs_standing_60s: person 1 stands 60 s at (3.6, 0) in front of the scanner, person 2 crosses
  // the room behind. The follow zone is widened to reach 3.6 m.
  const std::string dir = runScenario("legs_follow", "legs_standing_60s.ini",
                                      {"track.follow=nearest", "track.follow_zone=0.3 4.5 1.5"});
  // Fields of each row: frame (1), track (2), status (17).
  std::map<std::string, int> following_per_frame;
  std::set<std::string> followed;
  const auto rows = lines(readFile(dir + "/tracks.csv"));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> f;
    std::size_t a = 0;
    for (std::size_t b; (b = rows[i].find(',', a)) != std::string::npos; a = b + 1)
      f.push_back(rows[i].substr(a, b - a));
    f.push_back(rows[i].substr(a));
    REQUIRE(f.size() > 17);
    if (f[17] != "following") continue;
    ++following_per_frame[f[1]];
    followed.insert(f[2]);
  }
  // Measured: 681 of the stander's 705 rows (the first ones come before confirmation), one id.
  CHECK(following_per_frame.size() >= 600);
  CHECK(followed.size() == 1);
  for (const auto& [frame, n] : following_per_frame) CHECK(n == 1);
}

TEST_CASE("people_2d_legs.ini tracks the 10-person leg-height crowd", "[legs][pipeline]") {
  const std::string dir = freshDir("legs_crowd");
  const auto r = runHost({"run", kConfigs + "people_2d_legs.ini", "--out", dir, "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // Measured: MOTA 0.852, MOTP 0.063 m, 11 ID switches (README "Leg-height tracking"; 0.788
  // and 30 before confirmed people got a walker's noise).
  const std::string e = evalRunJson(dir);
  CHECK(jsonNumber(e, "mota") >= 0.78);
  CHECK(jsonNumber(e, "motp_m") <= 0.075);
  CHECK(jsonNumber(e, "id_switches") <= 25);
}

TEST_CASE("leg_pose keeps P3 scenario 1's walker facing the robot as they back away",
          "[legs][pipeline]") {
  // 40 seeds of the walk, turn and back-up: with a leg hidden, neither a turn rate kept from
  // before (heading_hidden_turn_tau) nor the midpoint's inferred motion may swing the estimate
  // round, and the mirror image (a turn the other way, the legs renamed) may not take the lead
  // as they stop. Measured 8.3°; 10.0° with stop 37's bank of 8, heading_hidden_turn_tau 0.2 s
  // and heading_backward_per_metre 1, where 16.3° with the motion evidence on hidden-leg scans,
  // 19.3° without heading_hidden_turn_tau, 19.5° with neither (README "Leg-height tracking").
  const std::string j = p3MonteCarlo("p3_s1_straight_turn_back", 40, 100);
  if (!kSanitized) CHECK(jsonNumber(j, "heading_mae_deg") < 9.5);
  CHECK(jsonNumber(j, "position_mae_m") < 0.05);
}

TEST_CASE("leg_pose reads P3 scenario 3's side view with the partly hidden leg less sure",
          "[legs][pipeline]") {
  // 30 seeds of the turn and walk-off seen from the side, where the far leg shows as a sliver
  // beside the near one: its circle sits centimetres off (occluded_width, occluded_sigma_leg).
  // After the turn the walker sets off with a leg hidden, where the turn rate relaxes within
  // heading_hidden_turn_tau (0.05 s). Measured 5.0°; 5.6° with stop 37's bank of 8,
  // heading_hidden_turn_tau 0.2 s and heading_backward_per_metre 1, and there 6.7° with
  // occluded_width = 0.
  const std::string j = p3MonteCarlo("p3_s3_turn_straight", 30, 1);
  if (!kSanitized) CHECK(jsonNumber(j, "heading_mae_deg") < 5.3);
}

TEST_CASE("leg_pose reads P3 scenario 2's side steps from their slow start", "[legs][pipeline]") {
  // 30 seeds of the side step, 180° turn and side step back. The motion counts from
  // heading_motion_speed (0.15 m/s): a side step starting slowly is not read as a turn. Measured
  // 3.7° (P3's target 5°); 7.6° with heading_motion_speed = 0.3.
  const std::string j = p3MonteCarlo("p3_s2_sidestep_turn", 30, 1);
  if (!kSanitized) CHECK(jsonNumber(j, "heading_mae_deg") < 5);
}

TEST_CASE("leg_pose turns round a walker left facing backward by P3 scenario 4's quick turns",
          "[legs][pipeline]") {
  // 100 seeds of the random walk. Mid-turn the lead can pass to a hypothesis walking backward
  // far from the prediction; that doubts the facing as a large innovation does, and the walk that
  // follows turns the estimate round. Measured 12.6°; 14.4° when only the best's own innovation
  // counted (the estimate then stayed facing backward for seconds).
  const std::string j = p3MonteCarlo("p3_s4_random", 100, 200);
  if (!kSanitized) CHECK(jsonNumber(j, "heading_mae_deg") < 13.5);
}

#ifdef PEDTRACK_WITH_ROSBAG
TEST_CASE("on a bag without odometry scan matching runs by itself", "[legs][pipeline]") {
  const std::string data = sharedDataDir();
  const std::string bag =
      data.empty() ? "" : data + "/leg_tracker/demo_stationary_simple_environment.bag";
  requireData(bag);
  const std::string dir = freshDir("legs_demo_bag");
  const auto r =
      runHost({"run", kConfigs + "people_2d_legs.ini", "--input", bag, "--out", dir, "-q"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string run = readFile(dir + "/run.json");
  // 1265 scans: every one after the first is matched, none rejected (the scanner stands still).
  CHECK(jsonValue(run, "scan_matches") >= 1200);
  CHECK(jsonValue(run, "scan_matches_rejected") <= 10);
  // Measured 10 tracks over the bag's 126 s (mean 34 s), a few people walking round the room
  // (27 before confirmed people got a walker's noise and re-identification looked where they
  // were last seen as well). Fewer than 5 would be people missed; many more, tracks broken.
  const auto ids = trackIds(dir + "/tracks.csv");
  CHECK(ids.size() >= 5);
  CHECK(ids.size() <= 40);
}

TEST_CASE("person following on the benchmark's outdoor recording: the standing person is found",
          "[legs][pipeline]") {
  // The first 240 s of the ICRA 2015 benchmark's outdoor following recording, scored by its rules
  // (followed person only). For its first 1.4 s the person stands with one foot ahead, both legs
  // in one segment: split_jump finds them there. Misses as in `pedtrack eval --following`.
  const std::string bag =
      requiredDataFile("leg_tracker_benchmark/person_following_outdoor_1_first240s.bag");
  auto run = [&](const std::string& name, const std::string& split) {
    const std::string dir = freshDir(name);
    const auto r =
        runHost({"run", kConfigs + "people_2d_legs.ini", "--input", bag, "--set",
                 "track.follow=nearest", "--set", "legs.split_jump=" + split, "--out", dir, "-q"});
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto e =
        runHost({"eval", "--truth", bag, "--tracks", dir + "/tracks.csv", "--following", "--json"});
    INFO(e.output);
    REQUIRE(e.exit_code == 0);
    return e.output;
  };
  // Measured: 7 misses of 1,811 annotated scans, 0.34 tracks on no annotated person per scan;
  // without the split 21 misses, all in the first 2.1 s.
  const std::string with = run("legs_following_split", "0.07");
  CHECK(jsonNumber(with, "misses") <= 12);
  CHECK(jsonNumber(with, "motp_m") <= 0.08);
  CHECK(jsonNumber(with, "non_target_tracks_per_scan") <= 0.45);
  CHECK(jsonNumber(run("legs_following_no_split", "0"), "misses") >= 18);
}

TEST_CASE("negative_2_merged.ini confirms few people where there are none", "[legs][pipeline]") {
  const std::string data = sharedDataDir();
  requireData(data.empty() ? "" : data + "/leg_tracker/negative_2.bag");
  const std::string dir = freshDir("legs_negative_2");
  const auto r = runShell("PEDTRACK_DATA='" + data + "' '" + std::string(PEDTRACK_BIN) + "' run '" +
                          kConfigs + "negative_2_merged.ini' --out '" + dir + "' -q");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // Measured: 0 confirmed tracks in 57.8 s; with 0.5 % of the returns dropped at random
  // (faults.nonfinite_ranges, seeds 1-8) 1 1 0 0 0 0 1 1. Without max_travel_turn_rate 3, and
  // 3 1 5 1 1 3 2 3: every ghost was confirmed by the way it went while the chair turned. The
  // scan matcher ran.
  CHECK(trackIds(dir + "/tracks.csv").size() <= 1);
  const std::string off = freshDir("legs_negative_2_turn_off");
  const auto r_off =
      runShell("PEDTRACK_DATA='" + data + "' '" + std::string(PEDTRACK_BIN) + "' run '" + kConfigs +
               "negative_2_merged.ini' --out '" + off + "' -q --set track.max_travel_turn_rate=0");
  REQUIRE(r_off.exit_code == 0);
  CHECK(trackIds(off + "/tracks.csv").size() >= 2);
  CHECK(jsonValue(readFile(dir + "/run.json"), "scan_matches") >= 400);
}
#endif  // PEDTRACK_WITH_ROSBAG

TEST_CASE("without odometry a robot driving through a crowd is tracked from its scan matching",
          "[legs][pipeline]") {
  // legs_crowd_10_moving: 10 walkers, 10 poles and bins, no walls, the robot driving a loop.
  // odometry = false: the frames carry no robot motion, so scan_odometry (mode auto) matches the
  // sparse scans; the tracks are scored in the sensor frame. Seed 31, where with one keyframe
  // per match the estimate turned 100° away (sensor-frame MOTA 0.46; measured now 0.79; with the
  // simulator's noisy odometry 0.84).
  const std::string dir = runScenario("legs_no_odometry", "legs_crowd_10_moving.ini",
                                      {"source.odometry=false", "source.seed=31"});
  CHECK(readFile(dir + "/run.json").find("scan_matches") != std::string::npos);
  CHECK(jsonNumber(evalRunJson(dir, {"--frame", "sensor"}), "mota") >= 0.75);
  // scan_odometry mode = on with odometry too: the match replaces the odometry (composing the two
  // counted every motion twice: sensor-frame MOTA 0.59 on the scenario's own seed; now 0.81).
  const std::string both =
      runScenario("legs_scan_odometry_on", "legs_crowd_10_moving.ini", {"odometry.mode=on"});
  CHECK(jsonNumber(evalRunJson(both, {"--frame", "sensor"}), "mota") >= 0.7);
}

TEST_CASE("a wheelchair without odometry keeps following its person through an open space",
          "[legs][pipeline]") {
  // legs_following_open: the leader walks 1.5 m ahead of the chair for 45 s, two bends and a
  // sharp turn, among passers-by, trees and poles; no walls, no odometry (scan matching only).
  // Measured: the leader's MOTA 0.898 (most misses in the first 3.7 s: standing, then until
  // confirmed), no ID switch, MOTP 0.032 m (with the clutter off the path: robot_clearance;
  // before it 0.897, 1 ID switch, 0.024 m, lost_velocity_window costing that switch here while
  // over seeds 1-24, 100-123 and 200-223 it took the leader's ID switches from 39 to 28).
  const std::string dir =
      runScenario("legs_following_open", "legs_following_open.ini", {"source.odometry=false"});
  const std::string e = evalRunJson(dir, {"--frame", "sensor", "--following", "1"});
  CHECK(jsonNumber(e, "mota") >= 0.85);
  CHECK(jsonNumber(e, "id_switches") <= 1);
  CHECK(jsonNumber(e, "motp_m") <= 0.05);
}
