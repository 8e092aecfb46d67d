#pragma once
// VLP-16 data packets into whole revolutions, counting what went missing on the way.
//
// A revolution ends where the head's azimuth wraps (the first block of a packet turns back from
// the previous packet's), as MRPT's CVelodyneScanner splits them. Lost packets are counted from
// gaps in the packets' own timestamps (µs since the top of the hour): the device sends one every
// 12 firing blocks (1,327 µs; 664 µs in dual-return mode), so a gap of k periods lost k - 1.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pedtrack::velodyne_udp {

using RawPacket = mrpt::obs::CObservationVelodyneScan::TVelodyneRawPacket;

struct Revolution {
  std::vector<RawPacket> packets;
  double t = 0;  ///< UNIX s: when its first packet arrived
};

class RevolutionAssembler {
 public:
  /// One datagram received at `t` (UNIX s). Returns true and fills `done` when this packet
  /// starts a new revolution (the one it completes is moved out). A datagram that is no VLP-16
  /// data packet (size, block flags, model) is counted and ignored.
  bool add(const std::uint8_t* data, std::size_t size, double t, Revolution& done);

  long packets() const { return packets_; }         ///< data packets accepted
  long badPackets() const { return bad_; }          ///< datagrams that were no data packet
  long lostPackets() const { return lost_; }        ///< gaps in the packets' timestamps
  long dualReturnPackets() const { return dual_; }  ///< packets in dual-return mode

 private:
  Revolution current_;
  int last_azimuth_ = -1;            // first block of the previous packet, 0.01°
  std::int64_t last_stamp_us_ = -1;  // previous packet's timestamp
  long packets_ = 0, bad_ = 0, lost_ = 0, dual_ = 0;
};

/// The packets a gap of `dt_us` between consecutive packets' timestamps lost, for packets sent
/// every `period_us` (the clock wraps at the top of the hour).
long packetsLostInGap(std::int64_t dt_us, double period_us);

}  // namespace pedtrack::velodyne_udp
