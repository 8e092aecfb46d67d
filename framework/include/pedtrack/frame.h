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
  std::vector<double> features;   ///< segmenter- or classifier-defined feature vector
  double cx = 0, cy = 0, cz = 0;  ///< centroid, robot frame (m)
};

/// A cluster that a classifier scored, with the measurement a tracker consumes (fixed frame).
struct Detection {
  int cluster = -1;            ///< index into Frame::clusters, -1 when not from a cluster
  double score = 0;            ///< class score / quality Q, higher = more person-like
  double x = 0, y = 0;         ///< position (m, fixed frame)
  double yaw = 0;              ///< orientation (rad), when the shape gives one
  double alpha = 0, beta = 0;  ///< torso ellipse semi-axes (m), 0 when unknown
};

/// A tracked person as reported in tracks.csv (see DESIGN.md "Outputs").
struct Track {
  long id = 0;
  double x = 0, y = 0;         ///< m, fixed frame
  double yaw = 0;              ///< rad
  double vx = 0, vy = 0;       ///< m/s, fixed frame
  double alpha = 0, beta = 0;  ///< torso semi-axes (m); written only when has_shape
  bool has_shape = false;
  double cov_xx = 0, cov_xy = 0, cov_yy = 0;  ///< written only when has_cov
  bool has_cov = false;
  double score = 0;
  std::vector<double> model_probs;
  std::string status;  ///< e.g. "tentative", "confirmed", "coasting"
  /// Normalized innovation squared of this frame's update (consistency checks); NaN when the
  /// track was not updated or the tracker does not compute it.
  double nis = std::numeric_limits<double>::quiet_NaN();
};

struct Frame {
  std::size_t index = 0;  ///< 0-based position in the stream
  double t = 0;           ///< observation timestamp, UNIX seconds
  std::vector<mrpt::obs::CObservation::Ptr> observations;
  mrpt::poses::CPose3D robot_pose;   ///< robot (base) in the fixed/odometry frame
  mrpt::poses::CPose3D sensor_pose;  ///< first range sensor in the fixed frame
  std::vector<Cluster> clusters;
  std::vector<Detection> detections;
  std::vector<Track> tracks;

  /// Points of every range observation, in the robot frame, built on first use and cached, so a
  /// pipeline that needs no points (replay, import) never pays for them.
  const mrpt::maps::CSimplePointsMap& cloud() const;

 private:
  mutable std::shared_ptr<mrpt::maps::CSimplePointsMap> cloud_;
};

/// True for the observation types a frame is built around (2D scans, Velodyne and rotating
/// scans, point clouds, 3D range scans).
bool isRangeObservation(const mrpt::obs::CObservation& obs);

}  // namespace pedtrack
