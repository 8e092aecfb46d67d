#pragma once
// KITTI's OXTS (GPS/IMU) records and the vehicle poses they give, for the sources that replay a
// KITTI sequence (`kitti`: its Velodyne scans; `detections`: a detector's output on them).
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

#include "pedtrack/param_table.h"

namespace pedtrack::kitti {

/// How KITTI's car carries its Velodyne, and how fast it scans: the keys the `kitti` and
/// `detections` sources share.
struct KittiRig {
  double scan_rate = 10;                               ///< Hz
  double mount_z = 1.73;                               ///< m, the Velodyne above the road
  std::vector<double> imu_to_velo{0.81, -0.32, 0.80};  ///< m, the Velodyne in the OXTS frame
};
/// `scan_rate`, `mount_z` and `imu_to_velo`, declared once.
const ParamTable<KittiRig>& kittiRigTable();

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
  /// The rig's `imu_to_velo` places the scanner in the OXTS unit's frame, its `mount_z` above
  /// the road.
  OxtsTrajectory(std::string oxts, const KittiRig& rig);
  mrpt::poses::CPose3D robotPose(long index);

 private:
  std::string oxts_;
  mrpt::poses::CPose3D robot_in_imu_, origin_inv_;
  double scale_ = 1;
  bool started_ = false;
};

}  // namespace pedtrack::kitti
