#include "scan_header.h"

namespace pedtrack::rawlog {

bool isScanClassName(const std::string& name) {
  return name == "mrpt::obs::CObservation2DRangeScan" || name == "CObservation2DRangeScan";
}

std::optional<std::uint32_t> readU32(const std::vector<std::uint8_t>& b, std::size_t at) {
  if (b.size() < at + 4) return std::nullopt;
  return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
         std::uint32_t(b[at + 3]) << 24;
}

std::optional<ScanHeader> readScanHeader(const std::vector<std::uint8_t>& b) {
  // version; aperture (float), rightToLeft (bool), maxRange (float); then the sensor pose as an
  // object: 0x80 | name length, the name, its version, its doubles, MRPT's end-of-object 0x88;
  // then the 32-bit count. Scan versions 4 and 5 put a covariance matrix object before the
  // count, 0–3 are older still: not checked.
  if (b.empty() || (b[0] != 6 && b[0] != 7)) return std::nullopt;
  std::size_t at = 1 + 9;
  if (b.size() <= at || !(b[at] & 0x80)) return std::nullopt;
  const std::size_t len = b[at] & 0x7F;
  if (b.size() < at + 1 + len + 1) return std::nullopt;
  const std::string pose(b.begin() + std::ptrdiff_t(at + 1),
                         b.begin() + std::ptrdiff_t(at + 1 + len));
  if (pose != "mrpt::poses::CPose3D" && pose != "CPose3D") return std::nullopt;
  at += 1 + len;
  const int version = b[at++];
  // Version 2: x, y, z and a quaternion; version 3: x, y, z and the rotation matrix.
  const std::size_t doubles = version == 2 ? 7 : version == 3 ? 12 : 0;
  if (doubles == 0) return std::nullopt;
  at += 8 * doubles;
  if (b.size() <= at || b[at] != 0x88) return std::nullopt;
  ++at;
  const std::optional<std::uint32_t> beams = readU32(b, at);
  if (!beams) return std::nullopt;
  return ScanHeader{*beams, at};
}

}  // namespace pedtrack::rawlog
