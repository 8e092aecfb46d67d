#pragma once
// How Pipeline::run runs: where outputs go, how many frames, the live queue's length.
#include <cstddef>
#include <string>

namespace pedtrack {

struct RunOptions {
  std::string out_dir;  ///< empty: no files written
  bool progress = true;
  long max_frames = -1;  ///< stop after this many frames (<0: all)
  /// Write point_labels.bin (every point's label, each frame) when the pipeline has a segmenter.
  bool point_labels = true;
  /// Non-empty: every frame the source produced is also written to this MRPT rawlog (--record).
  std::string record;
  /// Frames a live source may have waiting for the stages; beyond it the oldest is dropped.
  std::size_t live_queue = 2;
};

}  // namespace pedtrack
