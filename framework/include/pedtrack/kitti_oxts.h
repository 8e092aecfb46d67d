#pragma once
// KITTI's OXTS (GPS/IMU) records and the vehicle poses they give, for the sources that replay a
// KITTI sequence (`kitti`: its Velodyne scans; `detections`: a detector's output on them).
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace pedtrack::kitti {

/// One OXTS record's position and attitude (KITTI's first six values).
struct Oxts {
  double lat = 0, lon = 0, alt = 0;     ///< deg, deg, m
  double roll = 0, pitch = 0, yaw = 0;  ///< rad
};

/// The record of scan `index` from `oxts`: a folder (its file named like the scan, .txt) or a file
/// (its line `index`, from 0). Throws DataError naming the file and line at fault.
Oxts readOxts(const std::string& oxts, long index);

/// KITTI devkit's convertOxtsToPose: a Mercator projection with the scale of the sequence's first
/// latitude (`scale` = cos(lat0)), x east, y north, z up; rotation Rz(yaw) Ry(pitch) Rx(roll).
mrpt::poses::CPose3D oxtsPose(const Oxts& o, double scale);

/// A sequence's robot poses from its OXTS records. The robot frame stands on the road under the
/// scanner; the fixed frame is the robot frame of the first scan asked for.
class OxtsTrajectory {
 public:
  /// `imu_to_velo`: where the scanner is in the OXTS unit's frame (m; KITTI's Tr_imu_to_velo
  /// inverted, its rotation of under 1 degree left out); `mount_z`: the scanner above the road.
  OxtsTrajectory(std::string oxts, const std::vector<double>& imu_to_velo, double mount_z);
  mrpt::poses::CPose3D robotPose(long index);

 private:
  std::string oxts_;
  mrpt::poses::CPose3D robot_in_imu_, origin_inv_;
  double scale_ = 1;
  bool started_ = false;
};

}  // namespace pedtrack::kitti
