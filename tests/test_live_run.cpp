// Live operation in the framework: the bounded FrameQueue, FrameSupply reading a live source on
// its own thread (drops when the stages fall behind, stop requests), and `pedtrack run --record`
// keeping what a source produced so that it replays bit for bit.
#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <thread>

#include "pedtrack/frame_queue.h"
#include "pedtrack/frame_supply.h"
#include "pedtrack/stop_request.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
using namespace std::chrono_literals;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

Frame frameAt(double t) {
  Frame f;
  f.t = t;
  return f;
}

// A device that produces `count` frames, one every `period`, whatever the reader does.
class FakeDevice : public Sensor {
 public:
  FakeDevice(int count, std::chrono::milliseconds period) : count_(count), period_(period) {}
  bool live() const override { return true; }
  bool next(Frame& frame) override {
    if (produced_ >= count_) return false;
    std::this_thread::sleep_for(period_);
    frame.t = produced_++;
    return true;
  }

 private:
  int count_, produced_ = 0;
  std::chrono::milliseconds period_;
};

}  // namespace

TEST_CASE("the frame queue drops the oldest frame when full", "[live]") {
  FrameQueue q(2);
  const auto now = FrameQueue::Clock::now();
  for (int i = 0; i < 5; ++i) q.push(frameAt(i), now);
  CHECK(q.dropped() == 3);
  FrameQueue::Item item;
  REQUIRE(q.pop(item, 0ms));
  CHECK(item.frame.t == 3);  // the newest two are kept, in order
  REQUIRE(q.pop(item, 0ms));
  CHECK(item.frame.t == 4);
  CHECK_FALSE(q.pop(item, 10ms));  // empty, still open: a timeout
  CHECK_FALSE(q.closedAndEmpty());
  q.close();
  CHECK_FALSE(q.pop(item, 1000ms));  // closed: returns at once
  CHECK(q.closedAndEmpty());
}

TEST_CASE("a live source is read on its own thread and frames are dropped, not delayed", "[live]") {
  // 40 frames at 200 Hz into stages that take 20 ms each: the stages can keep one in four.
  FakeDevice device(40, 5ms);
  RunOptions opt;
  opt.live_queue = 1;
  FrameSupply supply(device, opt, nullptr);
  REQUIRE(supply.live());
  Frame f;
  FrameSupply::Clock::time_point arrival;
  int processed = 0;
  double last_t = -1;
  while (supply.next(f, arrival)) {
    CHECK(f.t > last_t);  // in order
    last_t = f.t;
    std::this_thread::sleep_for(20ms);
    ++processed;
  }
  supply.stop();
  CHECK(supply.framesRead() == 40);
  CHECK(supply.dropped() + processed == 40);
  // The stages could take one frame in four; scheduling on a loaded machine moves that a little.
  CHECK(supply.dropped() >= 10);
  CHECK(last_t >= 38);  // the newest frames are kept
  CHECK(supply.error().empty());
}

TEST_CASE("a stop request ends a live run between frames", "[live]") {
  FakeDevice device(1000000, 2ms);
  RunOptions opt;
  FrameSupply supply(device, opt, nullptr);
  Frame f;
  FrameSupply::Clock::time_point arrival;
  REQUIRE(supply.next(f, arrival));
  stopRequested() = true;
  CHECK_FALSE(supply.next(f, arrival));
  supply.stop();  // joins: the reading thread saw the request
  stopRequested() = false;
  CHECK(supply.framesRead() < 1000000);
}

TEST_CASE("pedtrack run --record keeps the frames so that they replay bit for bit", "[live]") {
  const std::string dir = freshDir("live_record");
  const auto a = runHost({"run", kConfigs + "people_2d_legs.ini", "--max-frames", "150", "--out",
                          dir + "/a", "--record", dir + "/session.rawlog", "-q"});
  INFO(a.output);
  REQUIRE(a.exit_code == 0);
  const std::string run = readFile(dir + "/a/run.json");
  CHECK(jsonValue(run, "frames_recorded") == 150);
  CHECK(jsonValue(run, "frames_dropped") == 0);
  CHECK(run.find("\"latency_ms\"") != std::string::npos);
  const auto b = runHost({"run", kConfigs + "people_2d_legs.ini", "--input",
                          dir + "/session.rawlog", "--out", dir + "/b", "-q"});
  INFO(b.output);
  REQUIRE(b.exit_code == 0);
  const std::string tracks = readFile(dir + "/a/tracks.csv");
  CHECK(lines(tracks).size() > 100);  // people were tracked
  CHECK(tracks == readFile(dir + "/b/tracks.csv"));
  // A file that cannot be written (no such directory; a directory) is named before anything is
  // written: exit 2, one line, no tracks.csv.
  for (const std::string& bad : {dir + "/no/such/dir/x.rawlog", dir}) {
    const auto c = runHost({"run", kConfigs + "people_2d_legs.ini", "--max-frames", "1", "--record",
                            bad, "--out", dir + "/c", "-q"});
    INFO(c.output);
    CHECK(c.exit_code == 2);
    CHECK(lines(c.output).size() == 1);
    CHECK_THAT(c.output, Catch::Contains("--record " + bad));
    CHECK_FALSE(std::filesystem::exists(dir + "/c/tracks.csv"));
  }
}

TEST_CASE("a live queue of a negative length is refused, not made unbounded", "[live]") {
  // Boost reads "-1" into an unsigned option as its largest value.
  const auto r = runHost({"run", kConfigs + "people_2d_legs.ini", "--live-queue=-1", "-q"});
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(lines(r.output).size() == 1);
  CHECK_THAT(r.output, Catch::Contains("--live-queue -1: expected a whole number of at least 0"));
}
