// Opens a ROS1 bag for rosbag_storage: its structure checked first (pedtrack/bag_check.h); a bag
// that is only cut short or was never indexed is re-indexed into a temporary copy
// (pedtrack/bag_recover.h) that is read in its place. For the ROS1 parts only (it includes
// rosbag_storage).
#pragma once

#include <rosbag/bag.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "pedtrack/bag_check.h"
#include "pedtrack/bag_recover.h"
#include "pedtrack/errors.h"

namespace pedtrack {

/// Opens `path` into `bag`. Returns what a re-indexed bag kept (nothing for a whole bag); the
/// caller warns with recoveryWarning() and reports the run as failed once the messages are read.
/// Throws DataError (one line, without the path) for a bag that is damaged, not cut, and
/// rosbag_storage's exceptions for what it refuses after the check.
inline std::optional<BagRecovery> openBagForReading(rosbag::Bag& bag, const std::string& path) {
  try {
    checkBagStructure(path);  // rosbag_storage trusts the lengths in the file
  } catch (const DataError& check) {
    std::string copy =
        (std::filesystem::temp_directory_path() / "pedtrack-reindexed-XXXXXX.bag").string();
    const int fd = mkstemps(copy.data(), 4);
    if (fd < 0) throw DataError("cannot create a temporary file for the re-indexed copy");
    ::close(fd);
    BagRecovery kept;
    try {
      kept = reindexBag(path, copy);
    } catch (const DataError&) {
      std::remove(copy.c_str());
      throw check;  // not a bag, or damaged, not cut: the check names the first fault
    }
    if (kept.messages == 0) {
      std::remove(copy.c_str());
      throw DataError("not a readable ROS bag: no complete message before its data ends at byte " +
                      std::to_string(kept.data_end));
    }
    try {
      bag.open(copy, rosbag::bagmode::Read);
    } catch (...) {
      std::remove(copy.c_str());
      throw;
    }
    std::remove(copy.c_str());  // the open file stays readable until the bag is closed
    if (kept.cause == BagRecovery::Cause::DamagedIndex) {
      const std::string what = check.what();  // "not a readable ROS bag: FAULT at byte N"
      kept.reason += " (" + what.substr(what.find(": ") + 2) + ")";
    }
    return kept;
  }
  bag.open(path, rosbag::bagmode::Read);
  return std::nullopt;
}

}  // namespace pedtrack
