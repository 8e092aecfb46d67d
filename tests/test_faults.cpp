// The fault-injection matrix: the shipped pipelines (2D leg, 2D torso, 3D VLP-16, 3D MHE) run on
// their simulated scenes with every fault of the `[faults]` section, through `pedtrack run`.
// Expected each time: exit 0 and status ok, no frame failed, a counted warning in run.json, no
// NaN or infinity in tracks.csv, tracking that goes on after the fault; a blind sensor's tracks
// coast and are deleted as configured. And the unit behaviour of the FrameGuard itself.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "pedtrack/frame_guard.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

struct Row {
  long frame = 0, track = 0;
  std::string status;
};

struct Outcome {
  std::string json, csv;
  std::vector<Row> rows;
  long lastFrame() const { return rows.empty() ? -1 : rows.back().frame; }
  std::set<long> idsAt(long frame, bool confirmed_only = true) const {
    std::set<long> ids;
    for (const auto& r : rows)
      if (r.frame == frame && (!confirmed_only || r.status != "tentative")) ids.insert(r.track);
    return ids;
  }
  std::size_t rowsAfter(long frame) const {
    std::size_t n = 0;
    for (const auto& r : rows) n += r.frame > frame;
    return n;
  }
};

Outcome run(const std::string& pipeline, long frames, const std::vector<std::string>& faults,
            const std::string& tag) {
  const std::string dir = freshDir("faults_" + tag);
  std::vector<std::string> args{
      "run", kConfigs + pipeline, "--max-frames", std::to_string(frames), "--out", dir, "-q"};
  for (const auto& f : faults) args.insert(args.end(), {"--set", "faults." + f});
  const auto r = runHost(args);
  INFO(pipeline << " with " << tag << ":\n" << r.output);
  REQUIRE(r.exit_code == 0);
  Outcome o;
  o.json = readFile(dir + "/run.json");
  o.csv = readFile(dir + "/tracks.csv");
  const auto ls = lines(o.csv);
  for (std::size_t i = 1; i < ls.size(); ++i) {
    std::vector<std::string> c;
    std::stringstream ss(ls[i]);
    for (std::string cell; std::getline(ss, cell, ',');) c.push_back(cell);
    REQUIRE(c.size() >= 18);
    o.rows.push_back({std::stol(c[1]), std::stol(c[2]), c[17]});
  }
  return o;
}

bool hasNonFinite(const std::string& csv) {
  std::string lower;
  for (char c : csv) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos;
}

struct FaultCase {
  std::string name;               // tag
  std::vector<std::string> keys;  // faults.* settings
  std::string warning;            // the count that must be > 0
  long at;                        // the frame of the fault (tracking must go on after it)
};

// Each fault once, at frame 20 or from frame 20 on where it has a place.
const std::vector<FaultCase> kMatrix{
    {"nonfinite", {"nonfinite_ranges=0.1"}, "invalid_", 0},
    {"zero", {"zero_ranges=0.1"}, "faults_zero_ranges", 0},
    {"max", {"max_ranges=0.1"}, "faults_max_ranges", 0},
    {"empty", {"empty_every=5"}, "empty_frames", 0},
    // 1,000,000 points; 200,000 under the sanitizers, which are slow on big clouds.
    {"huge_cloud",
     {"huge_cloud_at=20", kSanitized ? "huge_cloud_points=200000" : "huge_cloud_points=1000000"},
     "faults_huge_clouds",
     20},
    {"time_repeat", {"repeat_time_at=20,21"}, "time_repeats", 21},
    {"time_backwards", {"backwards_time_at=20"}, "time_backwards", 20},
    {"time_jump", {"jump_time_at=20"}, "time_jumps", 20},
    {"time_nan", {"nan_time_at=20"}, "bad_time", 20},
    {"dropped_frames", {"drop_every=4"}, "frame_gaps", 0},
    {"odometry_jump", {"odometry_jump_at=20"}, "odometry_jumps", 20},
};

void checkCase(const std::string& pipeline, long frames, const FaultCase& fc) {
  const Outcome o =
      run(pipeline, frames, fc.keys, pipeline.substr(0, pipeline.find('.')) + "_" + fc.name);
  INFO(pipeline << ", fault " << fc.name << "\nrun.json: " << o.json);
  CHECK(o.json.find("\"status\": \"ok\"") != std::string::npos);
  CHECK(jsonValue(o.json, "frames_failed") == 0);
  CHECK(jsonValue(o.json, "nonfinite_track_rows") == 0);
  // The warning: counted by the guard (input_warnings) or, for data that is odd but valid, by
  // the injector under the source (faults_*). "invalid_" is either kind of invalid return.
  const double warned = fc.warning == "invalid_" ? jsonValue(o.json, "invalid_ranges") +
                                                       jsonValue(o.json, "invalid_points")
                                                 : jsonValue(o.json, fc.warning);
  CHECK(warned > 0);
  CHECK_FALSE(hasNonFinite(o.csv));
  // Tracking goes on after the fault: tracks in the last ten frames, and the run reached them.
  CHECK(o.rowsAfter(std::max(fc.at, frames - 11)) > 0);
}

}  // namespace

// Under the sanitizers (scripts/check.sh) the pipelines run 5-20 times slower: fewer frames
// there, the faults still inside them (frame 20 at the latest).
#ifdef PEDTRACK_SANITIZED
constexpr long kFrames2d = 35, kFrames3d = 26, kFramesMhe = 22;
#else
constexpr long kFrames2d = 70, kFrames3d = 45, kFramesMhe = 30;
#endif

TEST_CASE("faults: the 2D leg pipeline survives every fault", "[faults][legs]") {
  for (const auto& fc : kMatrix) checkCase("people_2d_legs.ini", kFrames2d, fc);
}

TEST_CASE("faults: the 2D torso pipeline (imm_pdaf) survives every fault", "[faults][torso]") {
  for (const auto& fc : kMatrix) checkCase("people_2d_torso.ini", kFrames2d, fc);
}

TEST_CASE("faults: the 3D VLP-16 pipeline (imm_shape) survives every fault", "[faults][3d]") {
  for (const auto& fc : kMatrix) checkCase("people_3d_vlp16.ini", kFrames3d, fc);
}

TEST_CASE("faults: the 3D MHE pipeline (mhe_mlesac) survives the data faults", "[faults][mhe]") {
  // MHE costs about 0.5 s a frame: the faults that reach its solver, not the clock ones; under
  // the sanitizers (several s a frame) the one that changes the data its solver sees (the huge
  // cloud is the segmenter's, run under the sanitizers by the imm_shape case above).
  for (const auto& fc : kMatrix)
    if (fc.name == "nonfinite" ||
        (!kSanitized && (fc.name == "huge_cloud" || fc.name == "empty" || fc.name == "time_jump")))
      checkCase("people_3d_mhe.ini", kFramesMhe, fc);
}

TEST_CASE("faults: tracks coast over empty frames and are deleted while the sensor is blind",
          "[faults][legs][torso]") {
  for (const std::string pipeline : {"people_2d_legs.ini", "people_2d_torso.ini"}) {
    // Every fifth frame empty: the people tracked before an empty frame are the people tracked
    // after it (they coasted through it).
    const std::string tag = pipeline.substr(0, pipeline.find('.'));
    const Outcome coast = run(pipeline, 60, {"empty_every=5"}, tag + "_coast");
    std::size_t kept = 0, compared = 0;
    for (long k = 29; k < 60; k += 5) {
      const auto before = coast.idsAt(k - 1), after = coast.idsAt(k + 1);
      for (long id : before) kept += after.count(id);
      compared += before.size();
    }
    INFO(pipeline << ": " << kept << " of " << compared << " tracks kept over an empty frame");
    REQUIRE(compared > 0);
    CHECK(kept >= 0.8 * compared);

    // Blind from frame 30 for 40 frames (4 s): every track is deleted by the time it sees again
    // (both trackers delete after at most 2 s without data), and people are tracked after.
    const Outcome blind = run(pipeline, 110, {"blind_at=30", "blind_frames=40"}, tag + "_blind");
    INFO(pipeline << " blind\nrun.json: " << blind.json);
    CHECK(jsonValue(blind.json, "empty_frames") == 40);
    REQUIRE_FALSE(blind.idsAt(29).empty());
    CHECK(blind.idsAt(69, false).empty());
    CHECK(blind.rowsAfter(90) > 0);
  }
}

TEST_CASE("faults: a classifier model that fails to load is one clear error, exit 2", "[faults]") {
  const std::string dir = freshDir("faults_model");
  writeFile(dir + "/broken_svm.yml", "%YAML:1.0\nopencv_ml_svm:\n  format: 3\n  svmType: [");
  const auto r =
      runHost({"run", kConfigs + "people_2d_legs.ini", "--set",
               "classify.model=" + dir + "/broken_svm.yml", "--out", dir + "/out", "-q"});
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(lines(r.output).size() == 1);
  CHECK(r.output.find("broken_svm.yml") != std::string::npos);
}

TEST_CASE("faults: bad [faults] keys and values are one-line config errors", "[faults]") {
  const auto unknown = runHost({"run", kConfigs + "people_2d_legs.ini", "--set",
                                "faults.nonfinite_range=0.1", "--max-frames", "1"});
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.output.find("[faults] nonfinite_range: unknown key for fault injection (did "
                            "you mean 'nonfinite_ranges'?)") != std::string::npos);
  const auto frames = runHost({"run", kConfigs + "people_2d_legs.ini", "--set",
                               "faults.jump_time_at=1.5", "--max-frames", "1"});
  CHECK(frames.exit_code == 2);
  CHECK(frames.output.find("[faults] jump_time_at") != std::string::npos);
}

TEST_CASE("FrameGuard: skips frames it cannot use and cleans impossible returns", "[faults]") {
  FrameGuard guard(false);
  const auto scanFrame = [](double t, std::vector<float> ranges) {
    Frame f;
    f.t = t;
    auto s = mrpt::obs::CObservation2DRangeScan::Create();
    s->aperture = static_cast<float>(M_PI);
    s->maxRange = 30;
    s->resizeScan(ranges.size());
    for (std::size_t i = 0; i < ranges.size(); ++i) {
      s->setScanRange(i, ranges[i]);
      s->setScanRangeValidity(i, true);
    }
    f.observations.push_back(s);
    return f;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  const auto count = [&](const std::string& k) {
    for (const auto& [name, n] : guard.counts())
      if (name == k) return n;
    FAIL("no count " << k);
    return 0L;
  };

  Frame f = scanFrame(100.0, {1.f, nan, inf, 0.f, -1.f, 2.f});
  REQUIRE(guard.admit(f));
  const auto& scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan&>(*f.observations[0]);
  CHECK(scan.getScanRangeValidity(0));
  for (std::size_t i = 1; i <= 4; ++i) CHECK_FALSE(scan.getScanRangeValidity(i));
  CHECK(scan.getScanRangeValidity(5));
  CHECK(count("invalid_ranges") == 4);

  Frame same = scanFrame(100.0, {1.f});
  CHECK_FALSE(guard.admit(same));
  CHECK(count("time_repeats") == 1);
  Frame back = scanFrame(99.5, {1.f});
  CHECK_FALSE(guard.admit(back));
  CHECK(count("time_backwards") == 1);
  Frame reset = scanFrame(50.0, {1.f});  // 50 s back: a clock reset, used
  CHECK(guard.admit(reset));
  CHECK(count("clock_resets") == 1);
  Frame nan_t = scanFrame(std::numeric_limits<double>::quiet_NaN(), {1.f});
  CHECK_FALSE(guard.admit(nan_t));
  CHECK(count("bad_time") == 1);
  Frame jump = scanFrame(700.0, {1.f});
  CHECK(guard.admit(jump));
  CHECK(count("time_jumps") == 1);

  // A regular 10 Hz stream, then one frame missing.
  double t = 700.0;
  for (int i = 0; i < 10; ++i) {
    Frame g = scanFrame(t += 0.1, {1.f});
    CHECK(guard.admit(g));
  }
  CHECK(count("frame_gaps") == 0);
  Frame gap = scanFrame(t += 0.2, {1.f});
  CHECK(guard.admit(gap));
  CHECK(count("frame_gaps") == 1);

  // Odometry: 0.5 m in 0.1 s is driving; 8 m is a jump.
  Frame a = scanFrame(t += 0.1, {1.f});
  a.has_odometry = true;
  a.robot_pose = mrpt::poses::CPose3D(0.5, 0, 0, 0, 0, 0);
  CHECK(guard.admit(a));
  CHECK(count("odometry_jumps") == 0);
  Frame b = scanFrame(t += 0.1, {1.f});
  b.has_odometry = true;
  b.robot_pose = mrpt::poses::CPose3D(8.5, 0, 0, 0, 0, 0);
  CHECK(guard.admit(b));
  CHECK(count("odometry_jumps") == 1);
  Frame bad_pose = scanFrame(t += 0.1, {1.f});
  bad_pose.robot_pose = mrpt::poses::CPose3D(std::nan(""), 0, 0, 0, 0, 0);
  CHECK_FALSE(guard.admit(bad_pose));
  CHECK(count("bad_poses") == 1);

  // A cloud: non-finite points and points at the sensor go, the rest stay.
  Frame c;
  c.t = (t += 0.1);
  auto pc = mrpt::obs::CObservationPointCloud::Create();
  pc->pointcloud = mrpt::maps::CSimplePointsMap::Create();
  pc->pointcloud->insertPoint(1, 2, 0.5);
  pc->pointcloud->insertPoint(nan, 2, 0.5);
  pc->pointcloud->insertPoint(0, 0, 0);
  pc->pointcloud->insertPoint(3, inf, 0.5);
  pc->pointcloud->insertPoint(4, 1, 0.2);
  c.observations.push_back(pc);
  CHECK(guard.admit(c));
  CHECK(pc->pointcloud->size() == 2);
  CHECK(count("invalid_points") == 3);
  CHECK(count("empty_frames") == 0);
  Frame empty = scanFrame(t += 0.1, {});
  CHECK(guard.admit(empty));
  CHECK(count("empty_frames") == 1);
}
