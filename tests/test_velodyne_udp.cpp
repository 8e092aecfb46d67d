// The velodyne_udp source: the revolution assembler on the simulator's packets (lost packets
// counted from the packets' timestamps), then the live reader on loopback at the VLP-16's real
// rate (754 packets/s single return, 1,508 dual) and at 4x that, read at once or by a consumer
// slowed by an injected delay: no packet lost while the queue has room; when it overflows,
// whole revolutions are dropped and counted, and every one delivered is complete.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>
#include <map>
#include <thread>

#include "loopback_vlp16.h"
#include "pedtrack/pipeline.h"
#include "pedtrack/sim/simulator.h"
#include "pedtrack/velodyne_decode.h"
#include "test_support.h"
#include "velodyne_udp/revolution_assembler.h"

using namespace pedtrack;
using namespace pedtrack::test;
using Velo = mrpt::obs::CObservationVelodyneScan;
using pedtrack::velodyne_udp::packetsLostInGap;
using pedtrack::velodyne_udp::Revolution;
using pedtrack::velodyne_udp::RevolutionAssembler;

namespace {

const std::string kConfigs = std::string(PEDTRACK_SOURCE_DIR) + "/configs/";

void setStamp(Velo::TVelodyneRawPacket& p, double us) {
  const auto v = std::uint32_t(std::lround(std::fmod(us, 3600e6)));
  std::memcpy(reinterpret_cast<char*>(&p) + 1200, &v, 4);  // after the 12 blocks of 100 bytes
}

// The first `n` revolutions of the simulated crowd, stamped as a device's clock runs: a packet
// every 12 firing blocks without a break (the simulator starts each revolution at its frame
// time, 0.5 ms after the 75th packet of the one before).
std::vector<Velo::Ptr> simulate(int n) {
  sim::Simulator s(sim::loadScenario(kConfigs + "scenarios/crowd.ini"));
  s.setPointTruth(false);
  std::vector<Velo::Ptr> out;
  sim::SimFrame f;
  double us = 0;
  while (int(out.size()) < n && s.next(f)) {
    out.push_back(std::dynamic_pointer_cast<Velo>(f.observations.back()));
    for (auto& p : out.back()->scan_packets) setStamp(p, us), us += 12 * vlp16::kBlockUs;
  }
  return out;
}

// A revolution in dual-return mode: each block twice (strongest, last), six azimuths a packet,
// packets 6 firing blocks apart.
Velo::Ptr dualReturn(const Velo& single) {
  auto out = Velo::Create();
  *out = single;
  out->scan_packets.clear();
  for (const auto& p : single.scan_packets) {
    for (int half = 0; half < 2; ++half) {
      Velo::TVelodyneRawPacket d = p;
      for (int b = 0; b < Velo::BLOCKS_PER_PACKET; ++b) d.blocks[b] = p.blocks[6 * half + b / 2];
      d.laser_return_mode = Velo::RETMODE_DUAL;
      setStamp(d, p.gps_timestamp() + half * 6 * vlp16::kBlockUs);
      out->scan_packets.push_back(d);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("lost packets are counted from gaps in the packets' timestamps", "[velodyne_udp]") {
  const double period = 12 * vlp16::kBlockUs;  // 1,327.1 µs
  CHECK(packetsLostInGap(1327, period) == 0);
  CHECK(packetsLostInGap(1800, period) == 0);  // between two simulated revolutions
  CHECK(packetsLostInGap(2654, period) == 1);
  CHECK(packetsLostInGap(5 * 1327, period) == 4);
  CHECK(packetsLostInGap(1327 - 3600ll * 1000000, period) == 0);  // the top of the hour
  CHECK(packetsLostInGap(-5000000, period) == 0);                 // a clock step back
}

TEST_CASE("the assembler cuts revolutions where the azimuth wraps and counts what is missing",
          "[velodyne_udp]") {
  const auto revs = simulate(4);
  const std::size_t per = revs[0]->scan_packets.size();
  REQUIRE(per == 75);
  RevolutionAssembler a;
  std::vector<Revolution> done;
  Revolution r;
  std::size_t fed = 0;
  for (std::size_t k = 0; k < revs.size(); ++k)
    for (std::size_t i = 0; i < per; ++i) {
      if (k == 1 && i == 10) continue;  // a packet lost on the way
      const auto& p = revs[k]->scan_packets[i];
      if (a.add(reinterpret_cast<const std::uint8_t*>(&p), sizeof p, double(fed++), r))
        done.push_back(r);
    }
  const std::uint8_t junk[100] = {};
  CHECK_FALSE(a.add(junk, sizeof junk, 0, r));
  REQUIRE(done.size() == 3);  // the fourth stays open until a fifth starts
  CHECK(done[0].packets.size() == per);
  CHECK(done[1].packets.size() == per - 1);
  CHECK(done[2].packets.size() == per);
  CHECK(done[1].t == double(per));  // its first packet's arrival
  CHECK(std::memcmp(done[2].packets.data(), revs[2]->scan_packets.data(),
                    per * sizeof(Velo::TVelodyneRawPacket)) == 0);
  CHECK(a.lostPackets() == 1);
  CHECK(a.badPackets() == 1);
  CHECK(a.packets() == long(4 * per - 1));
  // Dual return: twice the packets, each half the period apart, nothing counted lost.
  RevolutionAssembler dual;
  std::size_t dual_done = 0;
  for (const auto& v : revs) {
    const auto d = dualReturn(*v);
    for (const auto& p : d->scan_packets)
      dual_done += dual.add(reinterpret_cast<const std::uint8_t*>(&p), sizeof p, 0, r);
  }
  CHECK(dual_done == 3);
  CHECK(r.packets.size() == 2 * per);
  CHECK(dual.lostPackets() == 0);
  CHECK(dual.dualReturnPackets() == long(8 * per));
}

namespace {

struct LoopbackResult {
  std::size_t sent = 0, frames = 0, torn = 0;
  long packets = 0, lost = 0, kernel = 0, revolutions = 0, dropped = 0, rcvbuf = 0;
};

// Sends `revs` to a velodyne_udp source on loopback, each revolution over `seconds`, while a
// consumer takes frames and sleeps `consumer_ms` after each (the stages, slowed).
LoopbackResult loopback(const std::vector<Velo::Ptr>& revs, double seconds, int consumer_ms,
                        int queue, int rcvbuf = 8 << 20) {
  const int port = freeUdpPort();
  PipelineOverrides ov;
  ov.sets = {"source.plugin=velodyne_udp",
             "source.address=127.0.0.1",
             "source.port=" + std::to_string(port),
             "source.queue=" + std::to_string(queue),
             "source.idle_timeout=1",
             "source.end_on_idle=true",
             "source.rcvbuf=" + std::to_string(rcvbuf)};
  const auto cfg = PipelineConfig::fromText("[pipeline]\nstages = source\n[source]\nplugin = sim\n",
                                            kConfigs + "live.ini", ov, testRegistry());
  Pipeline p(cfg);  // bound here, before anything is sent
  LoopbackResult r;
  std::thread device([&] {
    LoopbackVlp16 dev(port, freeUdpPort());
    for (const auto& v : revs) r.sent += dev.sendRevolution(*v, 0, seconds);
  });
  const std::size_t per = revs[0]->scan_packets.size();
  Frame f;
  while (p.source().next(f)) {
    const auto* got = dynamic_cast<const Velo*>(f.observations.at(0).get());
    REQUIRE(got);
    r.frames++;
    r.torn += got->scan_packets.size() != per;
    f = Frame();
    if (consumer_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(consumer_ms));
  }
  device.join();
  for (const auto& [k, v] : p.source().counters()) {
    if (k == "packets") r.packets = v;
    if (k == "packets_lost") r.lost = v;
    if (k == "kernel_drops") r.kernel = v;
    if (k == "revolutions") r.revolutions = v;
    if (k == "revolutions_dropped") r.dropped = v;
    if (k == "rcvbuf_bytes") r.rcvbuf = v;
  }
  return r;
}

void print(const char* what, const LoopbackResult& r) {
  std::printf(
      "velodyne_udp %-34s sent %5zu received %5ld lost %ld kernel drops %ld; "
      "revolutions %ld delivered %zu dropped %ld torn %zu (rcvbuf %ld)\n",
      what, r.sent, r.packets, r.lost, r.kernel, r.revolutions, r.frames, r.dropped, r.torn,
      r.rcvbuf);
}

}  // namespace

TEST_CASE("velodyne_udp on loopback: every packet at 1x and 4x the VLP-16's rate, single and dual",
          "[velodyne_udp][live]") {
  const auto single = simulate(31);
  std::vector<Velo::Ptr> dual;
  for (const auto& v : single) dual.push_back(dualReturn(*v));
  const double real = 75 / 754.0;  // s a revolution's 75 packets take at 754 packets/s
  struct Case {
    const char* what;
    const std::vector<Velo::Ptr>* revs;
    double seconds;
  };
  for (const Case& c : {Case{"single return, 754 packets/s", &single, real},
                        Case{"single return, 4x (3,016 packets/s)", &single, real / 4},
                        Case{"dual return, 1,508 packets/s", &dual, real},
                        Case{"dual return, 4x (6,032 packets/s)", &dual, real / 4}}) {
    INFO(c.what);
    const LoopbackResult r = loopback(*c.revs, c.seconds, 0, 10);
    print(c.what, r);
    CHECK(r.packets == long(r.sent));
    CHECK(r.lost == 0);
    CHECK(r.kernel == 0);
    CHECK(r.revolutions == long(c.revs->size()) - 1);  // the last stays open
    CHECK(r.frames == c.revs->size() - 1);
    CHECK(r.dropped == 0);
    CHECK(r.torn == 0);
  }
}

TEST_CASE("velodyne_udp with slowed stages: no packet lost, whole revolutions dropped and counted",
          "[velodyne_udp][live]") {
  const auto revs = simulate(31);
  const double real = 75 / 754.0;
  // A consumer at 50 ms a frame keeps up with 10 revolutions/s; one at 250 ms does not, and the
  // queue of 4 overflows; at 4x even the first falls behind.
  struct Case {
    const char* what;
    double seconds;
    int consumer_ms;
  };
  for (const Case& c :
       {Case{"1x, stages 50 ms a frame", real, 50}, Case{"1x, stages 250 ms a frame", real, 250},
        Case{"4x, stages 50 ms a frame", real / 4, 50}}) {
    INFO(c.what);
    const LoopbackResult r = loopback(revs, c.seconds, c.consumer_ms, 4);
    print(c.what, r);
    CHECK(r.packets == long(r.sent));
    CHECK(r.lost == 0);
    CHECK(r.kernel == 0);
    CHECK(r.revolutions == long(revs.size()) - 1);
    CHECK(long(r.frames) + r.dropped == r.revolutions);  // each delivered or counted dropped
    CHECK(r.torn == 0);
    if (c.consumer_ms == 250) CHECK(r.dropped > 10);
    if (c.consumer_ms == 50 && c.seconds == real) CHECK(r.dropped == 0);
  }
}

TEST_CASE("velodyne_udp counts what the network and the kernel lost", "[velodyne_udp][live]") {
  auto revs = simulate(31);
  // Every 25th packet never sent (a lossy link): counted from the gaps in the device's clock.
  std::size_t removed = 0;
  for (auto& v : revs) {
    auto& p = v->scan_packets;
    for (std::size_t i = 24; i < p.size(); i += 24) p.erase(p.begin() + long(i)), ++removed;
  }
  const double real = 75 / 754.0;
  const LoopbackResult lossy = loopback(revs, real, 0, 10);
  print("every 25th packet not sent", lossy);
  CHECK(lossy.packets == long(lossy.sent));
  CHECK(lossy.lost == long(removed) - 1);  // the very last packet's absence shows no gap
  CHECK(lossy.kernel == 0);
  // A burst without pacing into the smallest buffer (here: 1,800 of 2,325 packets received):
  // what the kernel drops is counted by the socket (SO_RXQ_OVFL) and again by the gaps.
  const LoopbackResult burst = loopback(simulate(31), 0, 0, 100, 65536);
  print("burst, smallest receive buffer", burst);
  // Both count the drops before the last packet received (a drop after it shows in neither).
  CHECK(burst.lost == burst.kernel);
  CHECK(burst.packets + burst.kernel <= long(burst.sent));
}

TEST_CASE("velodyne_udp: a live 3D pipeline tracks the people of every revolution",
          "[velodyne_udp][live][pipeline]") {
  // The crowd at the VLP-16's own pace (10 revolutions a second), people_3d_vlp16's stages
  // behind the source. PEDTRACK_LIVE_FRAMES: longer, for scripts/live_latency.sh.
  const auto revs = simulate(int(liveFrames(40)) + 1);
  const int port = freeUdpPort();
  PipelineOverrides ov;
  ov.source_plugin = "velodyne_udp";  // in place of the pipeline's simulator
  ov.sets = {"source.address=127.0.0.1", "source.port=" + std::to_string(port),
             "source.idle_timeout=1", "source.end_on_idle=true", "source.pose_z=1.0"};
  const std::string ini = kConfigs + "people_3d_vlp16.ini";
  const auto cfg = PipelineConfig::fromText(readFile(ini), ini, ov, testRegistry());
  Pipeline p(cfg);
  std::size_t sent = 0;
  std::thread device([&] {
    pinToDeviceCpu();
    LoopbackVlp16 dev(port, freeUdpPort());
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < revs.size(); ++i) {
      sent += dev.sendRevolution(*revs[i], 0, 75 / 754.0);
      std::this_thread::sleep_until(start + std::chrono::milliseconds(100 * (i + 1)));
    }
  });
  RunOptions opt;
  opt.out_dir = freshDir("velodyne_udp_live");
  opt.progress = false;
  const RunSummary s = p.run(opt);
  device.join();
  INFO(s.error);
  CHECK(s.status == "ok");
  std::map<std::string, long> c;
  for (const auto& [k, v] : s.stages[0].counters) c[k] = v;
  std::printf(
      "velodyne_udp live: %zu revolutions sent, %zu read, %zu processed, %zu dropped, "
      "%ld packets lost; latency p50 %.2f ms, p99 %.2f ms, max %.2f ms\n",
      revs.size() - 1, s.frames_read, s.frames_processed, s.frames_dropped,
      c["packets_lost"] + c["kernel_drops"], s.latency.percentile(50), s.latency.percentile(99),
      s.latency.max());
  CHECK(c["packets"] == long(sent));  // nothing lost on the way in
  CHECK(s.frames_read == revs.size() - 1);
  if (!kSanitized) CHECK(s.frames_processed == s.frames_read);  // a Release build keeps up
  const auto rows = lines(readFile(opt.out_dir + "/tracks.csv"));
  CHECK(rows.size() > 50);  // 20 walkers over 4 s
}
