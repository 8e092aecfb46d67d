#pragma once
// Leg detection in 2D scans (P3 §2.2, eq. 1): a circle of bounded radius fitted to each segment,
// non-circular segments rejected, legs seen by several scanners merged, and legs paired into
// person candidates.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pedtrack/fit/circle.h"

namespace pedtrack::seg {

struct LegParams {
  double r_min = 0.03, r_max = 0.07;  ///< m, P3's radius bounds
  double max_residual = 0.02;         ///< m, RMS distance of the points to the circle
  int min_points = 3;                 ///< P3 ignores clusters of fewer points
  /// Reject arcs whose circle centre is not farther from the sensor than their points (a leg's
  /// visible side is convex toward the sensor); P3 has no such test.
  bool require_convex = false;
};

struct Leg {
  fit::Circle circle;
  double residual = 0;  ///< RMS of the points' distances to the circle (m)
};

/// Fits P3 eq. 1 to one segment seen from (sx, sy) and accepts it as a leg when enough points
/// fit closely (and, with require_convex, the arc faces the sensor).
bool detectLeg(const fit::Points2& pts, double sx, double sy, const LegParams& p, Leg& out);

/// Where a segment that is no leg as a whole may be two legs, one just behind the other: the
/// index of the first point of the second part at the largest range step between consecutive
/// points (seen from (sx, sy)), when that step is at least `min_jump` and both parts keep
/// p.min_points (and 3); 0 when there is none. A person standing with one foot a little ahead
/// shows both legs as one segment when the step between them is below the segmenter's gap.
/// `step` (optional) receives that step, signed: the second part's range less the first's.
std::size_t legSplitPoint(const fit::Points2& pts, double sx, double sy, double min_jump,
                          const LegParams& p, double* step = nullptr);

/// A detected leg as mergeLegs reads it: which scan (observation) it came from, and its points
/// (in the frame of the centres).
struct ScanLeg {
  Leg leg;
  std::size_t scan = 0;
  fit::Points2 points;
};

/// One leg after merging: the ScanLegs it is made of (indices into mergeLegs' input, ascending)
/// and its circle.
struct MergedLeg {
  std::vector<std::size_t> members;
  Leg leg;
};

/// Scanners with overlapping fields of view see one leg twice: legs of different scans whose
/// centres are closer than `merge_distance` become one, closest first, never two legs of the same
/// scan (a person's two legs can come that close). A merged leg's circle is fitCircleBounded on
/// all its points within p's radius bounds; where that fails or its RMS residual exceeds
/// p.max_residual (arcs seen at slightly different times of a moving leg), the mean of the
/// centres and radii. Legs merged with nothing come back alone, unchanged; the result is ordered
/// by first member. `merge_distance` <= 0: nothing merges.
std::vector<MergedLeg> mergeLegs(const std::vector<ScanLeg>& legs, double merge_distance,
                                 const LegParams& p);

/// Pairs legs into person candidates: repeatedly the closest two unpaired legs whose centres
/// are at most `max_distance` apart. Returns each leg's partner index, -1 when unpaired.
std::vector<int> pairLegs(const std::vector<Eigen::Vector2d>& centres, double max_distance);

}  // namespace pedtrack::seg
