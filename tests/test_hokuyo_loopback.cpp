// MRPT's own CHokuyoURG driver, through the mrpt_sensor source, against a fake Ethernet Hokuyo on
// 127.0.0.1 (loopback_hokuyo.h) serving scans rendered by the simulator: the frames arrive intact,
// a device that goes silent, is switched off or sends malformed scans is survived and reconnected,
// and the leg pipeline tracks people from it live. Every run is bounded in frames and time.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <thread>

#include "loopback_hokuyo.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
using Fault = LoopbackHokuyo::Fault;
using Scans = std::vector<std::vector<float>>;

namespace {

const std::string kScenarios = std::string(PEDTRACK_SOURCE_DIR) + "/configs/scenarios/";

// Scans `first` .. `first + count - 1` of a 768-beam leg scenario, as the device serves them:
// metres per step, NaN where the simulated scanner had no return.
Scans renderScans(const std::string& scenario, std::size_t first, std::size_t count) {
  sim::Simulator simulator(sim::loadScenario(kScenarios + scenario));
  simulator.setPointTruth(false);
  Scans out;
  sim::SimFrame f;
  for (std::size_t k = 0; k < first + count && simulator.next(f); ++k) {
    if (k < first) continue;
    for (const auto& o : f.observations)
      if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) {
        std::vector<float> r(scan->getScanSize());
        for (std::size_t i = 0; i < r.size(); ++i)
          r[i] = scan->getScanRangeValidity(i) ? scan->getScanRange(i)
                                               : std::numeric_limits<float>::quiet_NaN();
        out.push_back(std::move(r));
      }
  }
  return out;
}

// The device's pace: the 10 Hz scenarios three times faster, to keep the tests short.
LoopbackHokuyo::Config fastDevice() {
  LoopbackHokuyo::Config c;
  c.speedup = 3;
  return c;
}

// A [source] section for CHokuyoURG on the device: MRPT's own keys, as rawlog-grabber takes them.
// The stream ends after `idle` s without data (the device ran out of scans) unless `extra` says
// otherwise.
// `link`: how MRPT reaches the device (IP_DIR / PORT_DIR, or COM_port_LIN).
std::string hokuyoSection(const std::string& link, const std::string& extra, double idle) {
  std::ostringstream s;
  s << "[source]\nplugin = mrpt_sensor\ndriver = CHokuyoURG\n"
    << link
    << "\nsensorLabel = HOKUYO_LOOP\nprocess_rate = 200\npose_z = 0.4\nidle_timeout = " << idle
    << "\n"
    << extra;
  return s.str();
}
std::string sourceSection(int port, const std::string& extra = "end_on_idle = true\n",
                          double idle = 4) {
  return hokuyoSection("IP_DIR = 127.0.0.1\nPORT_DIR = " + std::to_string(port), extra, idle);
}

// configs/people_2d_legs.ini with the device on `port` in place of its simulated [source].
void writeLegsPipeline(const std::string& path, int port) {
  std::string ini = readFile(std::string(PEDTRACK_SOURCE_DIR) + "/configs/people_2d_legs.ini");
  const auto src = ini.find("\n[source]") + 1;  // the section, not the comment naming it
  REQUIRE(src != 0);
  ini.replace(src, ini.find("\n[", src) + 1 - src, sourceSection(port));
  const auto model = ini.find("../models/");
  REQUIRE(model != std::string::npos);
  ini.replace(model, 3, std::string(PEDTRACK_SOURCE_DIR) + "/");
  writeFile(path, ini);
}

// The same for a serial (USB) Hokuyo: MRPT's COM_port_LIN instead of IP_DIR / PORT_DIR.
std::string serialSourceSection(const std::string& device_path,
                                const std::string& extra = "end_on_idle = true\n") {
  return hokuyoSection("COM_port_LIN = " + device_path, extra, 4);
}

struct Run {
  std::vector<Frame> frames;
  std::map<std::string, long> counters;
  double seconds = 0;
};

// Reads at most `max_frames` frames for at most `max_seconds` (the source itself gives up after
// idle_timeout without data), then the source's counters. `stall` s: the reader stops after the
// first frame for that long, as on a loaded machine, while the device goes on sending.
Run readFrames(const std::string& ini, std::size_t max_frames, double max_seconds,
               double stall = 0) {
  const auto cfg = PipelineConfig::fromText(ini, "hokuyo.ini", {}, testRegistry());
  const auto t0 = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  Run run;
  {
    Pipeline p(cfg);
    Frame f;
    while (run.frames.size() < max_frames && elapsed() < max_seconds && p.source().next(f)) {
      run.frames.push_back(std::move(f)), f = Frame();
      if (run.frames.size() == 1 && stall > 0)
        std::this_thread::sleep_for(std::chrono::duration<double>(stall));
    }
    for (const auto& [name, value] : p.source().counters()) run.counters[name] = value;
  }
  run.seconds = elapsed();
  return run;
}

const mrpt::obs::CObservation2DRangeScan* scanOf(const Frame& f) {
  return f.observations.size() == 1
             ? dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(f.observations[0].get())
             : nullptr;
}

// Beams of the frame that differ from the served scan: validity, or range beyond SCIP's 1 mm.
std::size_t mismatches(const Frame& f, const std::vector<float>& served) {
  const auto* scan = scanOf(f);
  if (!scan || scan->getScanSize() != served.size()) return served.size() + 1;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < served.size(); ++i) {
    const bool valid = std::isfinite(served[i]);
    if (scan->getScanRangeValidity(i) != valid ||
        (valid && std::abs(scan->getScanRange(i) - served[i]) > 0.0005 + 1e-6))
      ++bad;
  }
  return bad;
}

// Which served scan each frame is (the first identical one after the previous frame's), -1 when
// none: frames must come intact and in order.
std::vector<long> servedIndices(const std::vector<Frame>& frames, const Scans& served) {
  std::vector<long> idx;
  std::size_t from = 0;
  for (const auto& f : frames) {
    long found = -1;
    for (std::size_t j = from; j < served.size() && found < 0; ++j)
      if (mismatches(f, served[j]) == 0) found = static_cast<long>(j);
    idx.push_back(found);
    if (found >= 0) from = static_cast<std::size_t>(found) + 1;
  }
  return idx;
}

std::vector<long> allBut(std::size_t n, const std::vector<long>& skip) {
  std::vector<long> v;
  for (long i = 0; i < static_cast<long>(n); ++i)
    if (std::find(skip.begin(), skip.end(), i) == skip.end()) v.push_back(i);
  return v;
}

}  // namespace

TEST_CASE("hokuyo loopback: CHokuyoURG reads the served scans intact", "[hokuyo][mrpt_sensor]") {
  const Scans served = renderScans("legs_crowd_10.ini", 0, 40);
  REQUIRE(served.size() == 40);
  // The scans are worth comparing: people, clutter and walls in range, sky elsewhere.
  std::size_t valid = 0, total = 0;
  for (const auto& s : served)
    for (float r : s) valid += std::isfinite(r), ++total;
  REQUIRE(valid > total / 10);
  REQUIRE(valid < total);

  LoopbackHokuyo device(fastDevice(), served);
  const Run run =
      readFrames("[pipeline]\nstages = source\n" + sourceSection(device.port()), served.size(), 20);
  INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
  REQUIRE(run.frames.size() == served.size());
  for (std::size_t k = 0; k < served.size(); ++k) {
    INFO("frame " << k);
    REQUIRE(scanOf(run.frames[k]) != nullptr);
    CHECK(mismatches(run.frames[k], served[k]) == 0);
  }
  const auto* scan = scanOf(run.frames[0]);
  CHECK(scan->sensorLabel == "HOKUYO_LOOP");
  CHECK(scan->maxRange == Approx(11.0));                     // DMAX from PP
  CHECK(scan->aperture == Approx(768 * 2 * M_PI / 1024.0));  // AMIN..AMAX of ARES, MRPT's way
  CHECK(run.frames[0].sensor_pose.z() == Approx(0.4));       // MRPT's pose_z reached the driver
  for (std::size_t k = 1; k < run.frames.size(); ++k) CHECK(run.frames[k].t > run.frames[k - 1].t);
  CHECK(device.scansSent() == served.size());
  CHECK(device.connections() == 1);
  CHECK(run.counters.at("driver_errors") == 0);
  CHECK(run.counters.at("reconnects") == 0);
}

TEST_CASE("hokuyo loopback: a serial (USB) Hokuyo is read intact and woken after a hang",
          "[hokuyo][mrpt_sensor][serial]") {
  // The device sits on a pseudo-terminal, which CHokuyoURG opens as its COM port: CSerialPort's
  // line setup, SS (baud rate) and timed reads are exercised, not the TCP path.
  const Scans served = renderScans("legs_crowd_10.ini", 40, 30);
  REQUIRE(served.size() == 30);
  LoopbackHokuyo::Config cfg = fastDevice();
  cfg.serial = true;
  LoopbackHokuyo device(cfg, served);
  REQUIRE(!device.devicePath().empty());
  INFO("device " << device.devicePath());

  SECTION("every scan arrives intact and in order") {
    const Run run =
        readFrames("[pipeline]\nstages = source\n" + serialSourceSection(device.devicePath()),
                   served.size(), 20);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("driver_errors") == 0);
    CHECK(run.counters.at("reconnects") == 0);
  }

  SECTION("a device that goes silent is re-opened until it answers again") {
    device.addFault(Fault::Silence, 10, 1.2);
    const Run run = readFrames("[pipeline]\nstages = source\n" +
                                   serialSourceSection(device.devicePath(),
                                                       "end_on_idle = true\nreconnect_after = "
                                                       "0.5\nreconnect_delay = 0.2\n"),
                               served.size(), 25);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("stalls") >= 1);
    CHECK(run.counters.at("reconnects") >= 1);  // scans 10.. came from a re-opened line
  }
}

TEST_CASE("hokuyo loopback: a device starved for 1.6 s during start-up costs a retry, no more",
          "[hokuyo][mrpt_sensor][serial]") {
  // The Hokuyo loopback flake (#13, about 1 run in 25, and 4 of 200 here under load): MRPT's
  // start-up waits 200 ms for each reply on a serial line. When the device (here its thread on
  // a loaded machine) answers nothing for a second and a half, both of MRPT's start-ups fail, the
  // driver sits in its error state, and mrpt_sensor re-creates it after reconnect_after +
  // reconnect_delay (2.5 s) plus a start-up: past the 4 s idle_timeout, 0 frames read (the
  // flake's "read 0 frames in 5.8 s", 1 driver error, 1 reconnection). The device below sleeps
  // 1.6 s on the first QT; the start-up is now tried again at once: every scan arrives, no error.
  const Scans served = renderScans("legs_crowd_10.ini", 40, 30);
  LoopbackHokuyo::Config cfg = fastDevice();
  cfg.serial = true;
  cfg.slow_command = "QT";  // the first command of a start-up
  cfg.slow_replies = 1;
  cfg.slow_reply_seconds = 1.6;
  LoopbackHokuyo device(cfg, served);
  const Run run =
      readFrames("[pipeline]\nstages = source\n" + serialSourceSection(device.devicePath()),
                 served.size(), 20);
  INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
  CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
  CHECK(run.counters.at("driver_errors") == 0);
  CHECK(run.counters.at("reconnects") == 0);
  CHECK(run.counters.at("startup_retries") >= 1);  // one here; more on a loaded machine
}

TEST_CASE(
    "hokuyo loopback: a device that stops answering or sends garbage is survived and "
    "reconnected",
    "[hokuyo][mrpt_sensor]") {
  const Scans served = renderScans("legs_crowd_10.ini", 100, 30);
  REQUIRE(served.size() == 30);
  LoopbackHokuyo device(fastDevice(), served);
  const std::string quick = "end_on_idle = true\nreconnect_after = 0.5\nreconnect_delay = 0.2\n";

  SECTION("malformed scans are dropped, the stream goes on") {
    device.addFault(Fault::Truncate, 8);
    device.addFault(Fault::Garbage, 16);
    const Run run = readFrames("[pipeline]\nstages = source\n" + sourceSection(device.port()),
                               served.size() - 2, 20);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {8, 16}));
    CHECK(run.counters.at("driver_errors") >= 2);  // each bad scan put the driver in error
    CHECK(device.faultsFired() == 2);
    CHECK(device.connections() == 1);  // CHokuyoURG resynchronises on the next scan's echo
  }

  SECTION("SCIP sums are not checked by CHokuyoURG: a scan with wrong sums still arrives") {
    // Recorded so that a driver that starts checking them shows up here.
    device.addFault(Fault::BadChecksum, 5);
    const Run run = readFrames("[pipeline]\nstages = source\n" + sourceSection(device.port()),
                               served.size(), 20);
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(device.faultsFired() == 1);
  }

  SECTION("a device that goes silent is re-created until it answers again") {
    // The connection that went silent never streams again. The source's stall check (0.5 s here)
    // re-creates the driver before CHokuyoURG's own missed-scan check would reconnect.
    device.addFault(Fault::Silence, 10, 1.2);
    const Run run = readFrames(
        "[pipeline]\nstages = source\n" + sourceSection(device.port(), quick), served.size(), 25);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("stalls") >= 1);
    CHECK(run.counters.at("reconnects") >= 1);
    CHECK(device.connections() >= 2);
    CHECK(device.streamsStarted() >= 2);
  }

  SECTION("a device switched off for a while is reconnected") {
    // Connections are refused meanwhile: CHokuyoURG reports errors, then throws.
    device.addFault(Fault::Drop, 10, 1.0);
    const Run run = readFrames(
        "[pipeline]\nstages = source\n" + sourceSection(device.port(), quick), served.size(), 25);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("driver_errors") >= 1);
    CHECK(device.connections() >= 2);
  }

  SECTION("without reconnect a failing device ends the run with an error") {
    device.addFault(Fault::Drop, 10, 30);  // refused connections: the driver's error state
    CHECK_THROWS_WITH(readFrames("[pipeline]\nstages = source\n" +
                                     sourceSection(device.port(), "reconnect = false\n"),
                                 served.size(), 20),
                      Catch::StartsWith("CHokuyoURG: "));
  }
}

TEST_CASE("hokuyo loopback: scans read in a burst after a stall keep the device's spacing",
          "[hokuyo][mrpt_sensor]") {
  // A real-time 10 Hz device; the reader stalls 0.7 s after the first scan, so the next ~7 wait
  // in the socket and are read back to back. MRPT's CHokuyoURG stamped those (its first 10) by
  // arrival, 0-0.3 ms apart; mrpt_sensor has it use the device clock from the first scan.
  const Scans served = renderScans("legs_crowd_10.ini", 100, 25);
  REQUIRE(served.size() == 25);
  LoopbackHokuyo device(LoopbackHokuyo::Config(), served);
  const Run run = readFrames("[pipeline]\nstages = source\n" + sourceSection(device.port()),
                             served.size(), 20, 0.7);
  REQUIRE(run.frames.size() == served.size());
  // From the second frame on: this device's clock reads 0 at its first scan, which CHokuyoURG
  // takes for "no anchor yet" and anchors at the second scan's arrival instead.
  for (std::size_t k = 2; k < run.frames.size(); ++k) {
    INFO("frame " << k);
    CHECK(run.frames[k].t - run.frames[k - 1].t == Approx(0.1).margin(0.002));
  }
}

TEST_CASE("hokuyo loopback: a device still mute when the driver starts is waited for",
          "[hokuyo][mrpt_sensor]") {
  const Scans served = renderScans("legs_crowd_10.ini", 200, 20);
  REQUIRE(served.size() == 20);
  LoopbackHokuyo::Config cfg = fastDevice();

  SECTION("mute for 1 s: the start-up is tried again until the device answers") {
    cfg.mute_first = 1.0;  // booting: commands are ignored for 1 s from the first connection
    LoopbackHokuyo device(cfg, served);
    const Run run = readFrames("[pipeline]\nstages = source\n" + sourceSection(device.port()),
                               served.size(), 20);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("startup_retries") >= 1);
    CHECK(run.counters.at("reconnects") == 0);
    CHECK(device.connections() == 1);
  }

  SECTION("mute for 8 s: the source re-creates the driver until the device answers") {
    cfg.mute_first = 8.0;  // longer than the driver's start-up attempts (about 6 s)
    LoopbackHokuyo device(cfg, served);
    const Run run =
        readFrames("[pipeline]\nstages = source\n" +
                       sourceSection(device.port(),
                                     "end_on_idle = true\nreconnect_after = 0.5\nreconnect_delay = "
                                     "0.2\n",
                                     14),
                   served.size(), 30);
    INFO("read " << run.frames.size() << " frames in " << run.seconds << " s");
    CHECK(servedIndices(run.frames, served) == allBut(served.size(), {}));
    CHECK(run.counters.at("stalls") >= 1);
    CHECK(run.counters.at("reconnects") >= 1);
    CHECK(device.connections() >= 2);
  }

  SECTION("mute for 8 s: CHokuyoURG alone never starts the stream") {
    // What the stall check is for: a driver whose start-ups all went unanswered waits for scans
    // that were never asked for (it restarts only a stream it saw run), until idle_timeout.
    cfg.mute_first = 8.0;
    LoopbackHokuyo device(cfg, served);
    const Run run = readFrames(
        "[pipeline]\nstages = source\n" +
            sourceSection(device.port(), "end_on_idle = true\nreconnect_after = 0\n", 10),
        served.size(), 20);
    CHECK(run.frames.empty());
    CHECK(run.seconds > 10);  // the device answered from 8 s on: nobody asked it to stream
    CHECK(device.streamsStarted() == 0);
    CHECK(device.connections() == 1);
  }
}

TEST_CASE("hokuyo loopback: tracks come out of a live leg pipeline", "[hokuyo][legs][pipeline]") {
  // legs_standing_60s.ini from t = 6 s to 13 s: person 1, come in by the north door, walks to
  // (3.5, 0.8) and stands still there from 9.2 s; person 2 crosses the room at x = 7.
  // (PEDTRACK_LIVE_FRAMES: longer, for scripts/live_latency.sh; the person stands to the end.)
  const std::size_t n = std::min<std::size_t>(liveFrames(70), 500);
  const Scans served = renderScans("legs_standing_60s.ini", 60, n);
  REQUIRE(served.size() == n);
  // In real time (10 Hz), as the device would send them.
  LoopbackHokuyo device(LoopbackHokuyo::Config(), served);

  const std::string dir = freshDir("hokuyo_loopback_legs");
  writeLegsPipeline(dir + "/people_2d_legs_hokuyo.ini", device.port());

  // A queue deep enough that no frame is dropped: what is tracked does not depend on the load.
  const auto r = runHost({"run", dir + "/people_2d_legs_hokuyo.ini", "--out", dir + "/out", "-q",
                          "--max-frames", std::to_string(served.size()), "--live-queue", "100"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string json = readFile(dir + "/out/run.json");
  INFO(json);
  CHECK(jsonValue(json, "frames_processed") >= 0.9 * served.size());
  CHECK(jsonValue(json, "driver_errors") == 0);
  std::printf("hokuyo live: %zu scans served, latency p50 %.2f ms, p99 %.2f ms\n", served.size(),
              jsonValue(json, "p50"), jsonValue(json, "p99"));

  // tracks.csv: t,frame,track,x,y,... and the status 17th. The standing person has one
  // confirmed track over the last 10 frames read (the last second of the scenario).
  const auto rows = lines(readFile(dir + "/out/tracks.csv"));
  REQUIRE(rows.size() > 1);
  struct Row {
    long frame;
    double x, y;
    std::string track, status;
  };
  std::vector<Row> tracks;
  long last_frame = -1;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> c;
    std::stringstream ss(rows[i]);
    for (std::string cell; std::getline(ss, cell, ',');) c.push_back(cell);
    REQUIRE(c.size() >= 18);
    tracks.push_back({std::stol(c[1]), std::stod(c[3]), std::stod(c[4]), c[2], c[17]});
    last_frame = std::max(last_frame, tracks.back().frame);
  }
  CHECK(last_frame >= static_cast<long>(0.9 * served.size()));
  std::map<std::string, int> near_stander;
  for (const auto& row : tracks)
    if (row.status == "confirmed" && row.frame > last_frame - 10 &&
        std::hypot(row.x - 3.5, row.y - 0.8) < 0.35)
      ++near_stander[row.track];
  INFO(near_stander.size() << " confirmed tracks near the standing person");
  REQUIRE(near_stander.size() == 1);
  CHECK(near_stander.begin()->second >= 7);  // in (nearly) every one of those frames
}

TEST_CASE("hokuyo loopback: SIGTERM stops a live pipeline cleanly with every output flushed",
          "[hokuyo][legs][pipeline][signal]") {
  // 150 scans in real time (15 s); the run is asked to stop 4 s in, as a robot's launcher would
  // (6 s under the sanitizers, whose start-up takes ~2 s of it: the person walking in must be
  // tracked before the stop for the rows to be checked).
  const int stop_after = kSanitized ? 6 : 4;
  const Scans served = renderScans("legs_standing_60s.ini", 60, 150);
  REQUIRE(served.size() == 150);
  LoopbackHokuyo device(LoopbackHokuyo::Config(), served);
  const std::string dir = freshDir("hokuyo_loopback_sigterm");
  writeLegsPipeline(dir + "/people_2d_legs_hokuyo.ini", device.port());

  const auto t0 = std::chrono::steady_clock::now();
  // --preserve-status: timeout exits with pedtrack's own status after sending SIGTERM.
  const auto r =
      runShell("timeout --preserve-status -s TERM " + std::to_string(stop_after) + " " +
               std::string(PEDTRACK_BIN) + " run " + dir + "/people_2d_legs_hokuyo.ini --out " +
               dir + "/out --record " + dir + "/live.rawlog -q");
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(secs < stop_after + 5);  // it stopped when asked, not when the device ran out (15 s)

  const std::string json = readFile(dir + "/out/run.json");
  INFO(json);
  CHECK(json.find("\"status\": \"interrupted\"") != std::string::npos);
  CHECK(json.find("\"live\": true") != std::string::npos);
  const double processed = jsonValue(json, "frames_processed");
  CHECK(processed >= 10);
  CHECK(processed < served.size());
  CHECK(jsonValue(json, "frames_recorded") >= processed);

  // tracks.csv is whole: a header, complete rows, none from a frame after the last one read.
  // (Frame numbers count frames read: a slow build may drop or skip some, so the last row's
  // frame can exceed frames_processed, never frames_read.)
  const double read = jsonValue(json, "frames_read");
  const std::string csv = readFile(dir + "/out/tracks.csv");
  REQUIRE(!csv.empty());
  CHECK(csv.back() == '\n');
  const auto rows = lines(csv);
  REQUIRE(rows.size() > 1);
  const auto fields = [](const std::string& row) {
    return static_cast<std::size_t>(std::count(row.begin(), row.end(), ',')) + 1;
  };
  for (std::size_t i = 1; i < rows.size(); ++i) {
    INFO(rows[i]);
    REQUIRE(fields(rows[i]) == fields(rows[0]));
    CHECK(std::stol(rows[i].substr(rows[i].find(',') + 1)) < read);
  }

  // The recording is closed properly: it replays, frame for frame.
  const auto replay =
      runHost({"run", std::string(PEDTRACK_SOURCE_DIR) + "/configs/people_2d_legs.ini", "--input",
               dir + "/live.rawlog", "--out", dir + "/replay", "-q"});
  INFO(replay.output);
  REQUIRE(replay.exit_code == 0);
  CHECK(jsonValue(readFile(dir + "/replay/run.json"), "frames_read") ==
        jsonValue(json, "frames_recorded"));
}
