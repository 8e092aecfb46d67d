#include "stated_sizes.h"

#include <mrpt/rtti/CObject.h>

#include <optional>

namespace pedtrack::rawlog {
namespace {

// The class MRPT takes a stated name for: it drops any namespace ("mrjt::obs::X", "X" and
// "mrpt::obs::X" all read as X; fuzz_rawlog found a scan named the first way).
bool isClass(const std::string& name, const char* canonical) {
  const mrpt::rtti::TRuntimeClassId* id = mrpt::rtti::findRegisteredClass(name);
  return id != nullptr && std::string(id->className) == canonical;
}

std::optional<std::uint32_t> readU32(const std::vector<std::uint8_t>& b, std::size_t at) {
  if (b.size() < at + 4) return std::nullopt;
  return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
         std::uint32_t(b[at + 3]) << 24;
}

// A pose member serialized as an object at `at`: 0x80 | name length, the name, its version, its
// doubles, MRPT's end-of-object 0x88. The offset after it, or nullopt for another class or
// version. `doubles(version)`: how many doubles that version writes (0: not known).
std::optional<std::size_t> skipPose(const std::vector<std::uint8_t>& b, std::size_t at,
                                    const char* class_name, std::size_t (*doubles)(int version)) {
  if (b.size() <= at || !(b[at] & 0x80)) return std::nullopt;
  const std::size_t len = b[at] & 0x7F;
  if (b.size() < at + 1 + len + 1) return std::nullopt;
  const std::string name(b.begin() + std::ptrdiff_t(at + 1),
                         b.begin() + std::ptrdiff_t(at + 1 + len));
  if (!isClass(name, class_name)) return std::nullopt;
  at += 1 + len;
  const std::size_t n = doubles(b[at++]);
  if (n == 0) return std::nullopt;
  at += 8 * n;
  if (b.size() <= at || b[at] != 0x88) return std::nullopt;
  return at + 1;
}

// CPose3D version 2: x, y, z and a quaternion; version 3: x, y, z and the rotation matrix.
std::size_t pose3dDoubles(int version) {
  return version == 2 ? 7 : version == 3 ? 12 : 0;
}
// CPose2D version 1: x, y, phi.
std::size_t pose2dDoubles(int version) {
  return version == 1 ? 3 : 0;
}

std::string labelTooLong(const char* what, std::uint32_t bytes) {
  return std::string(what) + " whose sensor label is " + std::to_string(bytes) +
         " bytes long (at most " + std::to_string(kMaxLabelBytes) + ")";
}

// CObservation2DRangeScan versions 6 and 7: the version; aperture (float), rightToLeft (bool),
// maxRange (float); the sensor pose (CPose3D); the beam count; the beams' ranges (float) and
// validity (byte); stdError (float), the timestamp (8 bytes), beamAperture (float); the
// label. Versions 4 and 5 put a covariance matrix object before the count, 0–3 are older still.
std::string refuseScan(const std::function<std::vector<std::uint8_t>(std::size_t)>& peek) {
  const std::vector<std::uint8_t> b = peek(1 + 9 + 1 + 127 + 1 + 96 + 1 + 4);
  if (b.empty() || (b[0] != 6 && b[0] != 7)) return "";
  const std::optional<std::size_t> count_at =
      skipPose(b, 1 + 9, "mrpt::poses::CPose3D", pose3dDoubles);
  if (!count_at) return "";
  const std::optional<std::uint32_t> beams = readU32(b, *count_at);
  if (!beams) return "";
  if (*beams > kMaxScanBeams)
    return "a 2D scan of " + std::to_string(*beams) + " beams (at most " +
           std::to_string(kMaxScanBeams) + ")";
  // The beams are few enough to read ahead past them (5 bytes each) to the label's length.
  const std::size_t label_at = *count_at + 4 + 5 * std::size_t(*beams) + 16;
  const std::optional<std::uint32_t> label = readU32(peek(label_at + 4), label_at);
  return label && *label > kMaxLabelBytes ? labelTooLong("a 2D scan", *label) : "";
}

// CObservationOdometry versions 0–2: the version; the odometry (CPose2D); the label.
std::string refuseOdometry(const std::function<std::vector<std::uint8_t>(std::size_t)>& peek) {
  const std::vector<std::uint8_t> b = peek(1 + 1 + 127 + 1 + 24 + 1 + 4);
  if (b.empty() || b[0] > 2) return "";
  const std::optional<std::size_t> label_at = skipPose(b, 1, "mrpt::poses::CPose2D", pose2dDoubles);
  if (!label_at) return "";
  const std::optional<std::uint32_t> label = readU32(b, *label_at);
  return label && *label > kMaxLabelBytes ? labelTooLong("an odometry observation", *label) : "";
}

// CSensoryFrame: the version, (version 0: an id and a timestamp; version 1: an id), then the
// observations' count. CActionCollection: the version, then the actions' count. MRPT grows a
// deque to the count before reading one (fuzz_rawlog: 10^9 grew it towards 15 GB); a frame
// holds one observation per sensor.
std::string refuseItemCount(const char* name,
                            const std::function<std::vector<std::uint8_t>(std::size_t)>& peek,
                            bool frame) {
  const std::vector<std::uint8_t> b = peek(1 + 12 + 4);
  if (b.empty()) return "";
  const std::size_t at = 1 + (frame ? (b[0] == 0 ? 12 : b[0] == 1 ? 4 : 0) : 0);
  const std::optional<std::uint32_t> n = readU32(b, at);
  if (!n || *n <= kMaxEntryItems) return "";
  return std::string("a ") + name + " of " + std::to_string(*n) + " items (at most " +
         std::to_string(kMaxEntryItems) + ")";
}

}  // namespace

std::string refuseStatedSizes(const std::string& class_name,
                              const std::function<std::vector<std::uint8_t>(std::size_t)>& peek) {
  if (isClass(class_name, "mrpt::obs::CObservation2DRangeScan")) return refuseScan(peek);
  if (isClass(class_name, "mrpt::obs::CObservationOdometry")) return refuseOdometry(peek);
  if (isClass(class_name, "mrpt::obs::CSensoryFrame"))
    return refuseItemCount("mrpt::obs::CSensoryFrame", peek, true);
  if (isClass(class_name, "mrpt::obs::CActionCollection"))
    return refuseItemCount("mrpt::obs::CActionCollection", peek, false);
  return "";
}

}  // namespace pedtrack::rawlog
