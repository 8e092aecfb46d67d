// VLP-16 data packets: the input is cut into 1206-byte UDP payloads (the last one padded) and
// decoded with the VLP-16 calibration, as a live revolution or a pcap replay is.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cstdint>
#include <cstring>

#include "pedtrack/velodyne_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using Scan = mrpt::obs::CObservationVelodyneScan;
  static const mrpt::obs::VelodyneCalibration calib =
      mrpt::obs::VelodyneCalibration::LoadDefaultCalibration("VLP16");
  Scan scan;
  scan.calibration = calib;
  constexpr std::size_t kPacket = sizeof(Scan::TVelodyneRawPacket);
  static_assert(kPacket == 1206, "a VLP-16 data packet is 1206 bytes");
  for (std::size_t off = 0; off < size; off += kPacket) {
    Scan::TVelodyneRawPacket p{};
    std::memcpy(&p, data + off, std::min(kPacket, size - off));
    scan.scan_packets.push_back(p);
  }
  const auto points = pedtrack::decodeVelodyne(scan);
  for (const auto& pt : points)
    if (!(pt.laser >= 0 && pt.laser < 16)) __builtin_trap();  // a ring that does not exist
  return 0;
}
