#include "voxel_ccl/voxel_labelling.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace pedtrack::seg {
namespace {

// LSD radix sort of (key, index) pairs by the low `bits` bits of the keys, 11 bits a pass.
void radixSort(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& vals, int bits,
               std::vector<std::uint64_t>& tk, std::vector<std::uint32_t>& tv) {
  constexpr int kDigit = 11, kBuckets = 1 << kDigit;
  const std::size_t n = keys.size();
  tk.resize(n);
  tv.resize(n);
  std::size_t count[kBuckets];
  for (int shift = 0; shift < bits; shift += kDigit) {
    std::fill(count, count + kBuckets, 0);
    for (std::uint64_t k : keys) ++count[(k >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (auto& c : count) {
      const std::size_t x = c;
      c = sum;
      sum += x;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t pos = count[(keys[i] >> shift) & (kBuckets - 1)]++;
      tk[pos] = keys[i];
      tv[pos] = vals[i];
    }
    keys.swap(tk);
    vals.swap(tv);
  }
}

}  // namespace

std::vector<Voxel> forwardNeighbours(Connectivity c) {
  std::vector<Voxel> out;
  for (int dx = 0; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        if (dx == 0 && (dy < 0 || (dy == 0 && dz <= 0))) continue;  // not after the origin
        const int l1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (c == Connectivity::Six && l1 > 1) continue;
        if (c == Connectivity::Eighteen && l1 > 2) continue;
        out.push_back({dx, dy, dz});
      }
  return out;
}

int VoxelLabeler::find(int v) {
  while (parent_[v] != v) {
    parent_[v] = parent_[parent_[v]];
    v = parent_[v];
  }
  return v;
}

int VoxelLabeler::label(const std::vector<Voxel>& voxels, Connectivity connectivity,
                        std::vector<int>& component) {
  const std::size_t n = voxels.size();
  component.assign(n, -1);
  keys_.clear();
  if (n == 0) return 0;
  // Tight packing: each axis shifted to start at 1, with a free voxel on both sides, so a
  // neighbour's key is the voxel's key plus a constant offset and never wraps into another row.
  Voxel lo = voxels[0], hi = voxels[0];
  for (const Voxel& v : voxels)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], v[a]);
      hi[a] = std::max(hi[a], v[a]);
    }
  const std::uint64_t ny = std::uint64_t(hi[1] - lo[1]) + 3, nz = std::uint64_t(hi[2] - lo[2]) + 3;
  const std::uint64_t span = (std::uint64_t(hi[0] - lo[0]) + 3) * ny * nz;
  int bits = 1;
  while (bits < 64 && (std::uint64_t(1) << bits) < span) ++bits;
  point_keys_.resize(n);
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Voxel& v = voxels[i];
    point_keys_[i] =
        ((std::uint64_t(v[0] - lo[0] + 1) * ny) + std::uint64_t(v[1] - lo[1] + 1)) * nz +
        std::uint64_t(v[2] - lo[2] + 1);
    order_[i] = static_cast<std::uint32_t>(i);
  }
  radixSort(point_keys_, order_, bits, tmp_keys_, tmp_order_);
  // Unique voxels, and each point's voxel.
  point_voxel_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (keys_.empty() || keys_.back() != point_keys_[k]) keys_.push_back(point_keys_[k]);
    point_voxel_[order_[k]] = static_cast<int>(keys_.size()) - 1;
  }
  const int V = static_cast<int>(keys_.size());
  parent_.resize(V);
  for (int v = 0; v < V; ++v) parent_[v] = v;
  // Neighbours grouped by (dx, dy) row: a row's offsets (dz = -1, 0, +1) are consecutive keys,
  // so one cursor per row finds them all.
  struct Row {
    std::int64_t base;  // key offset of (dx, dy, 0)
    int dz_lo, dz_hi;   // the row's dz range
    bool has[3];        // which of dz = -1, 0, +1 are neighbours
  };
  std::vector<Row> rows;
  for (const Voxel& d : forwardNeighbours(connectivity)) {
    const std::int64_t base = (std::int64_t(d[0]) * std::int64_t(ny) + d[1]) * std::int64_t(nz);
    if (rows.empty() || rows.back().base != base) rows.push_back({base, d[2], d[2], {}});
    Row& r = rows.back();
    r.dz_lo = std::min(r.dz_lo, d[2]);
    r.dz_hi = std::max(r.dz_hi, d[2]);
    r.has[d[2] + 1] = true;
  }
  for (const Row& r : rows) {
    int j = 0;
    for (int i = 0; i < V; ++i) {
      // Keys fit in 63 bits: signed arithmetic, so dz = -1 needs no wrap-around.
      const std::int64_t centre = std::int64_t(keys_[i]) + r.base;  // later keys than keys_[i]
      while (j < V && std::int64_t(keys_[j]) < centre + r.dz_lo) ++j;
      if (j == V) break;
      for (int k = j; k < V && std::int64_t(keys_[k]) <= centre + r.dz_hi; ++k) {
        if (!r.has[std::int64_t(keys_[k]) - centre + 1]) continue;
        const int a = find(i), b = find(k);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // Components numbered by their lowest voxel: roots are always the lowest index of the set.
  compact_.assign(V, -1);
  int count = 0;
  for (int v = 0; v < V; ++v) {
    const int r = find(v);
    if (compact_[r] < 0) compact_[r] = count++;
    compact_[v] = compact_[r];
  }
  for (std::size_t i = 0; i < n; ++i) component[i] = compact_[point_voxel_[i]];
  return count;
}

}  // namespace pedtrack::seg
