#pragma once
// The per-point labels of a run (point_labels.bin) or a simulation (truth_points.bin), looked up
// frame by frame while a picture or video is drawn.
#include <memory>
#include <string>

#include "pedtrack/point_labels.h"

namespace pedtrack::render {

class LabelSource {
 public:
  /// Throws ConfigError when the file is missing or not a label file.
  explicit LabelSource(const std::string& path);
  LabelKind kind() const { return kind_; }
  /// The labels of frame `index` when the file has that frame with `points` labels, else null.
  /// Cheapest when frames are asked in increasing order (an earlier one reopens the file).
  const LabelFrame* at(std::size_t index, std::size_t points);

 private:
  std::string path_;
  LabelKind kind_;
  std::unique_ptr<LabelFileReader> reader_;
  LabelFrame current_, next_;  // the last frame read (kept at the end of the file), a buffer
  bool have_ = false, ended_ = false;
};

}  // namespace pedtrack::render
