#pragma once
// KITTI's object labels (object benchmark `label_2/NNNNNN.txt`, tracking benchmark
// `label_02/SSSS.txt`) and the calibration that turns their camera-frame boxes into the
// Velodyne's frame, where a pipeline run on the scans (the `kitti` source) reports its objects.
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "pedtrack/kitti_calib.h"

namespace pedtrack::eval {

using pedtrack::KittiCalib;
using pedtrack::readKittiCalib;

/// One labelled object, its box in the Velodyne frame.
struct KittiObject {
  long frame = -1;   ///< tracking labels: the frame; object labels: the file's number
  long track = -1;   ///< tracking labels: the track id (-1 DontCare); object labels: -1
  std::string type;  ///< Pedestrian, Person_sitting, Cyclist, Car, Van, Truck, Misc, DontCare...
  int occluded = 0;  ///< 0 visible ... 3 unknown
  double truncated = 0;
  double h = 0, w = 0, l = 0;  ///< m, box height, width, length
  double x = 0, y = 0, z = 0;  ///< m, the box's bottom centre, Velodyne frame
  double yaw = 0;              ///< rad, the box's length axis about the Velodyne's z
  bool person() const { return type == "Pedestrian" || type == "Person_sitting"; }
  bool dontCare() const { return type == "DontCare"; }
  /// Whether (px, py) lies inside the box's footprint grown by `margin` on every side.
  bool contains(double px, double py, double margin) const;
};

/// An object benchmark label file (15 values a line: type truncated occluded alpha bbox(4)
/// h w l x y z rotation_y). DontCare areas are kept (their boxes have no 3D extent).
/// Throws DataError naming the file and line.
std::vector<KittiObject> readKittiObjectLabels(const std::string& path, const KittiCalib& calib,
                                               long frame);

/// A tracking benchmark label file (17 values a line: frame track_id type ...).
std::vector<KittiObject> readKittiTrackingLabels(const std::string& path, const KittiCalib& calib);

/// An object benchmark folder's labels (DIR/label_2/NNNNNN.txt), each turned into the Velodyne
/// frame by its DIR/calib/NNNNNN.txt: per scan number, its calibration and objects. Throws
/// DataError naming a missing folder or file.
struct KittiScanLabels {
  KittiCalib calib;
  std::vector<KittiObject> objects;
};
std::map<long, KittiScanLabels> readKittiObjectDir(const std::string& dir);

}  // namespace pedtrack::eval

namespace pedtrack::eval {

/// A cluster a run called a person (its detection scored at least the threshold), in the
/// Velodyne frame, and the labelled object it lies on (-1: none).
struct KittiCalled {
  long cluster = -1;
  double x = 0, y = 0, score = 0;
  bool in_view = false;  ///< inside the camera's field of view (KittiCalib::inCameraView)
  int object = -1;       ///< index into the frame's objects
};

/// One scan's labelled objects against the clusters called persons.
struct KittiFrameMatch {
  long frame = -1;
  std::vector<KittiObject> objects;
  /// Per object: the called cluster on it with the highest score (index into `called`), -1 none.
  std::vector<int> detected_by;
  std::vector<KittiCalled> called;
};

/// Which labelled object each called cluster lies on (inside its footprint grown by `margin`; a
/// person's box first), and which object each was found on. DontCare areas have no 3D box and
/// take nothing.
KittiFrameMatch matchKittiFrame(long frame, std::vector<KittiObject> objects,
                                const KittiCalib& calib, std::vector<KittiCalled> called,
                                double margin);

}  // namespace pedtrack::eval
