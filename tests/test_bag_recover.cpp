// Bags cut short or never indexed (pedtrack/bag_recover.h) on bags the test writes with
// rosbag_storage: a recorder killed between chunks or inside one, a compressed chunk cut, an index
// damaged; what cannot be recovered stays refused. The leg_tracker demo bag cut at 20 offsets is
// test_bag_truncation.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>

#include <catch2/catch.hpp>
#include <cstring>

#include "bag_layout.h"
#include "pedtrack/bag_recover.h"
#include "pedtrack/errors.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

// `n` scans on /scan, 10 Hz, scan k has every range k/10 m; chunks of about 6 scans.
std::string writeScanBag(
    const std::string& path, int n,
    rosbag::compression::CompressionType c = rosbag::compression::Uncompressed) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setCompression(c);
  bag.setChunkThreshold(6 * 1300);
  for (int k = 0; k < n; ++k) {
    sensor_msgs::LaserScan s;
    s.header.stamp = ros::Time(100 + 0.1 * k);
    s.header.frame_id = "laser";
    s.angle_min = -1.5;
    s.angle_max = 1.5;
    s.angle_increment = 0.01;
    s.range_min = 0.01;
    s.range_max = 30;
    s.ranges.assign(301, 0.1f * float(k + 1));
    bag.write("/scan", s.header.stamp, s);
  }
  bag.close();
  return path;
}

struct Replay {
  std::vector<double> first_range;  // per frame: the range of its scan's first beam
  std::string error;                // what the source threw (at the end of a recovered bag)
};

// The rosbag source on `file` until its end or its error.
Replay replayBag(const std::string& file) {
  Replay r;
  r.error = readFramesUntilError(
      "[pipeline]\nstages = source\n[source]\nplugin = rosbag\nfile = " + file + "\n",
      [&](const Frame& f) {
        const auto* scan =
            dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(f.observations.at(0).get());
        r.first_range.push_back(scan ? scan->getScanRange(0) : -1);
      });
  return r;
}

void putU32(std::string& b, std::size_t at, std::uint32_t v) {
  std::memcpy(&b[at], &v, 4);
}
void putU64(std::string& b, std::size_t at, std::uint64_t v) {
  std::memcpy(&b[at], &v, 8);
}

// The position of a header field's value in the record at `at`.
std::size_t fieldAt(const std::string& b, std::size_t at, const std::string& name) {
  std::uint32_t hl;
  std::memcpy(&hl, b.data() + at, 4);
  const std::size_t f = b.substr(at + 4, hl).find(name + "=");
  REQUIRE(f != std::string::npos);
  return at + 4 + f + name.size() + 1;
}

}  // namespace

TEST_CASE("a recorder killed between chunks: no index, every message replayed", "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_unindexed");
  const std::string whole = readFile(writeScanBag(dir + "/whole.bag", 40));
  const BagLayout l = bagLayout(whole);
  REQUIRE(l.chunk_starts.size() >= 5);
  // What rosbag record leaves on disk: the chunks and their index records, index_pos 0.
  std::string killed = whole.substr(0, l.index_pos);
  putU64(killed, fieldAt(killed, 13, "index_pos"), 0);
  writeFile(dir + "/killed.bag", killed);
  const Replay r = replayBag(dir + "/killed.bag");
  REQUIRE(r.first_range.size() == 40);
  for (int k = 0; k < 40; ++k) CHECK(r.first_range[k] == Approx(0.1 * (k + 1)).epsilon(1e-6));
  CHECK_THAT(r.error, Catch::Contains(dir + "/killed.bag: no index (the recording was not "
                                            "closed); its 40 messages are read"));
}

TEST_CASE("a recorder killed inside a chunk: its header sizes 0, its complete records kept",
          "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_open_chunk");
  const std::string whole = readFile(writeScanBag(dir + "/whole.bag", 40));
  const BagLayout l = bagLayout(whole);
  // The last chunk as rosbag writes it before stopping it: sizes 0, records after the header,
  // no index records; the file ends 100 bytes into one of its messages.
  const std::size_t last = l.chunk_starts.back();
  std::string killed = whole.substr(0, l.chunk_ends.back());
  putU32(killed, fieldAt(killed, last, "size"), 0);
  std::uint32_t hl;
  std::memcpy(&hl, killed.data() + last, 4);
  putU32(killed, last + 4 + hl, 0);
  putU64(killed, fieldAt(killed, 13, "index_pos"), 0);
  const std::size_t cut = l.message_ends[l.message_ends.size() - 2] + 100;
  killed.resize(cut);
  writeFile(dir + "/killed.bag", killed);
  const Replay r = replayBag(dir + "/killed.bag");
  CHECK(r.first_range.size() == 39);
  CHECK(r.first_range.back() == Approx(3.9).epsilon(1e-6));
  CHECK_THAT(r.error, Catch::Contains("cut short: its data ends at byte " +
                                      std::to_string(l.message_ends[l.message_ends.size() - 2]) +
                                      " of " + std::to_string(cut)));
}

TEST_CASE("a compressed chunk cut short is lost whole, the chunks before it replay",
          "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_bz2");
  for (const auto c : {rosbag::compression::BZ2, rosbag::compression::LZ4}) {
    const std::string whole = readFile(writeScanBag(dir + "/whole.bag", 40, c));
    // The third chunk record (bagLayout reads uncompressed chunks only).
    const std::size_t third = [&] {
      std::size_t p = 13, n = 0;
      for (;;) {
        std::uint32_t hl, dl;
        std::memcpy(&hl, whole.data() + p, 4);
        std::memcpy(&dl, whole.data() + p + 4 + hl, 4);
        if (whole.substr(p + 4, hl).find(std::string("op=\x05", 4)) != std::string::npos &&
            ++n == 3)
          return p;
        p += 8 + hl + dl;
      }
    }();
    std::string cut = whole.substr(0, third + 60);
    writeFile(dir + "/cut.bag", cut);
    const Replay r = replayBag(dir + "/cut.bag");
    REQUIRE(r.first_range.size() >= 8);  // two chunks of about 6 scans
    for (std::size_t k = 0; k < r.first_range.size(); ++k)
      CHECK(r.first_range[k] == Approx(0.1 * double(k + 1)).epsilon(1e-6));
    CHECK_THAT(r.error, Catch::Contains("its data ends at byte " + std::to_string(third)));
  }
}

TEST_CASE("a bag with a damaged index is re-indexed from its chunks and says what was damaged",
          "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_index");
  std::string b = readFile(writeScanBag(dir + "/whole.bag", 20));
  const BagLayout l = bagLayout(b);
  // A chunk info naming a position that is no chunk.
  const std::size_t info = b.find("chunk_pos=", l.index_pos);
  REQUIRE(info != std::string::npos);
  b[info + 10] = char(b[info + 10] + 1);
  writeFile(dir + "/index.bag", b);
  const Replay r = replayBag(dir + "/index.bag");
  CHECK(r.first_range.size() == 20);
  CHECK_THAT(r.error, Catch::Contains("a damaged index (a chunk info naming no chunk at byte"));
}

TEST_CASE("what is not a cut bag stays refused: not a bag, damaged inside, nothing complete",
          "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_refused");
  const std::string whole = readFile(writeScanBag(dir + "/whole.bag", 20));
  const BagLayout l = bagLayout(whole);
  writeFile(dir + "/text.bag", "hello, not a bag\n");
  CHECK_THAT(replayBag(dir + "/text.bag").error,
             Catch::Contains("not a ROS bag of format 2.0") &&
                 Catch::Contains("[source] file: cannot open bag"));
  // A message's op field claiming 200 bytes inside the first chunk, and the file cut after it.
  std::string damaged = whole.substr(0, l.chunk_ends[1] + 50);
  const std::size_t op = damaged.find(std::string("\x04\x00\x00\x00op=\x02", 8));
  REQUIRE(op != std::string::npos);
  damaged[op] = char(200);
  writeFile(dir + "/damaged.bag", damaged);
  CHECK_THAT(replayBag(dir + "/damaged.bag").error,
             Catch::Contains("a header field longer than its header at byte"));
  // Cut before the first message is complete.
  writeFile(dir + "/empty.bag", whole.substr(0, l.message_ends[0] - 1));
  CHECK_THAT(replayBag(dir + "/empty.bag").error,
             Catch::Contains("no complete message before its data ends at byte"));
}

TEST_CASE("reindexBag writes a bag rosbag_storage reads with the messages' stamps and order",
          "[bag_recover]") {
  const std::string dir = freshDir("bag_recover_copy");
  const std::string whole = readFile(writeScanBag(dir + "/whole.bag", 30));
  const BagLayout l = bagLayout(whole);
  const std::size_t cut = (l.chunk_starts[2] + l.chunk_ends[2]) / 2;
  writeFile(dir + "/cut.bag", whole.substr(0, cut));
  const BagRecovery rec = reindexBag(dir + "/cut.bag", dir + "/copy.bag");
  CHECK(rec.messages == l.messagesBefore(cut));
  CHECK(rec.data_end == l.dataEnd(cut));
  CHECK(rec.file_size == cut);
  CHECK(rec.chunks == 3);
  rosbag::Bag bag(dir + "/copy.bag", rosbag::bagmode::Read);
  rosbag::View view(bag);
  std::size_t k = 0;
  for (const auto& m : view) {
    auto s = m.instantiate<sensor_msgs::LaserScan>();
    REQUIRE(s);
    CHECK(s->header.stamp == ros::Time(100 + 0.1 * double(k)));
    CHECK(m.getTime() == s->header.stamp);
    CHECK(s->ranges[0] == Approx(0.1 * double(k + 1)));
    ++k;
  }
  CHECK(k == rec.messages);
}
