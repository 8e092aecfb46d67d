#pragma once
// Every colour of a rendering, in one place (OpenCV BGR order). Tracks get a colour per id from a
// fixed palette, so the same id has the same colour in every picture and video of a run. The
// palette avoids the greys and light blue of points, the green of truth and the yellow of
// detections, so no layer can be mistaken for another.
#include <opencv2/core.hpp>

namespace pedtrack::render {

namespace colors {
inline const cv::Scalar kBackground(28, 24, 22);
inline const cv::Scalar kGridMinor(52, 48, 46);
inline const cv::Scalar kGridMajor(84, 80, 78);
inline const cv::Scalar kGridLabel(150, 145, 140);
inline const cv::Scalar kGround(120, 120, 120);  ///< points below --ground-z
inline const cv::Scalar kPoint(255, 235, 205);   ///< other points: white with a blue tint
inline const cv::Scalar kRemoved(70, 60, 150);   ///< points a band or region stage removed
inline const cv::Scalar kSensor(255, 255, 255);  ///< sensor triangle (outlined in kOutline)
inline const cv::Scalar kSensorPath(150, 150, 150);
inline const cv::Scalar kTruth(80, 230, 80);       ///< ground truth outlines and paths
inline const cv::Scalar kDetection(40, 225, 255);  ///< detection crosses
inline const cv::Scalar kDimText(150, 150, 150);   ///< scores of clusters not called persons
inline const cv::Scalar kLabelBox(255, 190, 90);   ///< labelled objects that are not people
inline const cv::Scalar kText(235, 235, 235);
inline const cv::Scalar kOutline(0, 0, 0);   ///< behind text and markers, for contrast
inline const cv::Scalar kPanel(45, 40, 38);  ///< legend and info panel fill
}  // namespace colors

/// The colour of track `id` (any integer, negative ones too).
cv::Scalar trackColor(long id);
/// Number of distinct track colours before they repeat.
int trackPaletteSize();
/// The colour of the points of cluster (or true person) `id`: hues spread by the golden angle,
/// skipping the yellow–green band of detections and truth.
cv::Scalar clusterColor(long id);

}  // namespace pedtrack::render
