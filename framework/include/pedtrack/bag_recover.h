// A ROS1 bag cut short (the recorder killed, the disk full, a copy interrupted) or never indexed,
// made readable again as `rosbag reindex` does: its chunks are scanned in order and every
// complete message before the cut is written, with a new index, to a copy that rosbag_storage
// opens in the original's place. Built with the ROS1 parts (cmake/PedtrackRos1.cmake).
#pragma once

#include <cstdint>
#include <string>

namespace pedtrack {

/// What a re-indexed bag kept.
struct BagRecovery {
  std::uint64_t data_end = 0;   ///< the byte where the readable data ends
  std::uint64_t file_size = 0;  ///< the damaged file's size
  std::size_t messages = 0;     ///< complete messages kept
  std::size_t chunks = 0;       ///< chunks kept (the last may be the cut one, partly)
  /// Why the bag needed it.
  enum class Cause { CutShort, NoIndex, DamagedIndex } cause = Cause::CutShort;
  /// The same as one phrase: "cut short: its data ends at byte 795994 of 1500000".
  std::string reason;
};

/// Scans `path`'s chunks in order and writes every complete message, re-indexed, as an
/// uncompressed bag at `out_path`. A record cut off by the end of the file ends the scan (what is
/// kept may be no message at all); a fault before it (a bag damaged, not cut) or a file that is not
/// a bag throws DataError, one line without the path ("not a readable ROS bag: … at byte N").
BagRecovery reindexBag(const std::string& path, const std::string& out_path);

/// The one-line message for a recovered bag: "FILE: cut short: its data ends at byte N of S; the M
/// complete messages before it are read (…)".
std::string recoveryWarning(const std::string& path, const BagRecovery& r);

}  // namespace pedtrack
