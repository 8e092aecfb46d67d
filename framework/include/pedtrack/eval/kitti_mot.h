#pragma once
// KITTI's 3D multi-object tracking evaluation as AB3DMOT runs it (its evaluate.py, built on
// KITTI's devkit evaluate_tracking.py): boxes matched by 3D IoU, KITTI's ignore rules for the
// class (neighbouring classes, truncated / occluded labels, DontCare areas, boxes under 25 px),
// CLEAR MOT counts, ID switches and fragmentations per labelled trajectory, and AB3DMOT's
// sAMOTA, AMOTA and AMOTP over 40 recall levels (Weng et al., "3D Multi-Object Tracking: A
// Baseline and New Evaluation Metrics", IROS 2020). docs/pipelines.md ("KITTI: tracking by
// detection") has the rules.
#include <string>
#include <vector>

#include "pedtrack/eval/hota.h"
#include "pedtrack/eval/kitti_boxes.h"
#include "pedtrack/kitti_tracking_file.h"

namespace pedtrack::eval {

using pedtrack::KittiTrackRow;
using pedtrack::readKittiTrackFile;

struct KittiSequence {
  std::string name;  ///< errors name it: the results file
  std::vector<KittiTrackRow> truth, tracks;
  long frames = 0;  ///< frames scored: 0..frames-1 (0: up to the last labelled frame)
};

struct KittiMotOptions {
  std::string object_class =
      "pedestrian";       ///< pedestrian or car (its neighbour: person_sitting / van)
  double min_iou = 0.25;  ///< 3D IoU a match needs
  /// > 0: match by the distance of the boxes' bottom centres in bird's-eye view instead (m);
  /// MOTP is then the mean distance (m).
  double max_distance = 0;
  double min_height = 25;  ///< px: an unmatched box this low or lower is not a false positive
  int max_occlusion = 2;
  int max_truncation = 0;
  /// Reproduce evaluate.py's re-averaging of the track scores it overwrites, pass after pass
  /// (a floating-point artifact: a track can fail the threshold its own mean set, and drop out).
  bool score_drift = false;
};

/// The counts of one pass at one score threshold, pooled over the sequences.
struct KittiMotCounts {
  long tp = 0, fp = 0, fn = 0, ids = 0, frag = 0, n_gt = 0;  ///< n_gt: labels not ignored
  long ignored_tp = 0;
  long trajectories = 0, mostly_tracked = 0, partly_tracked = 0, mostly_lost = 0;
  double sum_similarity = 0;  ///< IoU (or distance) summed over the matches
  double mota() const;
  double motp() const;  ///< mean IoU of the matches (or mean distance)
  double recall() const;
  double precision() const;
  /// AB3DMOT's scaled MOTA at recall r: clip(1 − (FN + FP + IDS − (1 − r) n_gt) / (r n_gt), 0, 1).
  double smota(double r) const;
};

struct KittiMotResult {
  double samota = 0, amota = 0, amotp = 0;
  double threshold = -1e4;  ///< the track-score threshold of `best` (the highest MOTA)
  KittiMotCounts best;      ///< the pass reported as MOTA, MOTP, IDS, FRAG, FP, FN
  int levels = 0;           ///< recall levels sampled (at most 40)
  /// HOTA (every track, no score threshold) with the 3D IoU (or 1 − distance / max_distance) as
  /// the similarity, after TrackEval's KITTI preprocessing: ignored labels and the boxes matched
  /// to them, and unmatched boxes too low or in a DontCare area, left out.
  HotaResult hota;
};

/// Scores the sequences together (counts pooled) as AB3DMOT's evaluate.py does.
KittiMotResult evaluateKittiMot(std::vector<KittiSequence> sequences, const KittiMotOptions& o);

}  // namespace pedtrack::eval
