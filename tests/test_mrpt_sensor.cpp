// The mrpt_sensor source driving a real MRPT driver: CVelodyneScanner replaying a pcap capture
// made from the packets of MRPT's VLP-16 sample, configured with MRPT's own keys. And the TCP
// link it gives an Ethernet Hokuyo, whose writes return whatever the device does.
#include <arpa/inet.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

#include "../plugins/sensors/mrpt_sensor/bounded_tcp_socket.h"
#include "pedtrack/errors.h"
#include "pedtrack/pipeline.h"
#include "test_support.h"

using namespace pedtrack;
using namespace pedtrack::test;

namespace {

template <typename T>
void put(std::ofstream& f, T v) {
  f.write(reinterpret_cast<const char*>(&v), sizeof v);
}

// Writes the VLP-16 sample's UDP data packets as an Ethernet pcap capture (what the sensor sends
// to port 2368), `repeats` times over so the driver sees complete revolutions.
std::size_t writePcap(const std::string& path, int repeats) {
  mrpt::io::CFileGZInputStream in(mrptDataset("test_velodyne_VLP16.rawlog"));
  auto obs = mrpt::serialization::archiveFrom(in).ReadObject<mrpt::obs::CObservationVelodyneScan>();
  std::ofstream f(path, std::ios::binary);
  put<std::uint32_t>(f, 0xa1b2c3d4);
  put<std::uint16_t>(f, 2);
  put<std::uint16_t>(f, 4);
  put<std::int32_t>(f, 0);
  put<std::uint32_t>(f, 0);
  put<std::uint32_t>(f, 65535);
  put<std::uint32_t>(f, 1);  // LINKTYPE_ETHERNET
  const std::size_t payload = mrpt::obs::CObservationVelodyneScan::PACKET_SIZE;
  std::size_t n = 0;
  for (int rep = 0; rep < repeats; ++rep) {
    for (const auto& pkt : obs->scan_packets) {
      unsigned char hdr[42] = {0};
      std::memset(hdr, 0xff, 6);  // Ethernet: broadcast
      hdr[12] = 0x08;             // IPv4
      hdr[14] = 0x45;             // version 4, 20-byte header
      const std::uint16_t ip_len = 20 + 8 + payload, udp_len = 8 + payload;
      hdr[16] = ip_len >> 8, hdr[17] = ip_len & 0xff;
      hdr[22] = 64, hdr[23] = 17;  // TTL, UDP
      hdr[26] = 192, hdr[27] = 168, hdr[28] = 1, hdr[29] = 201;
      hdr[30] = 255, hdr[31] = 255, hdr[32] = 255, hdr[33] = 255;
      hdr[34] = 2368 >> 8, hdr[35] = 2368 & 0xff;  // source port
      hdr[36] = 2368 >> 8, hdr[37] = 2368 & 0xff;  // destination port
      hdr[38] = udp_len >> 8, hdr[39] = udp_len & 0xff;
      const std::uint32_t usec = static_cast<std::uint32_t>(n * 1327);  // 754 packets/s
      put<std::uint32_t>(f, 1519637061 + usec / 1000000);
      put<std::uint32_t>(f, usec % 1000000);
      put<std::uint32_t>(f, 42 + payload);
      put<std::uint32_t>(f, 42 + payload);
      f.write(reinterpret_cast<const char*>(hdr), 42);
      f.write(reinterpret_cast<const char*>(&pkt), payload);
      ++n;
    }
  }
  return n;
}

// A listening TCP socket on 127.0.0.1 (an ephemeral port), as a device would be.
struct LoopbackListener {
  int fd = -1;
  unsigned short port = 0;
  LoopbackListener() {
    fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&a), len) == 0);
    REQUIRE(::listen(fd, 1) == 0);
    REQUIRE(::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0);
    port = ntohs(a.sin_port);
  }
  int accept() const { return ::accept(fd, nullptr, nullptr); }
  ~LoopbackListener() { ::close(fd); }
};

// mrpt_sensor's Hokuyo link connected to a listener: `peer` is the device's end.
struct ConnectedLink {
  LoopbackListener device;
  pedtrack::mrpt_sensor::BoundedTcpSocket link;
  int peer = -1;
  ConnectedLink() {
    link.connect("127.0.0.1", device.port);
    peer = device.accept();
    REQUIRE(peer >= 0);
  }
  ~ConnectedLink() {
    if (peer >= 0) ::close(peer);
  }
};

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// MRPT 2.5's own CClientTCPSocket retries a failed send() for ever: a Hokuyo that reset the
// connection while CHokuyoURG reconfigured it hung the pipeline inside doProcess() (seen in CI).
TEST_CASE("mrpt_sensor's Hokuyo link: a write to a reset connection returns and drops the link",
          "[mrpt_sensor]") {
  ConnectedLink c;
  auto& link = c.link;
  const linger reset{1, 0};  // close with RST, as a device that reboots
  ::setsockopt(c.peer, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
  ::close(c.peer);
  c.peer = -1;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the RST arrives
  mrpt::io::CStream& stream = link;                            // as CHokuyoURG::sendCmd writes
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 3; ++i) CHECK(stream.Write("QT\n", 3) == 3);
  CHECK(secondsSince(t0) < 0.5);
  CHECK_FALSE(link.isConnected());  // CHokuyoURG's next check reconnects
  CHECK(link.failedWrites() == 1);
}

TEST_CASE("mrpt_sensor's Hokuyo link: a device that stops reading bounds a write to its timeout",
          "[mrpt_sensor]") {
  using pedtrack::mrpt_sensor::BoundedTcpSocket;
  ConnectedLink c;  // the device never reads: the send buffers fill up
  auto& link = c.link;
  const std::vector<char> big(64 << 20, 'x');
  mrpt::io::CStream& stream = link;
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(stream.Write(big.data(), big.size()) == big.size());
  const double took = secondsSince(t0);
  CHECK(took >= BoundedTcpSocket::kWriteTimeoutMs * 1e-3 * 0.9);
  CHECK(took < BoundedTcpSocket::kWriteTimeoutMs * 1e-3 + 2.0);
  CHECK_FALSE(link.isConnected());
  CHECK(link.failedWrites() == 1);
}

TEST_CASE("mrpt_sensor runs CVelodyneScanner from an unchanged rawlog-grabber section",
          "[mrpt_sensor]") {
  const std::string dir = freshDir("mrpt_sensor_pcap");
  REQUIRE(writePcap(dir + "/vlp16.pcap", 3) > 100);
  // A rawlog-grabber section, plus the plugin line and when to stop.
  const std::string ini =
      "[pipeline]\nstages = velodyne\n"
      "[velodyne]\nplugin = mrpt_sensor\nend_on_idle = true\nidle_timeout = 2\n"
      "driver = CVelodyneScanner\nsensorLabel = VELODYNE\nprocess_rate = 100\nmodel = VLP16\n"
      "pcap_input = " +
      dir +
      "/vlp16.pcap\npcap_read_once = true\npcap_read_fast = true\n"
      "pose_z = 1.2\n";
  const std::vector<Frame> frames = readAllFrames(ini, "grabber.ini");
  REQUIRE(frames.size() >= 1);
  const auto* scan =
      dynamic_cast<const mrpt::obs::CObservationVelodyneScan*>(frames[0].observations[0].get());
  REQUIRE(scan != nullptr);
  CHECK(scan->sensorLabel == "VELODYNE_SCAN");      // the driver appends _SCAN to sensorLabel
  CHECK(frames[0].sensor_pose.z() == Approx(1.2));  // MRPT's own pose_z key reached the driver
  CHECK(frames[0].cloud().size() > 10000);          // a VLP-16 revolution: ~29k returns
}

TEST_CASE("mrpt_sensor names an unknown driver class", "[mrpt_sensor]") {
  const std::string ini =
      "[pipeline]\nstages = s\n[s]\nplugin = mrpt_sensor\ndriver = CNoSuchScanner\n";
  const auto cfg = PipelineConfig::fromText(ini, "g.ini", {}, testRegistry());
  CHECK_THROWS_WITH(
      Pipeline(cfg),
      Catch::StartsWith("g.ini: [s] driver: 'CNoSuchScanner' is not an MRPT sensor class"));
}
