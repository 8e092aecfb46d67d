#pragma once
// ROS1 range messages as MRPT observations, and a group of them (several scanners on one robot)
// as one frame: the rules the bag source (`rosbag`) and the live source (`ros_topic`) share.
#include <geometry_msgs/PoseArray.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPose3D.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include <limits>
#include <string>
#include <vector>

#include "bag_poses.h"
#include "pedtrack/frame.h"

namespace pedtrack::rosbag_source {

/// A LaserScan as MRPT's 2D scan mounted at `mount` on the robot; null when it cannot be
/// converted. Valid returns are ROS's: finite and within [range_min, range_max].
mrpt::obs::CObservation2DRangeScan::Ptr scanToObservation(const sensor_msgs::LaserScan& scan,
                                                          const mrpt::poses::CPose3D& mount);
/// A PointCloud2 (x, y, z fields) as MRPT's point cloud observation; null without x, y, z.
mrpt::obs::CObservationPointCloud::Ptr cloudToObservation(const sensor_msgs::PointCloud2& cloud,
                                                          const mrpt::poses::CPose3D& mount);

/// A detector's geometry_msgs/PoseArray (people or legs in the sensor's frame) as a frame of
/// detections: each pose placed in the fixed frame through the robot pose and the sensor's
/// mount, its heading the quaternion's yaw, its score 1 (the message has none). Poses that are
/// not finite are skipped and counted in `skipped`.
void poseArrayToFrame(const geometry_msgs::PoseArray& poses, const mrpt::poses::CPose3D& robot,
                      const mrpt::poses::CPose3D& mount, bool robot_known, Frame& frame,
                      long& skipped);

/// One converted message with the poses it was taken at.
struct MountedObservation {
  mrpt::obs::CObservation::Ptr obs;
  std::string topic;
  double stamp = 0;                   ///< header stamp, UNIX s
  mrpt::poses::CPose3D robot, mount;  ///< the robot in the fixed frame, the sensor on the robot
  bool robot_known = false;           ///< robot from tf or odometry, not the identity by default
};

/// Fills `frame` from a group (not empty): the robot at the newest stamp, each observation's
/// sensorPose placing its scanner relative to that robot pose (its mount, composed with the
/// robot's motion since its own stamp), so the merged cloud is one consistent robot frame.
/// Returns the newest stamp. frame.t is left to FrameClock.
double assembleFrame(const std::vector<MountedObservation>& group, Frame& frame);

/// Stages divide by the time step: frame times never go back, even where stamps do (bag order,
/// a restarted bag, another publisher); they are held at the newest so far.
class FrameClock {
 public:
  /// The frame time for a frame stamped `stamp`; `first_back` is true the first time stamps go
  /// back (to warn once).
  double next(double stamp, bool& first_back);

 private:
  double last_ = -std::numeric_limits<double>::infinity();
  bool went_back_ = false;
};

/// ConfigError at `where` when a `mounts` entry names a topic not in `known` (`what` says what
/// the known topics are), with the closest one as a hint.
void checkMountTopics(const MountTable& mounts, const std::vector<std::string>& known,
                      const std::string& where, const std::string& what);

}  // namespace pedtrack::rosbag_source
