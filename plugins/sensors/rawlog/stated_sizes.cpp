#include "stated_sizes.h"

#include <mrpt/rtti/CObject.h>

#include <optional>

namespace pedtrack::rawlog {
namespace {

// The class MRPT takes a stated name for, by its canonical name, or "" for none: MRPT drops any
// namespace ("mrjt::obs::X", "X" and "mrpt::obs::X" all read as X; fuzz_rawlog found a scan
// named the first way).
std::string classOf(const std::string& name) {
  const mrpt::rtti::TRuntimeClassId* id = mrpt::rtti::findRegisteredClass(name);
  return id != nullptr ? id->className : "";
}

std::optional<std::uint32_t> readU32(const std::vector<std::uint8_t>& b, std::size_t at) {
  if (b.size() < at + 4) return std::nullopt;
  return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
         std::uint32_t(b[at + 3]) << 24;
}

// A matrix object's element size: CMatrixF (float) or CMatrixD (double); 0 for another class.
std::size_t matrixElementBytes(const std::string& canonical) {
  return canonical == "mrpt::math::CMatrixF" ? 4 : canonical == "mrpt::math::CMatrixD" ? 8 : 0;
}

// A member object at `at` of one of the classes a pose or a scan holds: 0x80 | name length, the
// name, its version, its data, MRPT's end-of-object 0x88. The offset after it, or nullopt when
// it is another class or version, or runs past `b`:
// - CPose3D version 0: a CMatrixF (the 4 x 4 homogeneous matrix); 1: a CMatrixD (the same);
//   2: x, y, z and a quaternion (7 doubles); 3: x, y, z and the rotation matrix (12 doubles);
// - CPose2D version 0: x, y, phi as floats; 1: as doubles;
// - CMatrixF / CMatrixD version 0: rows, columns (uint32), the elements.
std::optional<std::size_t> skipObject(const std::vector<std::uint8_t>& b, std::size_t at,
                                      int depth = 0) {
  if (depth > 2 || b.size() <= at || !(b[at] & 0x80)) return std::nullopt;
  const std::size_t len = b[at] & 0x7F;
  if (b.size() < at + 1 + len + 1) return std::nullopt;
  const std::string cls = classOf(
      std::string(b.begin() + std::ptrdiff_t(at + 1), b.begin() + std::ptrdiff_t(at + 1 + len)));
  at += 1 + len;
  const int version = b[at++];
  std::optional<std::size_t> end;
  if (cls == "mrpt::poses::CPose3D") {
    if (version == 0 || version == 1) end = skipObject(b, at, depth + 1);
    if (version == 2 || version == 3) end = at + 8 * (version == 2 ? 7 : 12);
  } else if (cls == "mrpt::poses::CPose2D") {
    if (version == 0 || version == 1) end = at + (version == 0 ? 12 : 24);
  } else if (const std::size_t bytes = matrixElementBytes(cls); bytes != 0 && version == 0) {
    const auto rows = readU32(b, at), cols = readU32(b, at + 4);
    if (rows && cols && std::uint64_t(*rows) * *cols <= b.size())
      end = at + 8 + bytes * std::size_t(*rows) * *cols;
  }
  if (!end || b.size() <= *end || b[*end] != 0x88) return std::nullopt;
  return *end + 1;
}

std::string labelTooLong(const char* what, std::uint32_t bytes) {
  return std::string(what) + " whose sensor label is " + std::to_string(bytes) +
         " bytes long (at most " + std::to_string(kMaxLabelBytes) + ")";
}

// CObservation2DRangeScan, every version MRPT reads (0-7): the version; aperture (float),
// rightToLeft (bool), maxRange (float); the sensor pose (a CPose3D); before version 6 the pose's
// covariance (a CMatrixF); the beam count; the beams' ranges (float) and, from version 1, their
// validity (byte). From version 5 on, stdError (float), the timestamp (8 bytes) and
// beamAperture (float) come next, then the label.
std::string refuseScan(const Peek& peek) {
  // Room for the largest poses (a CPose3D holding a 4 x 4 CMatrixD) and a 6 x 6 covariance; a
  // larger covariance is not skipped here, and its own size is checked when MRPT reads it.
  const std::vector<std::uint8_t> b = peek(2048);
  if (b.empty() || b[0] > 7) return "";
  const int version = b[0];
  std::optional<std::size_t> count_at = skipObject(b, 1 + 9);
  if (count_at && version < 6) count_at = skipObject(b, *count_at);
  if (!count_at) return "";
  const std::optional<std::uint32_t> beams = readU32(b, *count_at);
  if (!beams) return "";
  if (*beams > kMaxScanBeams)
    return "a 2D scan of " + std::to_string(*beams) + " beams (at most " +
           std::to_string(kMaxScanBeams) + ")";
  if (version < 5) return "";  // no label
  // The beams are few enough to read ahead past them (5 bytes each) to the label's length.
  const std::size_t label_at = *count_at + 4 + 5 * std::size_t(*beams) + 16;
  const std::optional<std::uint32_t> label = readU32(peek(label_at + 4), label_at);
  return label && *label > kMaxLabelBytes ? labelTooLong("a 2D scan", *label) : "";
}

// CObservationOdometry versions 0-2: the version; the odometry (a CPose2D); the label.
std::string refuseOdometry(const Peek& peek) {
  const std::vector<std::uint8_t> b = peek(1 + 1 + 127 + 1 + 24 + 1 + 4);
  if (b.empty() || b[0] > 2) return "";
  const std::optional<std::size_t> label_at = skipObject(b, 1);
  if (!label_at) return "";
  const std::optional<std::uint32_t> label = readU32(b, *label_at);
  return label && *label > kMaxLabelBytes ? labelTooLong("an odometry observation", *label) : "";
}

// CMatrixF / CMatrixD version 0: rows and columns (uint32), then the elements, which MRPT
// allocates first (a pose's 4 x 4, a scan's covariance, a depth camera's range image).
std::string refuseMatrix(const Peek& peek, std::size_t element_bytes) {
  const std::vector<std::uint8_t> b = peek(1 + 8);
  const auto rows = readU32(b, 1), cols = readU32(b, 5);
  if (b.empty() || b[0] != 0 || !rows || !cols) return "";
  const std::uint64_t n = std::uint64_t(*rows) * *cols;
  if (n <= kMaxMatrixElements) return "";
  return "a " + std::to_string(*rows) + " x " + std::to_string(*cols) + " matrix (" +
         std::to_string(n * element_bytes) + " bytes; at most " +
         std::to_string(kMaxMatrixElements) + " elements)";
}

// CSensoryFrame: the version, (version 0: an id and a timestamp; version 1: an id), then the
// observations' count. CActionCollection: the version, then the actions' count. MRPT grows a
// deque to the count before reading one (fuzz_rawlog: 10^9 grew it towards 15 GB); a frame
// holds one observation per sensor.
std::string refuseItemCount(const char* name, const Peek& peek, bool frame) {
  const std::vector<std::uint8_t> b = peek(1 + 12 + 4);
  if (b.empty()) return "";
  const std::size_t at = 1 + (frame ? (b[0] == 0 ? 12 : b[0] == 1 ? 4 : 0) : 0);
  const std::optional<std::uint32_t> n = readU32(b, at);
  if (!n || *n <= kMaxEntryItems) return "";
  return std::string("a ") + name + " of " + std::to_string(*n) + " items (at most " +
         std::to_string(kMaxEntryItems) + ")";
}

}  // namespace

std::string refuseStatedSizes(const std::string& class_name, const Peek& peek) {
  const std::string cls = classOf(class_name);
  if (cls.empty()) return "";
  if (cls == "mrpt::obs::CObservation2DRangeScan") return refuseScan(peek);
  if (cls == "mrpt::obs::CObservationOdometry") return refuseOdometry(peek);
  if (cls == "mrpt::obs::CSensoryFrame") return refuseItemCount(cls.c_str(), peek, true);
  if (cls == "mrpt::obs::CActionCollection") return refuseItemCount(cls.c_str(), peek, false);
  if (const std::size_t bytes = matrixElementBytes(cls); bytes != 0)
    return refuseMatrix(peek, bytes);
  return "";
}

}  // namespace pedtrack::rawlog
