#pragma once
// KITTI tracking's text files: the labels (label_02/SSSS.txt) and results in the same layout
// (a tracker's, or a detector's boxes written so), one object a line. `pedtrack eval` scores
// them; the `detections` source replays them.
#include <string>
#include <vector>

#include "pedtrack/kitti_calib.h"

namespace pedtrack {

/// One line of a KITTI tracking label or results file.
struct KittiTrackRow {
  long frame = 0, id = -1;
  std::string type;  ///< lower case: pedestrian, person_sitting, dontcare, ...
  int truncated = 0, occluded = 0;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;  ///< the image box, px
  KittiCameraBox box;
  double score = -1;       ///< results: the 18th value (-1 when absent)
  bool has_score = false;  ///< the line had the 18th value (labels have none)
};

/// A label file (17 values a line) or a results file (17 or 18). Throws DataError naming the file
/// and line at fault.
std::vector<KittiTrackRow> readKittiTrackFile(const std::string& path);

}  // namespace pedtrack
