#include "ros_convert.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/point_cloud2.h>

#include <cmath>

namespace pedtrack::ros_plugins {

mrpt::obs::CObservation2DRangeScan::Ptr scanToObservation(const sensor_msgs::LaserScan& scan,
                                                          const mrpt::poses::CPose3D& mount) {
  auto o = mrpt::obs::CObservation2DRangeScan::Create();
  if (!mrpt::ros1bridge::fromROS(scan, mount, *o)) return nullptr;
  // mrpt::ros1bridge drops returns beyond 95% of range_max; ROS defines a return as valid
  // anywhere in [range_min, range_max], and a person at 5.4 m of a 5.6 m scanner is real.
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const float r = scan.ranges[k];
    o->setScanRangeValidity(k, std::isfinite(r) && r >= scan.range_min && r <= scan.range_max);
  }
  return o;
}

mrpt::obs::CObservationPointCloud::Ptr cloudToObservation(const sensor_msgs::PointCloud2& cloud,
                                                          const mrpt::poses::CPose3D& mount) {
  auto o = mrpt::obs::CObservationPointCloud::Create();
  auto pts = mrpt::maps::CSimplePointsMap::Create();
  if (!mrpt::ros1bridge::fromROS(cloud, *pts)) return nullptr;
  o->pointcloud = pts;
  o->sensorPose = mount;
  return o;
}

}  // namespace pedtrack::ros_plugins
