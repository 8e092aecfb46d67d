#pragma once
// A frame's tracks as ROS messages. Debian has no people_msgs, so the tracks go out as:
//  - geometry_msgs/PoseArray: one pose per track (position, orientation from yaw);
//  - sensor_msgs/PointCloud2 "people": one point per track, in the PoseArray's order, with the
//    fields x y z id vx vy yaw alpha beta cov_xx cov_xy cov_yy score status (see
//    kPeopleFields); a machine-readable array any ROS tool can read, and rviz can show;
//  - visualization_msgs/MarkerArray for rviz: torso ellipses, ids, velocity arrows, covariance
//    ellipses, the followed person.
#include <geometry_msgs/PoseArray.h>
#include <mrpt/poses/CPose3D.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::ros_plugins {

/// A track expressed in the published frame.
struct OutTrack {
  const Track* track = nullptr;  ///< id, status, score and shape (frame-independent)
  double x = 0, y = 0, z = 0, yaw = 0, vx = 0, vy = 0;
  double cov_xx = 0, cov_xy = 0, cov_yy = 0;
};

/// `tracks` (fixed frame) expressed in the frame whose pose in the fixed frame is `frame`:
/// positions in 3D, velocities, yaw and covariance rotated about the vertical (the robot and
/// sensor frames are taken as level).
std::vector<OutTrack> expressIn(const std::vector<Track>& tracks,
                                const mrpt::poses::CPose3D& frame);

/// The people cloud's status codes (field `status`, uint8).
enum class StatusCode : std::uint8_t {
  Tentative = 0,
  Confirmed = 1,
  Coasting = 2,
  Following = 3,
  Other = 255,
};
StatusCode statusCode(const std::string& status);

geometry_msgs::PoseArray toPoseArray(const std::vector<OutTrack>& tracks,
                                     const std::string& frame_id, const ros::Time& stamp);
sensor_msgs::PointCloud2 toPeopleCloud(const std::vector<OutTrack>& tracks,
                                       const std::string& frame_id, const ros::Time& stamp);

struct MarkerStyle {
  double person_height = 1.7;  ///< m, height of the torso columns
  double arrow_seconds = 1.0;  ///< velocity arrows show where the person is in this time
};
/// Starts with a DELETEALL, so tracks that ended vanish from rviz.
visualization_msgs::MarkerArray toMarkers(const std::vector<OutTrack>& tracks,
                                          const std::string& frame_id, const ros::Time& stamp,
                                          const MarkerStyle& style);

}  // namespace pedtrack::ros_plugins
