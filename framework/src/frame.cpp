#include "pedtrack/frame.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <algorithm>
#include <cmath>

#include "pedtrack/velodyne_decode.h"

namespace pedtrack {

bool isRangeObservation(const mrpt::obs::CObservation& obs) {
  using namespace mrpt::obs;
  return IS_CLASS(obs, CObservation2DRangeScan) || IS_CLASS(obs, CObservationVelodyneScan) ||
         IS_CLASS(obs, CObservationRotatingScan) || IS_CLASS(obs, CObservationPointCloud) ||
         IS_CLASS(obs, CObservation3DRangeScan);
}

Frame Frame::sameTimeAndPoses() const {
  Frame g;
  g.index = index;
  g.t = t;
  g.robot_pose = robot_pose;
  g.has_odometry = has_odometry;
  g.motion_unknown = motion_unknown;
  g.sensor_pose = sensor_pose;
  g.sensors = sensors;
  return g;
}

const mrpt::maps::CSimplePointsMap& Frame::cloud() const {
  if (cloud_) return *cloud_;
  auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
  // Keep every return: MRPT's default decimates laser points closer than 2 cm, which would
  // thin out exactly the dense leg and torso returns people produce.
  map->insertionOptions.minDistBetweenLaserPoints = 0;
  map->insertionOptions.also_interpolate = false;
  map->insertionOptions.isPlanarMap = false;
  auto spans = std::make_shared<std::vector<CloudSpan>>();
  for (std::size_t k = 0; k < observations.size(); ++k) {
    const auto& obs = observations[k];
    if (!obs || !isRangeObservation(*obs)) continue;
    const std::size_t before = map->size();
    auto velo = std::dynamic_pointer_cast<mrpt::obs::CObservationVelodyneScan>(obs);
    if (velo && velo->calibration.laser_corrections.size() == 16) {
      // Both firings of every VLP-16 block (see velodyne_decode.h), mounted on the robot; MRPT
      // decodes the 32- and 64-laser models completely itself.
      for (const auto& p : decodeVelodyne(*velo)) {
        double x, y, z;
        velo->sensorPose.composePoint(p.x, p.y, p.z, x, y, z);
        map->insertPointFast(x, y, z);
      }
    } else {
      map->insertObservation(*obs);
    }
    spans->push_back({k, before, map->size() - before});
  }
  map->mark_as_modified();
  spans_ = std::move(spans);
  cloud_ = std::move(map);
  return *cloud_;
}

const std::vector<CloudSpan>& Frame::cloudSpans() const {
  cloud();
  return *spans_;
}

int Frame::clusterFeatureIndex(const std::string& name) const {
  if (!cluster_feature_names) return -1;
  const auto& names = *cluster_feature_names;
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

std::vector<PointLabel>& Frame::labels() {
  const std::size_t n = cloud().size();
  if (point_labels.size() != n) point_labels.assign(n, PointLabel::Kept);
  return point_labels;
}

double Frame::heightOf(std::size_t i) const {
  const auto& c = cloud();
  const double x = c.getPointsBufferRef_x()[i], y = c.getPointsBufferRef_y()[i],
               z = c.getPointsBufferRef_z()[i];
  return ground.heightOrZ(x, y, z);
}

double GroundPlane::angleTo(const GroundPlane& o) const {
  const double dot = nx * o.nx + ny * o.ny + nz * o.nz;
  const double n1 = std::sqrt(nx * nx + ny * ny + nz * nz),
               n2 = std::sqrt(o.nx * o.nx + o.ny * o.ny + o.nz * o.nz);
  return std::acos(std::clamp(dot / (n1 * n2), -1.0, 1.0));
}

}  // namespace pedtrack
