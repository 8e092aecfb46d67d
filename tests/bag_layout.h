// The layout of a ROS1 bag (format 2.0) with uncompressed chunks, read by the tests themselves
// (independently of pedtrack's scanner) to know what a cut at a byte leaves: where every message
// record ends, and every position a reader could stop at.
#pragma once

#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace pedtrack::test {

struct BagLayout {
  std::vector<std::size_t> message_ends;  ///< in bag order
  /// Ends of every record (top level and inside chunks) and the start of every chunk's data.
  std::set<std::size_t> stops;
  std::vector<std::size_t> chunk_starts, chunk_ends;  ///< chunk records (top level)
  std::size_t index_pos = 0;

  /// Complete messages a cut at `cut` leaves.
  std::size_t messagesBefore(std::size_t cut) const {
    std::size_t n = 0;
    for (std::size_t e : message_ends) n += e <= cut;
    return n;
  }
  /// The byte where a reader of the first `cut` bytes finds the data end.
  std::size_t dataEnd(std::size_t cut) const { return *std::prev(stops.upper_bound(cut)); }
};

inline BagLayout bagLayout(const std::string& b) {
  const auto u32 = [&](std::size_t p) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + p, 4);
    return v;
  };
  // A record header's op (the field "op=" followed by one byte).
  const auto op = [&](std::size_t p) {
    const std::string h = b.substr(p + 4, u32(p));
    return h[h.find("op=") + 3];
  };
  BagLayout l;
  l.stops.insert(13);
  for (std::size_t p = 13; p < b.size();) {
    const std::size_t data = p + 8 + u32(p), end = data + u32(p + 4 + u32(p));
    if (p == 13) {
      const std::string h = b.substr(p + 4, u32(p));
      std::memcpy(&l.index_pos, h.data() + h.find("index_pos=") + 10, 8);
    }
    if (op(p) == 0x05) {
      l.chunk_starts.push_back(p);
      l.chunk_ends.push_back(end);
      l.stops.insert(data);
      for (std::size_t q = data; q < end;) {
        const std::size_t qe = q + 8 + u32(q) + u32(q + 4 + u32(q));
        if (op(q) == 0x02) l.message_ends.push_back(qe);
        l.stops.insert(qe);
        q = qe;
      }
    }
    l.stops.insert(end);
    p = end;
  }
  return l;
}

}  // namespace pedtrack::test
