#pragma once
// The sizes an MRPT 2D scan states in its serialized form, read before MRPT reads them.
//
// MRPT's CObservation2DRangeScan::serializeFrom sizes three arrays (ranges, validity,
// intensities: 9 bytes a beam) to the beam count it reads, before it reads one beam. A corrupt
// count of 10^9 (fuzz_rawlog found one) made it allocate and zero-fill 8.8 GB before the read
// failed. Its sensor label is a string whose 32-bit length MRPT allocates first too (up to
// 4 GiB). A 2D scanner gives at most tens of thousands of beams a scan, and a label is a name,
// so both are checked first.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pedtrack::rawlog {

/// The class names a 2D scan's object header carries (MRPT 2 and MRPT 1 rawlogs).
bool isScanClassName(const std::string& name);

/// Bytes readScanHeader needs at most: the version, the scan's fixed fields, the sensor pose
/// object and the beam count.
constexpr std::size_t kScanHeaderBytes = 1 + 9 + 1 + 127 + 1 + 96 + 1 + 4;

struct ScanHeader {
  std::uint32_t beams = 0;
  std::size_t beams_at = 0;  ///< offset of the beam count from the version byte
  /// Offset of the sensor label's 32-bit length: after the beams' ranges (float) and validity
  /// (byte), stdError (float), the timestamp (8 bytes) and beamAperture (float).
  std::size_t labelLengthAt() const { return beams_at + 4 + 5 * std::size_t(beams) + 16; }
};

/// `after_name`: the bytes that follow a 2D scan's class name. Its header for the layouts MRPT 2
/// writes (scan versions 6 and 7, the sensor pose a CPose3D of version 2 or 3); nullopt for any
/// other layout or too few bytes (MRPT reads those as it always did).
std::optional<ScanHeader> readScanHeader(const std::vector<std::uint8_t>& after_name);

/// The little-endian 32-bit value at `at`; nullopt when `b` ends before it.
std::optional<std::uint32_t> readU32(const std::vector<std::uint8_t>& b, std::size_t at);

/// Most beams a 2D scan may have (the largest 2D scanners give ~25,000 a turn).
constexpr std::uint32_t kMaxScanBeams = 1000000;
/// Longest sensor label a 2D scan may have, bytes.
constexpr std::uint32_t kMaxLabelBytes = 65536;

}  // namespace pedtrack::rawlog
