#include "pedtrack/frame.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include "pedtrack/velodyne_decode.h"

namespace pedtrack {

bool isRangeObservation(const mrpt::obs::CObservation& obs) {
  using namespace mrpt::obs;
  return IS_CLASS(obs, CObservation2DRangeScan) || IS_CLASS(obs, CObservationVelodyneScan) ||
         IS_CLASS(obs, CObservationRotatingScan) || IS_CLASS(obs, CObservationPointCloud) ||
         IS_CLASS(obs, CObservation3DRangeScan);
}

const mrpt::maps::CSimplePointsMap& Frame::cloud() const {
  if (cloud_) return *cloud_;
  auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
  // Keep every return: MRPT's default decimates laser points closer than 2 cm, which would
  // thin out exactly the dense leg and torso returns people produce.
  map->insertionOptions.minDistBetweenLaserPoints = 0;
  map->insertionOptions.also_interpolate = false;
  map->insertionOptions.isPlanarMap = false;
  for (const auto& obs : observations) {
    if (!obs || !isRangeObservation(*obs)) continue;
    auto velo = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(obs);
    if (velo && velo->calibration.laser_corrections.size() == 16) {
      // Both firings of every VLP-16 block (see velodyne_decode.h), mounted on the robot; MRPT
      // decodes the 32- and 64-laser models completely itself.
      for (const auto& p : decodeVelodyne(*velo)) {
        double x, y, z;
        velo->sensorPose.composePoint(p.x, p.y, p.z, x, y, z);
        map->insertPointFast(x, y, z);
      }
      continue;
    }
    map->insertObservation(*obs);
  }
  map->mark_as_modified();
  cloud_ = std::move(map);
  return *cloud_;
}

}  // namespace pedtrack
