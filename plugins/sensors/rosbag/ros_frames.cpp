#include "ros_frames.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/point_cloud2.h>

#include <algorithm>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/params.h"

namespace pedtrack::rosbag_source {

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

double assembleFrame(const std::vector<MountedObservation>& group, Frame& frame) {
  const MountedObservation& newest = *std::max_element(
      group.begin(), group.end(),
      [](const MountedObservation& a, const MountedObservation& b) { return a.stamp < b.stamp; });
  frame.robot_pose = newest.robot;
  frame.has_odometry = newest.robot_known;
  for (const MountedObservation& m : group) {
    const mrpt::poses::CPose3D in_fixed = m.robot + m.mount;
    m.obs->setSensorPose(&m == &newest ? m.mount : in_fixed - frame.robot_pose);
    frame.observations.push_back(m.obs);
    frame.sensors.push_back({m.topic, in_fixed});
  }
  frame.sensor_pose = frame.sensors.front().pose;
  return newest.stamp;
}

double FrameClock::next(double stamp, bool& first_back) {
  first_back = stamp < last_ && !went_back_;
  went_back_ = went_back_ || first_back;
  last_ = std::max(last_, stamp);
  return last_;
}

void checkMountTopics(const MountTable& mounts, const std::vector<std::string>& known,
                      const std::string& where, const std::string& what) {
  for (const auto& [topic, pose] : mounts) {
    if (std::find(known.begin(), known.end(), topic) != known.end()) continue;
    const std::string hint = closestMatch(topic, known);
    throw ConfigError(where + ": topic '" + topic + "' is not " + what +
                      (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
}

}  // namespace pedtrack::rosbag_source
