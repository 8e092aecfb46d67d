#pragma once
// 2D scan segmentation (P4 §2.1) and per-segment features for torso and leg classifiers.
#include <cstdint>
#include <string>
#include <vector>

#include "pedtrack/fit/circle.h"
#include "pedtrack/frame.h"

namespace pedtrack::seg {

/// The points of Frame::cloud() that came from one 2D scan, in beam order.
struct ScanRun {
  std::size_t first = 0;  ///< cloud index of the run's first point
  std::size_t count = 0;  ///< points of the run
  std::vector<int> beam;  ///< beam index of each point of the run (when asked for)
  double sx = 0, sy = 0;  ///< sensor position, robot frame
};

/// One run per 2D scan of the frame, in cloud order (from Frame::cloudSpans()), with each
/// point's beam index when `beams` (read from the scan's validity flags; DataError when their
/// count differs from the scan's points in the cloud). 3D observations form no run.
std::vector<ScanRun> scanRuns(const Frame& frame, bool beams = true);

struct SegmentParams {
  double gap = 0.13;   ///< m: consecutive points farther apart start a new segment
  int min_points = 3;  ///< shorter segments are dropped
  /// > 0: the gap grows with range as an adaptive breakpoint detector (Borges & Aldon 2004):
  /// max(gap, r·sin Δφ / sin(λ − Δφ)) with λ this angle (rad); 0: a fixed gap.
  double adaptive_angle = 0;
  /// >= 0: more beams than this without a return between two points also start a new segment
  /// (the beams between them saw past both: a range discontinuity); < 0: only the gap counts.
  /// One missing beam is a dropout, not a discontinuity.
  int max_missing = 1;
};

/// Splits one run into segments of Kept points (cloud indices), breaking where two consecutive
/// kept points are farther apart than the gap.
std::vector<std::vector<std::uint32_t>> splitRun(const Frame& frame, const ScanRun& run,
                                                 const SegmentParams& p);

/// Names of segmentFeatures' values, in order (clusters.csv columns). The four torso features
/// of P4 (after Zainudin et al. 2010) are `width`, `ellipse_a`, `ellipse_b` and
/// `ellipse_residual`; the others are the geometric segment features of Arras et al. (2007)
/// that leg detectors use.
const std::vector<std::string>& segmentFeatureNames();

/// Features of one segment's points (in scan order) seen from (sx, sy); `jump_prev/next` are
/// the range differences to the neighbouring points just outside the segment (m, positive when
/// the neighbour is farther: the segment stands in front), 0 at the scan's ends.
std::vector<double> segmentFeatures(const fit::Points2& pts, double sx, double sy, double jump_prev,
                                    double jump_next);

}  // namespace pedtrack::seg
