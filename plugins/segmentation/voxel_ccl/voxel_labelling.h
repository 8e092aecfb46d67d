#pragma once
// Connected-component labelling of occupied voxels (P2 §3.2 labels a voxel image with
// 26-connectivity). Sparse: only occupied voxels are stored, as sorted integer keys, and each
// neighbour offset is found by a cursor that only moves forward through the sorted keys, so a
// frame costs one radix sort plus O(voxels × neighbours) with no hash lookups.
#include <array>
#include <cstdint>
#include <vector>

namespace pedtrack::seg {

enum class Connectivity { Six = 6, Eighteen = 18, TwentySix = 26 };

/// Integer voxel coordinates of one point.
using Voxel = std::array<int, 3>;

class VoxelLabeler {
 public:
  /// Labels the connected components of the voxels occupied by the points (`voxels[i]` is point
  /// i's voxel). Returns the number of components; `component[i]` is point i's component, the
  /// components numbered 0.. in the order of their lowest voxel (x, then y, then z).
  int label(const std::vector<Voxel>& voxels, Connectivity connectivity,
            std::vector<int>& component);

  /// Occupied voxels of the last call.
  std::size_t voxelCount() const { return keys_.size(); }

 private:
  int find(int v);
  std::vector<std::uint64_t> point_keys_, keys_, tmp_keys_;
  std::vector<std::uint32_t> order_, tmp_order_;
  std::vector<int> parent_, point_voxel_, compact_;
};

/// The neighbour offsets of one connectivity that come after (0, 0, 0) in (x, y, z) order: half
/// of them, since a pair is joined once. 3, 9 or 13 offsets.
std::vector<Voxel> forwardNeighbours(Connectivity c);

}  // namespace pedtrack::seg
