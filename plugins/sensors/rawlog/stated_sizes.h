#pragma once
// Sizes an MRPT object states in a rawlog, checked before MRPT allocates them.
//
// MRPT sizes memory to a count or a string length it reads, before it reads what was counted:
// - a 2D scan's three arrays (ranges, validity, intensities: 9 bytes a beam) to its beam count.
//   A corrupt count of 10^9 (fuzz_rawlog found one) made it allocate and zero-fill 8.8 GB
//   before the read failed;
// - a string (a scan's or odometry's sensor label) to its 32-bit length, up to 4 GiB;
// - a sensory frame's observations (an action collection's actions), a deque, to its count;
// - a matrix object (a pose's homogeneous matrix, a scan's covariance in old versions, a depth
//   camera's range image) to its rows times columns.
// A 2D scanner gives at most tens of thousands of beams a scan and a label is a name, so for
// these classes, the most common in 2D rawlogs, the sizes are read ahead and checked first,
// in every version of their layout MRPT reads.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pedtrack::rawlog {

/// Most beams a 2D scan may have (the largest 2D scanners give ~25,000 a turn).
constexpr std::uint32_t kMaxScanBeams = 1000000;
/// Most observations in a sensory frame (actions in an action collection).
constexpr std::uint32_t kMaxEntryItems = 65536;
/// Longest sensor label, bytes.
constexpr std::uint32_t kMaxLabelBytes = 65536;
/// Most elements of a matrix object (2^25: a 4096 x 4096 range image fits twice).
constexpr std::uint64_t kMaxMatrixElements = std::uint64_t(1) << 25;

/// `peek(n)`: up to n of the bytes that follow the class name MRPT has just read (the object's
/// version first), left unread.
using Peek = std::function<std::vector<std::uint8_t>(std::size_t)>;

/// Why the object whose class name MRPT has just read must be refused (a size above the
/// limits), or "" when nothing is wrong, the class is not one checked, or its layout is not one
/// MRPT reads (MRPT then fails on it as it always did).
std::string refuseStatedSizes(const std::string& class_name, const Peek& peek);

}  // namespace pedtrack::rawlog
