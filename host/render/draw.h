#pragma once
// The layers of a picture, each drawn by one function onto a BGR image. Colours come from
// palette.h; positions are fixed-frame metres mapped through a View.
#include <mrpt/poses/CPose3D.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pedtrack/eval/object_table.h"
#include "pedtrack/frame.h"
#include "pedtrack/point_labels.h"
#include "view.h"

namespace pedtrack::render {

// ---- map: draw_map.cpp ----------------------------------------------------------------------
/// Metric grid (a line every metre, or coarser when lines would crowd) with labelled major lines.
void drawGrid(cv::Mat& img, const View& view);
/// A bar of a round length with its label, top right.
void drawScaleBar(cv::Mat& img, const View& view);

struct PointCounts {
  std::size_t ground = 0, other = 0;
  std::size_t removed = 0, clustered = 0;  ///< with run labels
};
/// The frame's cloud in the fixed frame. Without labels: points lower than `ground_z` in the
/// robot frame grey, the others light blue (2D scans are horizontal slices: never ground). With
/// a run's labels: ground grey, removed dim red, unclustered light blue, each cluster its own
/// colour; with truth labels: ground grey, objects light blue, each person its own colour.
PointCounts drawPoints(cv::Mat& img, const View& view, const Frame& frame, double ground_z,
                       const LabelFrame* labels = nullptr, LabelKind kind = LabelKind::Run);
/// The sensor as a triangle pointing along its heading.
void drawSensor(cv::Mat& img, const View& view, const mrpt::poses::CPose3D& sensor_pose);
/// A thin polyline through fixed-frame points (the sensor's path).
void drawPolyline(cv::Mat& img, const View& view, const std::vector<cv::Point2d>& path,
                  const cv::Scalar& color, int thickness);

// ---- objects: draw_objects.cpp --------------------------------------------------------------
/// A track's 95 % covariance ellipse, torso ellipse (or a 0.25 m circle) and 1 s velocity arrow.
void drawTrackBody(cv::Mat& img, const View& view, const ObjectRow& track);
/// A track's centre dot and id label; drawn after every body so no other layer hides them.
void drawTrackMarker(cv::Mat& img, const View& view, const ObjectRow& track);
/// A true person: thin torso outline, leg circles when known, small id label.
void drawTruth(cv::Mat& img, const View& view, const ObjectRow& truth);
/// A detection: a tilted cross.
void drawDetection(cv::Mat& img, const View& view, const ObjectRow& detection, int size_px = 0);
/// A detection's score beside its cross: bright from `person_score` on (called a person), dim
/// below.
void drawDetectionScore(cv::Mat& img, const View& view, const ObjectRow& detection,
                        double person_score);

/// A labelled object's box (fixed frame): its footprint, `yaw` along its length, and its name.
struct LabelBox {
  double x = 0, y = 0, yaw = 0, l = 0, w = 0;
  std::string name;
  bool person = false;  ///< drawn in the truth colour; other objects in the box colour
};
void drawLabelBox(cv::Mat& img, const View& view, const LabelBox& box);

enum class LineStyle { Solid, Dashed };
/// An object's path through its rows (time order).
void drawPath(cv::Mat& img, const View& view, const std::vector<const ObjectRow*>& path,
              const cv::Scalar& color, int thickness, LineStyle style);
/// Start (hollow circle) and end (filled dot) markers of a path.
void drawPathEnds(cv::Mat& img, const View& view, const std::vector<const ObjectRow*>& path,
                  const cv::Scalar& color, int radius_px);

// ---- text: draw_text.cpp --------------------------------------------------------------------
/// Text with a dark outline, legible on points and grid alike. `origin` is the baseline start.
void drawText(cv::Mat& img, const std::string& text, cv::Point origin, const cv::Scalar& color,
              double scale = 0.45);
/// Lines of text on a panel in the top-left corner.
void drawInfoPanel(cv::Mat& img, const std::vector<std::string>& lines);
/// How points are coloured, for the legend.
enum class PointColours { ByHeight, RunLabels, TruthLabels };

/// What each mark means, bottom left, or with `pick_corner` in the bottom corner that hides less
/// of the picture (not in videos, where a legend jumping between corners distracts). `overlay`
/// adds the path markers.
/// `with_scores` names the detections' scores, `with_boxes` the labelled boxes' colours.
void drawLegend(cv::Mat& img, bool overlay, bool with_truth, bool with_detections, bool pick_corner,
                PointColours points = PointColours::ByHeight, bool with_scores = false,
                bool with_boxes = false);

}  // namespace pedtrack::render
