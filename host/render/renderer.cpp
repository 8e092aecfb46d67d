#include "renderer.h"

#include <mrpt/core/format.h>

#include <string>

#include "draw.h"
#include "palette.h"

namespace pedtrack::render {
namespace {

using mrpt::format;

cv::Mat background(const Scene& s) {
  cv::Mat img(s.view.size, s.view.size, CV_8UC3, colors::kBackground);
  drawGrid(img, s.view);
  return img;
}

void finish(cv::Mat& img, const Scene& s, const std::vector<std::string>& info, bool overlay) {
  drawInfoPanel(img, info);
  drawScaleBar(img, s.view);
  const PointColours colours = !s.labels                            ? PointColours::ByHeight
                               : s.labels->kind() == LabelKind::Run ? PointColours::RunLabels
                                                                    : PointColours::TruthLabels;
  drawLegend(img, overlay, s.truth != nullptr, s.detections != nullptr, !s.video, colours,
             s.scores && s.detections, bool(s.boxes));
}

// The frame's points, coloured by the label file when it has this frame.
PointCounts points(cv::Mat& img, const Scene& s, const Frame& frame) {
  const LabelFrame* labels = s.labels ? s.labels->at(frame.index, frame.cloud().size()) : nullptr;
  return drawPoints(img, s.view, frame, s.ground_z, labels,
                    s.labels ? s.labels->kind() : LabelKind::Run);
}

// "points N (ground G, ...)" for the info panel.
std::string pointsLine(const PointCounts& p) {
  std::string o = "points " + std::to_string(p.ground + p.other + p.removed + p.clustered) +
                  " (ground " + std::to_string(p.ground);
  if (p.removed) o += ", removed " + std::to_string(p.removed);
  if (p.clustered) o += ", clustered " + std::to_string(p.clustered);
  return o + ")";
}

/// Paths of every object of `index` over [t0, t1] of the table's own clock.
void drawTrails(cv::Mat& img, const View& view, const ObjectIndex& index, double t0, double t1,
                bool truth) {
  for (const auto& [id, path] : index.paths()) {
    const auto trail = ObjectIndex::window(path, t0, t1);
    if (truth)
      drawPath(img, view, trail, colors::kTruth, 1, LineStyle::Dashed);
    else
      drawPath(img, view, trail, trackColor(id), 2, LineStyle::Solid);
  }
}

}  // namespace

cv::Mat renderFrame(const Scene& s, const Frame& frame) {
  cv::Mat img = background(s);
  const std::size_t upto = std::min(frame.index + 1, s.sensor_path.size());
  drawPolyline(img, s.view, {s.sensor_path.begin(), s.sensor_path.begin() + upto},
               colors::kSensorPath, 1);
  const PointCounts counts = points(img, s, frame);

  const long index = static_cast<long>(frame.index);
  const FrameRows tracks = s.tracks->at(frame.t, index);
  FrameRows truth, detections;
  if (s.truth) truth = s.truth->at(frame.t, index);
  if (s.detections) detections = s.detections->at(frame.t, index);

  // Trails end at the table's own time for this frame (simulated clocks need not match the
  // rawlog's), or at the frame's time when the table has no row here.
  if (s.trail_s > 0) {
    if (s.truth) {
      const double t = std::isnan(truth.t) ? frame.t : truth.t;
      drawTrails(img, s.view, *s.truth, t - s.trail_s, t, true);
    }
    const double t = std::isnan(tracks.t) ? frame.t : tracks.t;
    drawTrails(img, s.view, *s.tracks, t - s.trail_s, t, false);
  }
  if (s.boxes)
    for (const LabelBox& b : s.boxes(frame)) drawLabelBox(img, s.view, b);
  for (const ObjectRow* r : truth.rows) drawTruth(img, s.view, *r);
  for (const ObjectRow* r : detections.rows) drawDetection(img, s.view, *r);
  if (s.scores)
    for (const ObjectRow* r : detections.rows) drawDetectionScore(img, s.view, *r, s.person_score);
  for (const ObjectRow* r : tracks.rows) drawTrackBody(img, s.view, *r);
  drawSensor(img, s.view, frame.sensor_pose);
  for (const ObjectRow* r : tracks.rows) drawTrackMarker(img, s.view, *r);

  std::vector<std::string> info = {
      "frame " + std::to_string(frame.index) +
          format("   t %.3f s (+%.2f s)", frame.t, frame.t - s.t_first),
      pointsLine(counts) + "   tracks " + std::to_string(tracks.rows.size())};
  if (s.truth || s.detections)
    info.push_back((s.truth ? "truth " + std::to_string(truth.rows.size()) + "   " : "") +
                   (s.detections ? "detections " + std::to_string(detections.rows.size()) : ""));
  finish(img, s, info, false);
  return img;
}

cv::Mat renderOverlay(const Scene& s, const Frame& last) {
  cv::Mat img = background(s);
  drawPolyline(img, s.view, s.sensor_path, colors::kSensorPath, 1);
  const PointCounts counts = points(img, s, last);
  if (s.detections)
    for (const auto& r : s.detections->rows()) drawDetection(img, s.view, r, 5);
  if (s.truth) {
    for (const auto& [id, path] : s.truth->paths()) {
      drawPath(img, s.view, path, colors::kTruth, 1, LineStyle::Dashed);
      drawPathEnds(img, s.view, path, colors::kTruth, 3);
    }
  }
  for (const auto& [id, path] : s.tracks->paths())
    drawPath(img, s.view, path, trackColor(id), 2, LineStyle::Solid);
  drawSensor(img, s.view, last.sensor_pose);
  // Ends and labels after every path, so a later path never covers an earlier one's marker.
  for (const auto& [id, path] : s.tracks->paths()) {
    drawPathEnds(img, s.view, path, trackColor(id), 4);
    const cv::Point end = s.view.pixel(path.back()->x, path.back()->y);
    drawText(img, std::to_string(id), end + cv::Point(6, -6), trackColor(id), 0.5);
  }

  std::vector<std::string> info = {
      "overlay of frames 0-" + std::to_string(last.index) +
          format("   %.1f s from t %.3f", last.t - s.t_first, s.t_first),
      "tracks " + std::to_string(s.tracks->paths().size()) + " ids, " +
          std::to_string(s.tracks->rows().size()) + " rows   last frame's " + pointsLine(counts)};
  if (s.truth || s.detections)
    info.push_back(
        (s.truth ? "truth " + std::to_string(s.truth->paths().size()) + " ids   " : "") +
        (s.detections ? "detections " + std::to_string(s.detections->rows().size()) : ""));
  finish(img, s, info, true);
  return img;
}

}  // namespace pedtrack::render
