#pragma once
// Composes whole pictures from the layers: one frame (a PNG, or one video frame) or the
// trajectory overlay of a whole run.
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "draw.h"
#include "label_source.h"
#include "object_index.h"
#include "pedtrack/frame.h"
#include "view.h"

namespace pedtrack::render {

/// Everything a picture shows besides the frame itself.
struct Scene {
  View view;
  const ObjectIndex* tracks = nullptr;      ///< never null
  const ObjectIndex* truth = nullptr;       ///< null without --truth
  const ObjectIndex* detections = nullptr;  ///< null without --detections
  std::vector<cv::Point2d> sensor_path;     ///< sensor position of every frame, by index
  double t_first = 0;                       ///< time of the first frame (elapsed time origin)
  double ground_z = 0.15;                   ///< m, robot frame: lower points are ground
  double trail_s = 2;                       ///< s of track and truth history behind each frame
  bool video = false;                       ///< frames of a video: keep every mark in place
  LabelSource* labels = nullptr;            ///< per-point labels (--labels / --run), or null
  /// Write each detection's score beside it (--scores); from person_score on it is a person's.
  bool scores = false;
  double person_score = 0.5;
  /// Labelled objects of a frame (--kitti), fixed frame; empty when none.
  std::function<std::vector<LabelBox>(const Frame&)> boxes;
};

/// One frame: points, sensor, the rows of the frame's tracks, truth and detections, and the
/// last `trail_s` seconds of every track and true path.
cv::Mat renderFrame(const Scene& scene, const Frame& frame);
/// The whole run: `last`'s points, the sensor's path, every track's and true person's full path
/// with start and end markers, every detection.
cv::Mat renderOverlay(const Scene& scene, const Frame& last);

}  // namespace pedtrack::render
