#pragma once
// kitti_tracks.txt: a run's tracks in KITTI's tracking results format, so KITTI's evaluation
// tools (and AB3DMOT's) read them unchanged. Private to the `detections` source.
#include <fstream>
#include <string>

#include "pedtrack/frame.h"
#include "pedtrack/kitti_calib.h"

namespace pedtrack::detections {

/// The box written for a track that carries none (KITTI's mean pedestrian, m).
struct DefaultBox {
  double h = 1.76, w = 0.66, l = 0.84;
};

class KittiTracksWriter {
 public:
  /// `mount_z`: the Velodyne above the robot frame's origin (the road); `type`: the class written.
  KittiTracksWriter(const std::string& path, const KittiCalib& calib, double mount_z,
                    std::string type);
  /// One line per track of `f` the camera sees (others are counted, outOfView()): `frame track_id
  /// type 0 0 alpha x1 y1 x2 y2 h w l x y z rotation_y score` (camera frame; the image box is the
  /// 3D box projected by P2).
  void write(long kitti_frame, const Frame& f);
  void close();
  std::size_t outOfView() const { return out_of_view_; }

 private:
  std::ofstream out_;
  std::string path_;
  KittiCalib calib_;
  double mount_z_;
  std::string type_;
  DefaultBox default_;
  std::size_t out_of_view_ = 0;
};

}  // namespace pedtrack::detections
