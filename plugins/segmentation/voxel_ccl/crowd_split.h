#pragma once
// Splitting a connected component that holds several people (ours, #45): people who stand or
// walk close together share voxels, so P2's connected components give them one cluster. Each
// person has a head, and between two heads the highest returns drop to the shoulders or below:
// the component's height map is searched for such peaks, and its points are shared among them.
#include <Eigen/Core>
#include <vector>

namespace pedtrack::voxelccl {

struct CrowdSplitParams {
  /// m: components whose bounding box (horizontal) has a shorter diagonal are one person
  double min_extent = 0.7;
  double max_extent = 5.0;    ///< m: a longer diagonal is a wall or a hedge, left whole
  double cell = 0.10;         ///< m: side of the height map's cells
  double min_head = 1.0;      ///< m above the ground: lowest head (a child)
  double head_dip = 0.14;     ///< share of the lower head's height that the highest returns
                              ///< between two heads lie below it at least (head and neck:
                              ///< ~0.25 m of an adult's 1.75 m, ~0.16 m of a 1.15 m child)
  double min_spacing = 0.45;  ///< m: closest two heads (an adult's shoulder breadth)
  double min_share = 0.1;     ///< least share of the component's points one person takes
  /// deg: the sensor's highest beam above its horizon (VLP-16: 15; 0: no limit). A peak seen
  /// within 0.5 deg of it is where the view ends, not a head: near the sensor the top beam cuts
  /// a tall object (a bush, a tree, a person) flat, and its highest returns are no head.
  double top_elevation = 0;
};

/// Shares the ground-aligned points of one component among the people in it. Returns the number
/// of people found (1: not split, `part` all 0) and sets part[i] in [0, count) for every point.
/// The people's centres start at the heads and move to the mean of their torso points
/// (a few k-means steps in the horizontal plane), so legs and bags go with their person; a
/// person left with under min_share of the points is dropped and the rest shared again.
/// `sensor` is the sensor's position in the same frame as the points.
int splitCrowd(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& sensor,
               const CrowdSplitParams& p, std::vector<int>& part);

}  // namespace pedtrack::voxelccl
