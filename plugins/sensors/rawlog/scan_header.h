#pragma once
// The beam count of an MRPT 2D scan, read from its serialized header before MRPT reads it.
//
// MRPT's CObservation2DRangeScan::serializeFrom sizes three arrays (ranges, validity,
// intensities: 9 bytes a beam) to the count it reads, before it reads one beam. A corrupt count
// of 10^9 (fuzz_rawlog found one) made it allocate and zero-fill 8.8 GB before the read failed.
// A 2D scanner gives at most tens of thousands of beams a scan, so the count is checked first.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pedtrack::rawlog {

/// The class names a 2D scan's object header carries (MRPT 2 and MRPT 1 rawlogs).
bool isScanClassName(const std::string& name);

/// Bytes scanBeamCount needs at most: the version, the scan's fixed fields, the sensor pose
/// object and the count.
constexpr std::size_t kScanHeaderBytes = 1 + 9 + 1 + 127 + 1 + 96 + 1 + 4;

/// `after_name`: the bytes that follow a 2D scan's class name. Its beam count for the layouts
/// MRPT 2 writes (scan versions 6 and 7, the sensor pose a CPose3D of version 2 or 3); nullopt
/// for any other layout or too few bytes (MRPT reads those as it always did).
std::optional<std::uint32_t> scanBeamCount(const std::vector<std::uint8_t>& after_name);

/// Most beams a 2D scan may have (the largest 2D scanners give ~25,000 a turn).
constexpr std::uint32_t kMaxScanBeams = 1000000;

}  // namespace pedtrack::rawlog
