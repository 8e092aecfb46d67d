#pragma once
// The detection files the `detections` source replays: a 3D detector's output in KITTI's camera
// frame (AB3DMOT's comma-separated files, or KITTI tracking label / results lines), and pedtrack's
// own detections.csv. Private to the `detections` source.
#include <map>
#include <string>
#include <vector>

#include "pedtrack/frame.h"
#include "pedtrack/kitti_tracking_file.h"

namespace pedtrack::detections {

/// One detection of a KITTI file: its class, box (camera frame) and the detector's score.
struct KittiDetection {
  std::string type;  ///< Pedestrian, Car, ... (AB3DMOT's 1, 2, 3; tracking files': lower case)
  KittiCameraBox box;
  double score = 1;  ///< label lines, which have none: 1
};

/// A KITTI detection file, by frame: AB3DMOT's lines `frame,type,x1,y1,x2,y2,score,h,w,l,x,y,z,
/// rotation_y,alpha` (comma separated; type 1 pedestrian, 2 car, 3 cyclist), or, when its first
/// line has no comma, a KITTI tracking label / results file (readKittiTrackFile; a line without
/// a score scores 1). DontCare lines are left out. Throws DataError naming the file and line
/// (or frame) at fault.
std::map<long, std::vector<KittiDetection>> readKittiDetections(const std::string& path);

/// One frame of a detections.csv: its time and detections (fixed frame).
struct CsvFrame {
  double t = 0;
  std::vector<Detection> detections;
};

/// pedtrack's detections.csv (docs/outputs.md), by its `frame` column; the box columns z,h,w,l
/// are read when present. Frame numbers missing between two present ones (frames without
/// detections) come back empty, their times interpolated. Throws DataError naming the file and
/// line at fault (a tracks.csv is refused).
std::map<long, CsvFrame> readDetectionsCsv(const std::string& path);

}  // namespace pedtrack::detections
