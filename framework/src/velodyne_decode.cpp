#include "pedtrack/velodyne_decode.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pedtrack {
namespace {

using Velo = mrpt::obs::CObservationVelodyneScan;

}  // namespace

std::vector<VelodynePoint> decodeVelodyne(const Velo& scan) {
  std::vector<VelodynePoint> out;
  const std::size_t lasers = scan.calibration.laser_corrections.size();
  if (lasers != 16) {
    Velo copy = scan;  // MRPT decodes 32/64-laser models completely
    copy.generatePointCloud();
    const auto& pc = copy.point_cloud;
    for (std::size_t i = 0; i < pc.size(); ++i)
      out.push_back({pc.x[i], pc.y[i], pc.z[i], i < pc.laser_id.size() ? pc.laser_id[i] : 0,
                     std::atan2(pc.y[i], pc.x[i])});
    return out;
  }
  const double min_r = scan.minRange, max_r = scan.maxRange;
  out.reserve(scan.scan_packets.size() * Velo::BLOCKS_PER_PACKET * Velo::SCANS_PER_BLOCK);
  for (const auto& pkt : scan.scan_packets) {
    const bool dual = pkt.laser_return_mode == Velo::RETMODE_DUAL;
    const int step = dual ? 2 : 1;
    // Median rotation between consecutive blocks, to interpolate within a block.
    std::array<int, Velo::BLOCKS_PER_PACKET> diffs{};
    int nd = 0;
    for (int b = 0; b + step < Velo::BLOCKS_PER_PACKET; ++b)
      diffs[nd++] =
          (Velo::ROTATION_MAX_UNITS + pkt.blocks[b + step].rotation() - pkt.blocks[b].rotation()) %
          Velo::ROTATION_MAX_UNITS;
    std::nth_element(diffs.begin(), diffs.begin() + nd / 2, diffs.begin() + nd);
    const int median = diffs[nd / 2];
    for (int b = 0; b < Velo::BLOCKS_PER_PACKET; ++b) {
      const auto& blk = pkt.blocks[b];
      if (blk.header() != Velo::UPPER_BANK) continue;
      // Dual return: blocks come in pairs (last, strongest) with one rotation; the pair's
      // stronger return is kept (when the strongest is also the last, the second block holds
      // the second-strongest instead).
      if (dual && b % 2 == 1) continue;
      for (int k = 0; k < Velo::SCANS_PER_BLOCK; ++k) {
        uint16_t raw = blk.laser_returns[k].distance();
        if (dual) {
          const auto& other = pkt.blocks[b + 1].laser_returns[k];
          if (!raw || (other.distance() && other.intensity() > blk.laser_returns[k].intensity()))
            raw = other.distance();
        }
        if (!raw) continue;
        const int laser = k % 16, firing = k / 16;
        const auto& c = scan.calibration.laser_corrections[laser];
        const double dist = raw * Velo::DISTANCE_RESOLUTION + c.distanceCorrection;
        if (dist < min_r || dist > max_r) continue;
        const int units = (blk.rotation() + vlp16::azimuthOffset(laser, firing, median)) %
                          Velo::ROTATION_MAX_UNITS;
        // Velodyne azimuth is clockwise from the device's forward axis; MRPT's +y is left.
        const double az = units * 0.01 * M_PI / 180.0;
        const double ca = std::cos(az), sa = std::sin(az);
        const double xy =
            dist * c.cosVertCorrection + c.verticalOffsetCorrection * c.sinVertCorrection;
        const double ho = c.horizontalOffsetCorrection;
        out.push_back({static_cast<float>(xy * ca + ho * sa),
                       static_cast<float>(-(xy * sa - ho * ca)),
                       static_cast<float>(dist * c.sinVertCorrection + c.verticalOffsetCorrection),
                       laser, static_cast<float>(-az)});
      }
    }
  }
  return out;
}

}  // namespace pedtrack
