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

#include <vector>

namespace pedtrack {

struct VelodynePoint {
  float x, y, z;  ///< sensor frame (MRPT axes: x forward, y left), m
  int laser;      ///< laser (ring) index
  float azimuth;  ///< rad, MRPT convention (counter-clockwise)
};

std::vector<VelodynePoint> decodeVelodyne(const mrpt::obs::CObservationVelodyneScan& scan);

}  // namespace pedtrack
