// The leg_tracker demo bag cut as a recorder killed or a copy interrupted would leave it, at 20
// offsets chosen from its own layout (inside the bag header, inside a chunk's header, inside a
// message's header and data, at a message boundary, at a chunk's end and at a chunk boundary,
// inside an index record and inside the bag's index): each cut replays exactly the complete scans
// before it, equal to the whole bag's, and ends in one error naming where its data ends. Cut at
// half, `pedtrack run` writes the whole replay's tracks up to the cut and exits 1.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "bag_layout.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

std::string demoBag() {
  return requiredDataFile("leg_tracker/demo_stationary_simple_environment.bag");
}

struct Replay {
  std::vector<double> t;
  std::vector<std::vector<float>> ranges;
  std::string error;
};

Replay replayBag(const std::string& file) {
  Replay r;
  r.error = readFramesUntilError(
      "[pipeline]\nstages = source\n[source]\nplugin = rosbag\nfile = " + file + "\n",
      [&](const Frame& f) {
        r.t.push_back(f.t);
        const auto* scan =
            dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(f.observations.at(0).get());
        REQUIRE(scan);
        std::vector<float> ranges(scan->getScanSize());
        for (std::size_t k = 0; k < ranges.size(); ++k) ranges[k] = scan->getScanRange(k);
        r.ranges.push_back(std::move(ranges));
      });
  return r;
}

}  // namespace

TEST_CASE("the demo bag cut at 20 offsets replays exactly the complete scans before each cut",
          "[bag_truncation]") {
  const std::string bag = demoBag();
  const std::string bytes = readFile(bag);
  const BagLayout l = bagLayout(bytes);
  REQUIRE(l.chunk_starts.size() == 4);
  REQUIRE(l.message_ends.size() == 1265);
  const Replay whole = replayBag(bag);
  REQUIRE(whole.error.empty());
  REQUIRE(whole.t.size() == 1265);
  const std::size_t c1 = l.chunk_starts[0], c2 = l.chunk_starts[1], e1 = l.chunk_ends[0];
  const std::size_t m = l.message_ends[99];  // the end of the 100th message, a start of the next
  const std::vector<std::pair<std::size_t, const char*>> cuts = {
      {c1 - 100, "inside the bag header"},
      {c1, "after the bag header"},
      {c1 + 10, "inside the first chunk's header"},
      {*l.stops.upper_bound(c1) + 20, "inside the first connection record"},
      {m + 6, "inside a message record's header"},
      {m + 900, "inside a message's data"},
      {m, "at a message boundary"},
      {e1 - 1, "one byte before the first chunk's end"},
      {e1, "at the first chunk's end, before its index record"},
      {e1 + 30, "inside the first chunk's index record"},
      {c2, "at the boundary of chunks 1 and 2"},
      {c2 + 5, "inside chunk 2's record header"},
      {bytes.size() / 2, "at half the file"},
      {1500000, "at 1.5 MB (the cut of the issue)"},
      {(l.chunk_starts[2] + l.chunk_ends[2]) / 2, "inside chunk 3"},
      {l.chunk_ends[2], "at chunk 3's end"},
      {l.chunk_starts[3] + 200000, "inside chunk 4"},
      {l.index_pos, "at the bag's index, all of it lost"},
      {l.index_pos + 100, "inside the index's connection record"},
      {bytes.size() - 50, "inside the last chunk info"}};
  REQUIRE(cuts.size() == 20);
  const std::string dir = freshDir("bag_truncation");
  for (const auto& [cut, where] : cuts) {
    INFO("cut at byte " << cut << ", " << where);
    writeFile(dir + "/cut.bag", bytes.substr(0, cut));
    const Replay r = replayBag(dir + "/cut.bag");
    const std::size_t n = l.messagesBefore(cut);
    if (n == 0) {
      CHECK(r.t.empty());
      CHECK_THAT(r.error, Catch::Contains("no complete message before its data ends at byte " +
                                          std::to_string(l.dataEnd(cut))));
      continue;
    }
    REQUIRE(r.t.size() == n);
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(r.t[k] == whole.t[k]);
      CHECK(r.ranges[k] == whole.ranges[k]);
    }
    CHECK_THAT(r.error, Catch::Contains(dir + "/cut.bag: cut short: its data ends at byte " +
                                        std::to_string(l.dataEnd(cut)) + " of " +
                                        std::to_string(cut) + "; the " + std::to_string(n) +
                                        " complete messages before it are read"));
  }
}

TEST_CASE("pedtrack run on the demo bag cut at half: the whole run's tracks up to the cut, exit 1",
          "[bag_truncation]") {
  const std::string bag = demoBag();
  const std::string bytes = readFile(bag);
  const std::string dir = freshDir("bag_truncation_run");
  writeFile(dir + "/half.bag", bytes.substr(0, bytes.size() / 2));
  const auto whole = runHost(
      {"run", kConfigs + "people_2d_legs.ini", "--input", bag, "--out", dir + "/whole", "-q"});
  REQUIRE(whole.exit_code == 0);
  const auto half = runHost({"run", kConfigs + "people_2d_legs.ini", "--input", dir + "/half.bag",
                             "--out", dir + "/half", "-q"});
  CHECK(half.exit_code == 1);
  const std::size_t n = bagLayout(bytes).messagesBefore(bytes.size() / 2);
  CHECK_THAT(half.output,
             Catch::Contains("warning: " + dir + "/half.bag: cut short: its data ends") &&
                 Catch::Contains("error: " + dir + "/half.bag: cut short: its data ends") &&
                 Catch::Contains("the " + std::to_string(n) + " complete messages"));
  const auto a = lines(readFile(dir + "/whole/tracks.csv"));
  const auto b = lines(readFile(dir + "/half/tracks.csv"));
  REQUIRE(b.size() > 100);
  REQUIRE(b.size() < a.size());
  for (std::size_t i = 0; i < b.size(); ++i) REQUIRE(b[i] == a[i]);
  // The next row of the whole run is of a later frame than any the half run read.
  const std::string run = readFile(dir + "/half/run.json");
  CHECK(jsonValue(run, "frames_read") == double(n));
  CHECK_THAT(run, Catch::Contains("\"status\": \"error\"") &&
                      Catch::Contains("\"bag_messages_recovered\": " + std::to_string(n)));
}

TEST_CASE("pedtrack import of a cut bag writes its complete scans, then fails",
          "[bag_truncation]") {
  const std::string bytes = readFile(demoBag());
  const std::string dir = freshDir("bag_truncation_import");
  writeFile(dir + "/cut.bag", bytes.substr(0, 1500000));
  const auto r = runHost({"import", dir + "/cut.bag", "--out", dir + "/cut.rawlog", "-q"});
  const std::size_t n = bagLayout(bytes).messagesBefore(1500000);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.output, Catch::Contains("wrote " + std::to_string(n) + " observations") &&
                           Catch::Contains("error: " + dir + "/cut.bag: cut short"));
  CHECK(readAllFrames("[pipeline]\nstages = source\n[source]\nplugin = rawlog\nfile = " + dir +
                      "/cut.rawlog\n")
            .size() == n);
}

TEST_CASE("pedtrack eval --truth of a cut benchmark bag scores its complete chunks, then fails",
          "[bag_truncation]") {
  const std::string bag =
      requiredDataFile("leg_tracker_benchmark/person_following_outdoor_1_first240s.bag");
  const std::string bytes = readFile(bag);
  const std::string dir = freshDir("bag_truncation_eval");
  // Its chunks are bz2-compressed: a cut inside the third loses that chunk whole (a bz2 block
  // decompresses only complete), the first two are read.
  writeFile(dir + "/cut.bag", bytes.substr(0, 300000));
  const auto run = runHost({"run", kConfigs + "people_2d_legs.ini", "--input", dir + "/cut.bag",
                            "--out", dir + "/run", "-q"});
  CHECK(run.exit_code == 1);
  const auto eval = runHost({"eval", "--truth", dir + "/cut.bag", "--tracks",
                             dir + "/run/tracks.csv", "--following", "--json"});
  CHECK(eval.exit_code == 1);
  CHECK_THAT(eval.output, Catch::Contains("warning: --truth " + dir + "/cut.bag: cut short"));
  const std::string runjson = readFile(dir + "/run/run.json");
  const double scans = jsonValue(runjson, "frames_read");
  CHECK(scans > 600);
  CHECK_THAT(eval.output, Catch::Contains("\"scans\": " + std::to_string(long(scans))));
}
