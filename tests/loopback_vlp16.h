#pragma once
// A VLP-16 on loopback: sends real-format Velodyne data packets (1206-byte UDP payloads, as the
// simulator builds them) and position packets (512 bytes with a $GPRMC sentence) to 127.0.0.1,
// to the ports MRPT's CVelodyneScanner listens on. Tests set those ports (the driver's static
// VELODYNE_DATA_UDP_PORT / VELODYNE_POSITION_UDP_PORT) to free ones chosen at run time.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cstddef>

namespace pedtrack::test {

/// A UDP port that was free a moment ago (bound to port 0, read back, released).
int freeUdpPort();

class LoopbackVlp16 {
 public:
  LoopbackVlp16(int data_port, int position_port);
  ~LoopbackVlp16();
  LoopbackVlp16(const LoopbackVlp16&) = delete;
  LoopbackVlp16& operator=(const LoopbackVlp16&) = delete;

  /// Sends one revolution that starts at `t` (UNIX s): its data packets, paced over `seconds` (a
  /// real VLP-16 spreads a 10 Hz revolution's 75 packets over 0.1 s), with a position packet
  /// after every 14th data packet, as the device does. Returns the data packets sent.
  std::size_t sendRevolution(const mrpt::obs::CObservationVelodyneScan& scan, double t,
                             double seconds);
  /// A datagram of the wrong size and content on the data port (a malformed packet).
  void sendGarbage();

 private:
  void sendTo(int port, const void* data, std::size_t size);
  void sendPosition(double t);
  std::size_t data_sent_ = 0;
  int fd_ = -1;
  int data_port_, position_port_;
};

}  // namespace pedtrack::test
