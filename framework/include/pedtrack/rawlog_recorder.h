#pragma once
// `pedtrack run --record FILE.rawlog`: every frame a source produced, written as an MRPT rawlog
// (observations format, gz-compressed as MRPT writes them) the moment it is produced: the range
// observations as they came from the driver, preceded by the robot's odometry when the source
// has any. The rawlog source replays it frame for frame (and rawlog-edit, RawLogViewer read it).
#include <memory>
#include <string>

#include "pedtrack/frame.h"

namespace pedtrack {

class RawlogRecorder {
 public:
  /// Throws DataError naming the file when it cannot be created.
  explicit RawlogRecorder(const std::string& path);
  ~RawlogRecorder();
  void write(const Frame& frame);
  std::size_t written() const { return written_; }
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  std::size_t written_ = 0;
};

}  // namespace pedtrack
