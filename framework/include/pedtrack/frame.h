#pragma once
// One time step of the pipeline: the observations a source produced and what each stage adds.
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace pedtrack {

/// A group of points (indices into Frame::cloud()) that a segmenter believes is one object.
struct Cluster {
  std::vector<std::uint32_t> indices;
  /// Segmenter-defined feature vector; its names are Frame::cluster_feature_names.
  std::vector<double> features;
  /// Where the object is, robot frame (m): the centroid of the points, or the centre of the
  /// shape the segmenter fitted (a leg circle's centre).
  double cx = 0, cy = 0, cz = 0;
  /// Axis-aligned bounding box of the points in the robot frame: sizes along x, y, z (m).
  double size_x = 0, size_y = 0, size_z = 0;
  /// Index of the cluster this one pairs with (the other leg of one person), -1 for none.
  int pair = -1;
};

/// What the stages decided about one point of Frame::cloud(). Stages only mark points; the
/// cloud itself is never copied or erased from, so every stage sees the same indices.
enum class PointLabel : std::uint8_t {
  Kept = 0,     ///< still in play for the next stage
  Ground = 1,   ///< removed as ground (a ground stage)
  Removed = 2,  ///< removed by a height band, region of interest or range limit
};

/// A ground plane in the robot frame: n·p + d = 0 with a unit normal n pointing up, so
/// height(p) = n·p + d is a point's signed height above the ground (m).
struct GroundPlane {
  bool valid = false;
  double nx = 0, ny = 0, nz = 1, d = 0;
  double height(double x, double y, double z) const { return nx * x + ny * y + nz * z + d; }
  /// height() when the plane is valid, else z itself (the robot frame's own height).
  double heightOrZ(double x, double y, double z) const { return valid ? height(x, y, z) : z; }
  /// Angle between this plane's normal and another's (rad).
  double angleTo(const GroundPlane& o) const;
};

/// An upright 3D box (a 3D detector's, KITTI's): where its bottom is and how big it is. Its
/// heading is the owner's yaw; `l` lies along it, `w` across. h = 0: no box known.
struct Box3 {
  double z = 0;                ///< m, height of the box's bottom in the robot frame
  double h = 0, w = 0, l = 0;  ///< m, height, width, length
  bool known() const { return h > 0; }
};

/// A cluster that a classifier scored, with the measurement a tracker consumes (fixed frame).
struct Detection {
  int cluster = -1;            ///< index into Frame::clusters, -1 when not from a cluster
  double score = 0;            ///< class score / quality Q, higher = more person-like
  double x = 0, y = 0;         ///< position (m, fixed frame)
  double yaw = 0;              ///< orientation (rad), when the shape gives one
  double alpha = 0, beta = 0;  ///< torso ellipse semi-axes (m), 0 when unknown
  Box3 box;                    ///< a 3D detector's box (h = 0: none); yaw is its heading
};

/// A tracked person as reported in tracks.csv (docs/outputs.md).
struct Track {
  long id = 0;
  double x = 0, y = 0;         ///< m, fixed frame
  double yaw = 0;              ///< rad
  double vx = 0, vy = 0;       ///< m/s, fixed frame
  double alpha = 0, beta = 0;  ///< torso semi-axes (m); written only when has_shape
  bool has_shape = false;
  Box3 box;  ///< the person's 3D box, smoothed over the detections that updated the track
  double cov_xx = 0, cov_xy = 0, cov_yy = 0;  ///< written only when has_cov
  bool has_cov = false;
  double score = 0;
  std::vector<double> model_probs;
  std::string status;  ///< e.g. "tentative", "confirmed", "coasting"
  /// Normalized innovation squared of this frame's update (consistency checks); NaN when the
  /// track was not updated or the tracker does not compute it.
  double nis = std::numeric_limits<double>::quiet_NaN();
  /// The cluster (index into Frame::clusters) of the detection that updated the track this
  /// frame, -1 when none did: links a track to clusters.csv and point_labels.bin.
  int cluster = -1;
};

/// A place on the ground plane of the fixed frame (m).
struct PlanarPoint {
  double x = 0, y = 0;
};

/// The points one observation contributed to Frame::cloud().
struct CloudSpan {
  std::size_t observation = 0;  ///< index into Frame::observations
  std::size_t first = 0;        ///< cloud index of its first point
  std::size_t count = 0;        ///< its points
};

/// A range sensor that contributed to a frame, and where it was.
struct SensorPose {
  std::string label;          ///< the observation's sensorLabel (a bag topic, a rawlog label)
  mrpt::poses::CPose3D pose;  ///< the sensor in the fixed frame, at its observation's time
};

struct Frame {
  std::size_t index = 0;  ///< 0-based position in the stream
  double t = 0;           ///< observation timestamp, UNIX seconds
  std::vector<mrpt::obs::CObservation::Ptr> observations;
  mrpt::poses::CPose3D robot_pose;  ///< robot (base) in the fixed/odometry frame
  /// The source knows the robot's motion (odometry, /tf, a simulator). False: robot_pose is the
  /// identity only because nothing said otherwise (a lone live sensor, a bag without poses),
  /// and a robot that moves makes the world move in the fixed frame.
  bool has_odometry = false;
  /// An odometry stage could not tell how the robot moved up to this frame (scan matching found
  /// too little to match, outdoors, or most of the view hidden) and the source gives no
  /// odometry: robot_pose is a guess, and what stands still in the world may move in the fixed
  /// frame. A tracker then learns nothing as static scene and judges no motion in that frame.
  /// False also when nothing could tell (no odometry stage): the robot is then taken as still.
  bool motion_unknown = false;
  mrpt::poses::CPose3D sensor_pose;  ///< first range sensor in the fixed frame
  /// Every range sensor that contributed to the frame, one entry per range observation, in
  /// observation order (several scanners merged into one frame, each with its own pose);
  /// sensor_pose stays the first one's for the stages that think in one sensor.
  std::vector<SensorPose> sensors;
  /// The ground under the robot, set by a ground stage (valid = false until one ran).
  GroundPlane ground;
  /// One label per point of cloud(), or empty while no stage has removed anything (every point
  /// Kept). A stage that removes points sizes it through labels(); later stages read isKept().
  std::vector<PointLabel> point_labels;
  std::vector<Cluster> clusters;
  /// Names of Cluster::features, set by the segmenter that made the clusters (shared, not copied
  /// per frame); null when the clusters carry no features.
  std::shared_ptr<const std::vector<std::string>> cluster_feature_names;
  /// Index of the feature called `name` in Cluster::features; -1 when the clusters carry none.
  int clusterFeatureIndex(const std::string& name) const;
  std::vector<Detection> detections;
  std::vector<Track> tracks;
  /// Where the people a tracker follows are (fixed frame; tentative ones included, as far as the
  /// tracker knows them): the pipeline hands every frame the last value a tracker wrote, and a
  /// tracker overwrites it after its step. Stages before the tracker read it as last frame's
  /// people: scan matching leaves their returns out, as people move and walls do not.
  std::vector<PlanarPoint> people;

  /// Points of every range observation, in the robot frame, built on first use and cached, so a
  /// pipeline that needs no points (replay, import) never pays for them.
  /// A frame at this one's index, time and poses (odometry flags and sensors too), with no
  /// observations and nothing a stage made: for the same scene observed another way (the
  /// observations resampled or thinned) and run through the stages again.
  Frame sameTimeAndPoses() const;

  const mrpt::maps::CSimplePointsMap& cloud() const;
  /// Which cloud points came from which observation, in cloud order (built with the cloud).
  const std::vector<CloudSpan>& cloudSpans() const;
  /// The (first) sensor's mounting pose on the robot: sensor_pose relative to robot_pose.
  mrpt::poses::CPose3D sensorMount() const { return sensor_pose - robot_pose; }

  /// point_labels, sized to cloud() with every point Kept on first use.
  std::vector<PointLabel>& labels();
  bool isKept(std::size_t i) const {
    return point_labels.empty() || point_labels[i] == PointLabel::Kept;
  }
  /// Height of point i above the ground plane when one is known, else its robot-frame z (m).
  double heightOf(std::size_t i) const;

 private:
  mutable std::shared_ptr<mrpt::maps::CSimplePointsMap> cloud_;
  mutable std::shared_ptr<std::vector<CloudSpan>> spans_;
};

/// True for the observation types a frame is built around (2D scans, Velodyne and rotating
/// scans, point clouds, 3D range scans).
bool isRangeObservation(const mrpt::obs::CObservation& obs);

}  // namespace pedtrack
