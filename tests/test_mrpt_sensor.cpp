// The mrpt_sensor source driving a real MRPT driver: CVelodyneScanner replaying a pcap capture
// made from the packets of MRPT's VLP-16 sample, configured with MRPT's own keys.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <fstream>

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

}  // namespace

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
