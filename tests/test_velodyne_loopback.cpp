// MRPT's real CVelodyneScanner driver, run by the mrpt_sensor source on live UDP, fed by a VLP-16
// on loopback (loopback_vlp16.h) that sends the simulator's revolutions as real-format data and
// position packets. Ports are chosen free at run time; every loop is bounded.
#include <mrpt/hwdrivers/CVelodyneScanner.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>
#include <map>
#include <thread>

#include "loopback_vlp16.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/sim/simulator.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;
using Velo = mrpt::obs::CObservationVelodyneScan;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

struct Revolution {
  double t;
  Velo::Ptr scan;
};

// The first `n` revolutions of a simulated scenario, as the simulated VLP-16 sends them.
std::vector<Revolution> simulate(const std::string& scenario, int n) {
  sim::Simulator s(sim::loadScenario(scenario));
  s.setPointTruth(false);
  std::vector<Revolution> out;
  sim::SimFrame f;
  while (static_cast<int>(out.size()) < n && s.next(f)) {
    auto scan = std::dynamic_pointer_cast<Velo>(f.observations.back());
    REQUIRE(scan);
    out.push_back({f.t, scan});
  }
  return out;
}

// The points pedtrack decodes from a revolution as the simulator made it.
std::size_t decodedPoints(const Velo::Ptr& scan) {
  Frame f;
  f.observations.push_back(scan);
  return f.cloud().size();
}

// A rawlog-grabber section for the live driver, on the free ports just chosen.
std::vector<std::string> liveSource() {
  mrpt::hwdrivers::CVelodyneScanner::VELODYNE_DATA_UDP_PORT = static_cast<short>(freeUdpPort());
  mrpt::hwdrivers::CVelodyneScanner::VELODYNE_POSITION_UDP_PORT = static_cast<short>(freeUdpPort());
  return {"source.plugin=mrpt_sensor",   "source.driver=CVelodyneScanner", "source.model=VLP16",
          "source.sensorLabel=VELODYNE", "source.process_rate=3000",       "source.pose_z=1.0",
          "source.end_on_idle=true",     "source.idle_timeout=1.5"};
}

// Each revolution's packets are sent over this long: 188 packets/s, a quarter of a VLP-16's
// 754. MRPT's CVelodyneScanner reads one packet per call and polls its position socket for
// 1 ms in each: where 1 ms polls take 1.5-2 ms (a VM whose CPU the hypervisor steals; measured
// here) it reads at most ~500 packets/s and loses the rest, at the full rate and even at half
// of it. This test checks what arrives and that it is tracked, not the driver's throughput.
constexpr double kRevolutionSendSeconds = 0.4;

// Sends the revolutions, one malformed datagram after the third.
std::thread emit(const std::vector<Revolution>& revs) {
  return std::thread([&revs] {
    LoopbackVlp16 device(mrpt::hwdrivers::CVelodyneScanner::VELODYNE_DATA_UDP_PORT,
                         mrpt::hwdrivers::CVelodyneScanner::VELODYNE_POSITION_UDP_PORT);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the driver is listening
    for (std::size_t i = 0; i < revs.size(); ++i) {
      device.sendRevolution(*revs[i].scan, revs[i].t, kRevolutionSendSeconds);
      if (i == 2) device.sendGarbage();
    }
  });
}

}  // namespace

TEST_CASE("velodyne loopback: the live driver receives every revolution intact", "[velodyne]") {
  const auto revs = simulate(kConfigs + "scenarios/crowd.ini", 12);
  PipelineOverrides ov;
  ov.sets = liveSource();
  const auto cfg = PipelineConfig::fromText("[pipeline]\nstages = source\n[source]\nplugin = sim\n",
                                            kConfigs + "live.ini", ov, testRegistry());
  Pipeline p(cfg);  // the driver binds its UDP ports here, before anything is sent
  std::thread device = emit(revs);
  std::vector<Frame> frames;
  Frame f;
  while (frames.size() < 100 && p.source().next(f)) frames.push_back(f), f = Frame();
  device.join();
  // Every packet sent, by content: where it came in a revolution, in sending order.
  const std::size_t per_rev = revs[0].scan->scan_packets.size();
  std::map<std::string, std::size_t> order;
  for (std::size_t r = 0; r < revs.size(); ++r)
    for (std::size_t k = 0; k < revs[r].scan->scan_packets.size(); ++k) {
      const auto* b = reinterpret_cast<const char*>(&revs[r].scan->scan_packets[k]);
      order[std::string(b, sizeof(Velo::TVelodyneRawPacket))] = r * per_rev + k;
    }
  // Integrity, exactly: every packet received is one that was sent, byte for byte, in the order
  // sent (the malformed datagram dropped), and a complete revolution decodes to the points of
  // the one sent. Completeness within bounds: UDP drops what a reader starved of CPU for longer
  // than its socket buffer lasts cannot take, and MRPT's driver reads one packet per call.
  std::size_t received = 0, complete = 0;
  long last = -1;
  for (const Frame& fr : frames) {
    const auto* got = dynamic_cast<const Velo*>(fr.observations.at(0).get());
    REQUIRE(got != nullptr);
    CHECK(fr.sensor_pose.z() == Approx(1.0));
    for (const auto& pkt : got->scan_packets) {
      const auto it = order.find(std::string(reinterpret_cast<const char*>(&pkt), sizeof pkt));
      REQUIRE(it != order.end());
      CHECK(static_cast<long>(it->second) > last);
      last = static_cast<long>(it->second);
      ++received;
    }
    for (const Revolution& r : revs) {
      if (got->scan_packets.size() != r.scan->scan_packets.size() ||
          std::memcmp(got->scan_packets.data(), r.scan->scan_packets.data(),
                      got->scan_packets.size() * sizeof(Velo::TVelodyneRawPacket)) != 0)
        continue;
      ++complete;
      CHECK(fr.cloud().size() == decodedPoints(r.scan));
      break;
    }
  }
  // The last revolution stays open in the driver until the next one starts.
  const std::size_t sent = (revs.size() - 1) * per_rev;
  std::printf("velodyne intact: %zu of %zu packets received, %zu of %zu revolutions complete\n",
              received, sent, complete, revs.size() - 1);
  CHECK(received >= 0.8 * sent);
  CHECK(complete >= (revs.size() - 1) / 2);
}

TEST_CASE("velodyne loopback: a live 3D pipeline tracks the people", "[velodyne]") {
  const auto revs = simulate(kConfigs + "scenarios/crowd.ini", 40);
  PipelineOverrides ov;
  ov.sets = liveSource();
  const std::string ini = kConfigs + "people_3d_vlp16.ini";
  const auto cfg = PipelineConfig::fromText(readFile(ini), ini, ov, testRegistry());
  Pipeline p(cfg);
  std::thread device = emit(revs);
  RunOptions opt;
  opt.out_dir = freshDir("velodyne_live");
  opt.progress = false;
  const RunSummary s = p.run(opt);
  device.join();
  INFO(s.error);
  CHECK(s.status == "ok");
  CHECK(s.live);
  CHECK(s.frames_processed + s.frames_dropped + s.frames_failed == s.frames_read);
  // See the packet loss note in the case above. Under the sanitizers the driver's thread loses
  // far more beside a 3D pipeline taking ~300 ms a frame: 12-21 of the 40 revolutions were read
  // on the 2-core VM (CI once 17). There the check is that some arrive and are tracked (rows).
  const std::size_t least = kSanitized ? revs.size() / 5 : revs.size() / 2;
  CHECK(s.frames_read >= least);
  CHECK(s.frames_processed >= least);
  // Scan-to-tracks latency, reported for the figures (the 30 ms target is for a Release build
  // on one core: see README "Run on a robot").
  std::printf(
      "velodyne live: %zu frames read, %zu processed, %zu dropped; latency p50 %.2f ms, "
      "p99 %.2f ms, max %.2f ms\n",
      s.frames_read, s.frames_processed, s.frames_dropped, s.latency.percentile(50),
      s.latency.percentile(99), s.latency.max());
  const auto rows = lines(readFile(opt.out_dir + "/tracks.csv"));
  CHECK(rows.size() > 50);  // 20 walkers over 4 s
}
