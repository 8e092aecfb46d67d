#pragma once
// Person / non-person decisions of a run scored against the simulator's per-point truth, as P2
// reports them (Table 1: the appearance classifier alone; Table 2: appearance + motion, "an
// object is a person when a (confirmed) track is established on it").
//
// The scored samples are the clusters a detection was made from (detections.csv's `cluster`
// column), frame by frame. A cluster's truth is the most frequent truth label of its points
// (truth_points.bin against the run's point_labels.bin): a person id makes it a person, an object
// or the ground a non-person. It is decided a person
//   by appearance: when its detection's score is >= q_person;
//   completely:    when a track row of that frame with status `person_status` names it in its
//                  `cluster` column (tracks.csv).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pedtrack/point_labels.h"

namespace pedtrack::eval {

struct DecisionOptions {
  double q_person = 0.5;                    ///< appearance: person when score >= this (P2's Q_P)
  std::string person_status = "confirmed";  ///< complete: a track with this status on the cluster
};

/// A 2×2 confusion matrix, rows actual (non-person, person), columns decided (non-person, person).
struct DecisionMatrix {
  std::size_t tn = 0, fp = 0;  ///< non-persons decided non-person / person
  std::size_t fn = 0, tp = 0;  ///< persons decided non-person / person
  void add(bool actual_person, bool decided_person);
  std::size_t total() const { return tn + fp + fn + tp; }
  // NaN when undefined (0/0).
  double detectionRate() const;      ///< TP / (TP + FN)
  double falsePositiveRate() const;  ///< FP / (FP + TN)
  double precision() const;          ///< TP / (TP + FP)
  double accuracy() const;           ///< (TP + TN) / total
};

/// The two classifiers' matrices over the same samples.
struct DecisionPair {
  DecisionMatrix appearance, complete;
};

/// One truth id's decisions (person id > 0, object -id < 0).
struct ObjectDecisions {
  std::int32_t id = 0;
  std::size_t hit_frames = 0;         ///< scored frames where the scan hit it
  std::size_t frames = 0;             ///< frames where it owned a scored cluster
  std::size_t appearance_frames = 0;  ///< of them, frames where one of its clusters passed Q_P
  std::size_t complete_frames = 0;    ///< ... where one of its clusters had a person track
};

/// The evidence of one frame (besides its label files).
struct FrameDecisionInput {
  /// (cluster index, score) of each detection made from a cluster.
  std::vector<std::pair<std::int32_t, double>> detections;
  /// Clusters named by a track row with the person status.
  std::vector<std::int32_t> person_track_clusters;
};

struct DecisionReport {
  // Frames.
  std::size_t frames = 0;                     ///< in both label files (scored)
  std::size_t truth_only_frames = 0;          ///< truth frames the run did not process
  std::size_t frames_without_detections = 0;  ///< scored frames with no detection on a cluster
  // Clusters, over the scored frames.
  std::size_t clusters = 0;            ///< clusters with points in point_labels.bin
  std::size_t clusters_scored = 0;     ///< of them, with a detection (= per_cluster totals)
  std::size_t unscored_person = 0;     ///< clusters without a detection owned by a person
  std::size_t unscored_nonperson = 0;  ///< ... by an object or the ground
  std::size_t scored_ground = 0;       ///< scored clusters owned by the ground (non-persons)
  // Input that could not be used.
  std::size_t detections = 0;                  ///< detection rows of the scored frames
  std::size_t detections_without_cluster = 0;  ///< empty `cluster`: not made from a cluster
  std::size_t detections_unknown_cluster = 0;  ///< cluster index without points in the labels
  std::size_t detections_duplicate = 0;        ///< a second detection of a cluster (max score used)
  std::size_t detection_frames_unmatched = 0;  ///< detection frames absent from point_labels.bin
  std::size_t track_rows_person = 0;  ///< track rows with the person status (scored frames)
  std::size_t track_rows_without_cluster = 0;  ///< ... with no cluster this frame (coasting)
  std::size_t track_clusters_unscored = 0;     ///< ... on a cluster that has no detection
  /// Over the scored clusters' detections; NaN when none.
  double min_score = std::numeric_limits<double>::quiet_NaN(),
         max_score = std::numeric_limits<double>::quiet_NaN();

  /// (a) every scored cluster in every frame.
  DecisionPair per_cluster;
  /// (b) every person id and object id once (ground-owned clusters do not take part): decided
  /// a person if decided so in at least one frame (P2 Table 2) ...
  DecisionPair per_object_any;
  /// ... or in more than half of its frames.
  DecisionPair per_object_majority;
  /// Every id the scans hit in the scored frames: persons by id, then objects by number. Those
  /// with frames == 0 never owned a scored cluster and are not in (b).
  std::vector<ObjectDecisions> per_object;
  std::size_t persons_never_scored = 0, objects_never_scored = 0;
};

struct DecisionInputs {
  std::string truth_points;  ///< truth_points.bin
  std::string point_labels;  ///< the run's point_labels.bin
  std::string detections;    ///< the run's detections.csv (with `frame`, `score`, `cluster`)
  std::string tracks;        ///< the run's tracks.csv (with `frame`, `status`, `cluster`)
};

/// Reads the four files and scores every frame the run processed (label frames matched by index,
/// CSV rows by their `frame` column). Throws ConfigError naming the file when one is missing or
/// lacks a needed column, DataError when the label files' frames differ in size.
DecisionReport evaluateDecisions(const DecisionInputs& in, const DecisionOptions& options);

/// One frame, added to `report` (call finishDecisions after the last).
void scoreDecisionFrame(const LabelFrame& truth, const LabelFrame& run,
                        const FrameDecisionInput& input, const DecisionOptions& options,
                        DecisionReport& report);

/// Sorts report.per_object and fills the per-object matrices and never-scored counts from it.
void finishDecisions(DecisionReport& report);

}  // namespace pedtrack::eval
