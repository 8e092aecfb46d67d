#include "velodyne_udp/revolution_assembler.h"

#include <cmath>
#include <cstring>

#include "pedtrack/velodyne_decode.h"

namespace pedtrack::velodyne_udp {
namespace {

using Velo = mrpt::obs::CObservationVelodyneScan;
constexpr std::uint8_t kVlp16 = 0x22;
constexpr std::int64_t kHourUs = 3600ll * 1000000ll;

}  // namespace

long packetsLostInGap(std::int64_t dt_us, double period_us) {
  if (dt_us < 0) dt_us += kHourUs;  // the timestamp wrapped at the top of the hour
  if (dt_us < 0 || dt_us > 10 * 1000000ll) return 0;  // a clock jump, not a gap
  return std::max(0l, std::lround(double(dt_us) / period_us) - 1);
}

bool RevolutionAssembler::add(const std::uint8_t* data, std::size_t size, double t,
                              Revolution& done) {
  RawPacket p;
  if (size != sizeof(RawPacket)) {
    ++bad_;
    return false;
  }
  std::memcpy(&p, data, sizeof p);
  for (const auto& b : p.blocks)
    if (b.header() != Velo::UPPER_BANK || b.rotation() >= 36000) {
      ++bad_;
      return false;
    }
  if (p.velodyne_model_ID != kVlp16) {
    ++bad_;
    return false;
  }
  ++packets_;
  // Dual return: each azimuth in two blocks, so a packet spans 6 firing blocks, not 12.
  const bool dual = p.laser_return_mode == Velo::RETMODE_DUAL;
  dual_ += dual;
  const double period = (dual ? 6 : 12) * vlp16::kBlockUs;
  const std::int64_t stamp = p.gps_timestamp();
  if (last_stamp_us_ >= 0) lost_ += packetsLostInGap(stamp - last_stamp_us_, period);
  last_stamp_us_ = stamp;
  const int azimuth = p.blocks[0].rotation();
  const bool wraps = last_azimuth_ >= 0 && azimuth < last_azimuth_;
  last_azimuth_ = azimuth;
  bool completed = false;
  if (wraps && !current_.packets.empty()) {
    done = std::move(current_);
    current_ = Revolution();
    completed = true;
  }
  if (current_.packets.empty()) current_.t = t;
  current_.packets.push_back(p);
  return completed;
}

}  // namespace pedtrack::velodyne_udp
