#include "ros_frames.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/ros1bridge/point_cloud2.h>

#include <algorithm>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/params.h"

namespace pedtrack::rosbag_source {

void poseArrayToFrame(const geometry_msgs::PoseArray& poses, const mrpt::poses::CPose3D& robot,
                      const mrpt::poses::CPose3D& mount, bool robot_known, Frame& frame,
                      long& skipped) {
  frame.robot_pose = robot;
  frame.has_odometry = robot_known;
  frame.sensor_pose = robot + mount;
  for (const auto& p : poses.poses) {
    const auto& q = p.orientation;
    const double x = p.position.x, y = p.position.y, z = p.position.z;
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) ||
        !std::isfinite(q.x + q.y + q.z + q.w)) {
      ++skipped;
      continue;
    }
    Detection d;
    double fz = 0;
    frame.sensor_pose.composePoint(x, y, z, d.x, d.y, fz);
    // The quaternion's yaw, its scale cancelling (a zero one, no heading given, is yaw 0).
    const double yaw =
        std::atan2(2 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);
    d.yaw = std::remainder(frame.sensor_pose.yaw() + yaw, 2 * M_PI);
    d.score = 1;
    frame.detections.push_back(d);
  }
}

mrpt::obs::CObservation2DRangeScan::Ptr scanToObservation(const sensor_msgs::LaserScan& scan,
                                                          const mrpt::poses::CPose3D& mount) {
  // Written here rather than with mrpt::ros1bridge::fromROS (MRPT 2.5.8): MRPT's scan spans
  // [-aperture/2, aperture/2] about the sensor's x axis, and fromROS fits a scan that is not
  // symmetric about it (a Hokuyo's [-34.5 deg, 51.3 deg] in leg_tracker's benchmark) by shifting
  // the beams and wrapping the ones that fall off one end round to the other: returns from the
  // left end appeared on the right, and the validity this function set by ROS index no longer
  // matched the ranges (the benchmark's followed person lost in a third of the scans). Here the
  // scan is padded with invalid beams to be symmetric, and the part of a beam step that padding
  // cannot absorb turns the beams (the observation's sensorPose, on top of `mount`).
  const std::size_t n = scan.ranges.size();
  double inc = scan.angle_increment;
  if (n < 2 || !std::isfinite(scan.angle_min) || !std::isfinite(inc) || inc == 0) return nullptr;
  std::vector<float> ranges(scan.ranges.begin(), scan.ranges.end());
  double lo = scan.angle_min;
  if (inc < 0) {  // clockwise beams: the same scan counter-clockwise
    std::reverse(ranges.begin(), ranges.end());
    lo = scan.angle_min + double(n - 1) * inc;
    inc = -inc;
  }
  const double hi = lo + double(n - 1) * inc;
  if (hi - lo > 2 * M_PI + inc) return nullptr;
  // Invalid beams below lo (pad_lo) or above hi (pad_hi) centre the scan on the x axis.
  const long shift = std::lround((hi + lo) / inc);
  const std::size_t pad_lo = shift > 0 ? std::size_t(shift) : 0;
  const std::size_t pad_hi = shift < 0 ? std::size_t(-shift) : 0;
  const std::size_t total = n + pad_lo + pad_hi;
  auto o = mrpt::obs::CObservation2DRangeScan::Create();
  o->rightToLeft = true;
  o->aperture = float(double(total - 1) * inc);
  o->maxRange = scan.range_max;
  o->sensorLabel = scan.header.frame_id;
  o->resizeScan(total);
  for (std::size_t j = 0; j < total; ++j) {  // beam j is ROS beam j - pad_lo, or padding
    const float r = j >= pad_lo && j < pad_lo + n ? ranges[j - pad_lo] : NAN;
    const bool valid = std::isfinite(r) && r >= scan.range_min && r <= scan.range_max;
    o->setScanRange(j, valid ? r : 0);
    o->setScanRangeValidity(j, valid);
  }
  // ROS beam k is at lo + k·inc; MRPT's beam pad_lo + k at -aperture/2 + (pad_lo + k)·inc.
  const double turn = lo + 0.5 * double(o->aperture) - double(pad_lo) * inc;
  o->sensorPose = mount + mrpt::poses::CPose3D(0, 0, 0, turn, 0, 0);
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
    // How the observation's own axes sit on its sensor's (a scan's beams turned by a fraction of
    // a step: scanToObservation); the identity for most.
    mrpt::poses::CPose3D own;
    m.obs->getSensorPose(own);
    const mrpt::poses::CPose3D axes = own - m.mount;
    m.obs->setSensorPose((&m == &newest ? m.mount : in_fixed - frame.robot_pose) + axes);
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
