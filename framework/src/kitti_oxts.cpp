#include "pedtrack/kitti_oxts.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pedtrack/errors.h"

namespace pedtrack::kitti {
namespace fs = std::filesystem;

Oxts readOxts(const std::string& oxts, long index) {
  std::string file = oxts, line;
  long want = index;
  if (fs::is_directory(oxts)) {
    // KITTI raw names a scan's record like the scan: 10 digits.
    char name[32];
    std::snprintf(name, sizeof name, "%010ld.txt", index);
    file = (fs::path(oxts) / name).string();
    want = 0;
  }
  std::ifstream f(file);
  if (!f)
    throw DataError(file + ": cannot open (the OXTS record of scan " + std::to_string(index) + ")");
  for (long k = 0; k <= want; ++k)
    if (!std::getline(f, line))
      throw DataError(file + ": no line " + std::to_string(want + 1) +
                      " (the OXTS record of scan " + std::to_string(index) + ")");
  std::istringstream is(line);
  Oxts o;
  if (!(is >> o.lat >> o.lon >> o.alt >> o.roll >> o.pitch >> o.yaw) ||
      !std::isfinite(o.lat + o.lon + o.alt + o.roll + o.pitch + o.yaw))
    throw DataError(file + ": line " + std::to_string(want + 1) +
                    ": expected lat lon alt roll pitch yaw first (KITTI OXTS)");
  return o;
}

mrpt::poses::CPose3D oxtsPose(const Oxts& o, double scale) {
  constexpr double kEarthRadius = 6378137;  // m, as KITTI's devkit
  const double x = scale * o.lon * M_PI * kEarthRadius / 180;
  const double y = scale * kEarthRadius * std::log(std::tan((90 + o.lat) * M_PI / 360));
  return mrpt::poses::CPose3D(x, y, o.alt, o.yaw, o.pitch, o.roll);
}

const ParamTable<KittiRig>& kittiRigTable() {
  using P = KittiRig;
  static const auto t =
      ParamTable<P>()
          .real(&P::scan_rate, "scan_rate", "Hz", 0.1, 1000,
                "scans per second (KITTI: 10) where KITTI raw's timestamps.txt gives no times: "
                "scan n is at n / scan_rate s")
          .real(&P::mount_z, "mount_z", "m", 0, 10,
                "the scanner's height above the road (KITTI's HDL-64: 1.73 m); the robot frame "
                "is on the road under it")
          .vector(&P::imu_to_velo, "imu_to_velo", "m", 3, -10, 10,
                  "where the scanner is in the OXTS unit's frame (KITTI's Tr_imu_to_velo "
                  "inverted; its rotation, under 1 degree, is left out)");
  return t;
}

OxtsTrajectory::OxtsTrajectory(std::string oxts, const KittiRig& rig)
    : oxts_(std::move(oxts)),
      robot_in_imu_(rig.imu_to_velo.at(0), rig.imu_to_velo.at(1),
                    rig.imu_to_velo.at(2) - rig.mount_z, 0, 0, 0) {}

mrpt::poses::CPose3D OxtsTrajectory::robotPose(long index) {
  const Oxts o = readOxts(oxts_, index);
  // The first record fixes the projection's scale and the fixed frame's origin.
  if (!started_) scale_ = std::cos(o.lat * M_PI / 180);
  const mrpt::poses::CPose3D robot = oxtsPose(o, scale_) + robot_in_imu_;
  if (!started_) origin_inv_ = -robot;
  started_ = true;
  return origin_inv_ + robot;
}

}  // namespace pedtrack::kitti
