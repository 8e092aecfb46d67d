#pragma once
// KITTI's Velodyne scans on disk (raw, tracking and object datasets): which scans a path names,
// when each was taken, the points of one, and the vehicle's poses from its OXTS (GPS/IMU)
// records. Private to the `kitti` sensor.
#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/poses/CPose3D.h>

#include <optional>
#include <string>
#include <vector>

#include "pedtrack/kitti_oxts.h"

namespace pedtrack::kitti {

struct Scan {
  std::string path;
  double t = 0;    ///< s
  long index = 0;  ///< the number the file is named by (000042.bin: 42)
};

/// The scans `input` names: a `.bin` file, or every `.bin` of a folder in name order (KITTI raw's
/// `velodyne_points/data`, tracking's `velodyne/SSSS`, object's `velodyne`). Times come from
/// KITTI raw's `timestamps.txt` beside `data/` when there is one, else index / rate. Throws
/// DataError naming the path at fault (no scans, a name that is not a number, timestamps that do
/// not match the scans).
std::vector<Scan> listScans(const std::string& input, double rate);

/// One scan: float32 x, y, z, reflectance per point, little-endian, Velodyne frame. Throws
/// DataError naming the file (unreadable, not a whole number of 16-byte points).
mrpt::maps::CPointsMapXYZI::Ptr readScan(const std::string& path);

/// Where the OXTS records of `input`'s scans are when not given: KITTI raw's `oxts/data` folder
/// (one file per scan) beside `velodyne_points`, or tracking's `oxts/SSSS.txt` (one line per scan)
/// for `velodyne/SSSS`; empty when neither exists (the object dataset has none).
std::string findOxts(const std::string& input);

}  // namespace pedtrack::kitti
