#pragma once
// Decodes the raw packets of a CObservationVelodyneScan into sensor-frame points.
//
// Why not MRPT's generatePointCloud(): MRPT 2.5.8 reads only the first 16 of the 32 returns in
// each VLP-16 firing block, dropping the second firing — half of every real VLP-16 scan
// (test_velodyne_VLP16.rawlog: 22,591 returns in the packets, 11,305 decoded). This decoder
// reads both firings with MRPT's own timing-based azimuth interpolation and calibration, and
// falls back to MRPT for 32- and 64-laser models, which MRPT decodes fully.
#include <mrpt/math/TPoint3D.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cmath>
#include <vector>

namespace pedtrack {

/// VLP-16 firing timing (datasheet, and MRPT's decoder): a block of two firings of 16 lasers
/// lasts 110.592 µs, lasers fire 2.304 µs apart, the second firing starts 55.296 µs in.
namespace vlp16 {
constexpr double kBlockUs = 110.592, kLaserUs = 2.304, kFiringUs = 55.296;
/// Azimuth (0.01° units) by which `laser` of `firing` lags its block's rotation value when the
/// head turns `block_units` per block. Encoder (simulator) and decoder share it.
inline int azimuthOffset(int laser, int firing, int block_units) {
  return static_cast<int>(
      std::lround(block_units * (laser * kLaserUs + firing * kFiringUs) / kBlockUs));
}
}  // namespace vlp16

struct VelodynePoint {
  float x, y, z;  ///< sensor frame (MRPT axes: x forward, y left), m
  int laser;      ///< laser (ring) index
  float azimuth;  ///< rad, MRPT convention (counter-clockwise)
};

std::vector<VelodynePoint> decodeVelodyne(const mrpt::obs::CObservationVelodyneScan& scan);

}  // namespace pedtrack
