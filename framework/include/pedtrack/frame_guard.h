#pragma once
// Checks every frame a source hands over before any stage sees it, whatever the source: a
// driver, a log or a fault injector. A frame whose time or pose is unusable is skipped; range
// data no sensor can produce (NaN, inf, negative or zero ranges flagged valid, non-finite cloud
// points) is removed. Each kind is counted (run.json `input_warnings`) and warned about once on
// stderr, so a robot's operator learns that the input is at fault, and the stages never do.
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack {

class FrameGuard {
 public:
  /// A pause longer than this (s) is counted as a time jump; the frame is still used (trackers
  /// bound their prediction step).
  static constexpr double kTimeJump = 5.0;
  /// Time going back by at most this much (s) is a late or repeated frame, skipped; further back
  /// is a clock reset, used.
  static constexpr double kClockReset = 10.0;
  /// Robot motion beyond kOdometryJumpMetres + kOdometryJumpSpeed * dt between frames (m) is
  /// counted as an odometry jump (a reset or a wrong transform); the frame is still used.
  static constexpr double kOdometryJumpMetres = 1.0;
  static constexpr double kOdometryJumpSpeed = 10.0;
  /// A step of more than this many usual frame periods means frames went missing.
  static constexpr double kGapFactor = 1.8;

  explicit FrameGuard(bool warn = true) : warn_(warn) {}
  /// The source hands over detections, not range data (Sensor::detectionsOnly): frames without
  /// observations are no fault.
  void expectDetectionsOnly() { detections_only_ = true; }

  /// Cleans `frame`'s range data; false when the frame must be skipped.
  bool admit(Frame& frame);

  /// Every kind with its count, zeros included (a stable run.json schema).
  std::vector<std::pair<std::string, long>> counts() const;
  long total() const;

 private:
  bool detections_only_ = false;
  enum Kind {
    kBadTime,
    kTimeRepeat,
    kTimeBackwards,
    kClockResets,
    kTimeJumps,
    kFrameGaps,
    kBadPose,
    kOdometryJumps,
    kInvalidRanges,
    kInvalidPoints,
    kEmptyFrames,
    kKinds
  };
  void count(Kind k, const Frame& f, long n, const std::string& what);
  // Removes impossible returns from the frame's observations; the points left.
  std::size_t clean(Frame& f);
  // The median of the recent frame periods (s), 0 until enough were seen.
  double typicalPeriod() const;

  bool warn_;
  long counts_[kKinds] = {};
  bool have_last_ = false;
  double last_t_ = 0;
  mrpt::poses::CPose3D last_pose_;
  std::array<double, 32> periods_{};
  std::size_t n_periods_ = 0;
};

}  // namespace pedtrack
