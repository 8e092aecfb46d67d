#pragma once
// Segmentation scored point by point: a run's point labels (point_labels.bin) against the
// simulator's per-point truth (truth_points.bin), frame by frame.
#include <cstdint>
#include <string>
#include <vector>

#include "pedtrack/point_labels.h"

namespace pedtrack::eval {

struct SegmentationOptions {
  long min_points = 10;    ///< people with fewer returns in a frame are not scored there
  long fragment = 3;       ///< a cluster takes part in a person (or object) from this many points
  double isolation = 0.5;  ///< m: people at least this clear of everything else form the
                           ///< "isolated" subset (clearance from the truth file)
};

/// Outcome counts over (person, frame) samples. `correct` = exactly one cluster holds the
/// person and it holds no other person or object; the others are not exclusive (a person can be
/// split and merged at once).
struct PersonSegCounts {
  std::size_t samples = 0, correct = 0, split = 0, merged_person = 0, merged_object = 0, missed = 0;
  PersonSegCounts& operator+=(const PersonSegCounts& o);
};

struct SegmentationReport {
  std::size_t frames = 0;             ///< frames in both files
  std::size_t truth_only_frames = 0;  ///< truth frames the run did not process
  // Points, summed over frames.
  std::size_t ground_points = 0, ground_removed = 0, ground_in_clusters = 0;
  std::size_t person_points = 0, person_as_ground = 0, person_band_removed = 0,
              person_in_clusters = 0;
  std::size_t object_points = 0, object_as_ground = 0;
  // Ground plane: frames where both planes are valid; normal angle (deg) and the height
  // difference of the two planes under the robot (m).
  std::vector<double> plane_angle_deg, plane_offset;
  PersonSegCounts all, isolated;
  /// Per person id: its samples (all, isolated).
  std::vector<std::pair<std::int32_t, PersonSegCounts>> per_person, per_person_isolated;
};

/// Reads both files and scores every frame the run processed (frames matched by index). Throws
/// ConfigError when the files are not a truth and a run label file, DataError when a frame's
/// point counts differ (the run read other data).
SegmentationReport evaluateSegmentation(const std::string& truth_path, const std::string& run_path,
                                        const SegmentationOptions& options);

/// One frame (both label vectors of equal size), added to `report`.
void scoreSegmentationFrame(const LabelFrame& truth, const LabelFrame& run,
                            const SegmentationOptions& options, SegmentationReport& report);

}  // namespace pedtrack::eval
