#pragma once
// Where Pipeline::run gets its frames. A file source is read in the pipeline's thread, frame by
// frame as the stages ask. A live source (Sensor::live()) is read on its own thread into a
// bounded FrameQueue: the device's data keeps arriving while the stages work, and when they fall
// behind the oldest waiting frame is dropped, so tracks stay current. Either way every frame the
// source produced can be recorded (--record) the moment it is produced, before any drop.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "pedtrack/frame_queue.h"
#include "pedtrack/plugin.h"
#include "pedtrack/rawlog_recorder.h"
#include "pedtrack/run_options.h"
#include "pedtrack/stop_request.h"

namespace pedtrack {

class FrameSupply {
 public:
  using Clock = std::chrono::steady_clock;
  /// `recorder` may be null. Starts the reading thread for a live source.
  FrameSupply(Sensor& source, const RunOptions& options, RawlogRecorder* recorder);
  ~FrameSupply();
  FrameSupply(const FrameSupply&) = delete;
  FrameSupply& operator=(const FrameSupply&) = delete;

  /// The next frame and when the source handed it over; false at the end of the stream, on a
  /// source error (then error() says what) or once stopRequested() is set.
  bool next(Frame& frame, Clock::time_point& arrival);
  /// Ends reading: joins the live thread (which checks stopRequested() between reads).
  void stop();

  bool live() const { return live_; }
  std::size_t framesRead() const { return read_; }
  std::size_t dropped() const { return queue_ ? queue_->dropped() : 0; }
  /// The source's or the recorder's error, empty when none (valid after stop()).
  const std::string& error() const { return error_; }

 private:
  // Reads one frame from the source and records it; false at the end or on an error.
  bool read(Frame& frame, Clock::time_point& arrival);
  void readLoop();

  Sensor& source_;
  const long max_frames_;
  RawlogRecorder* recorder_;
  const bool live_;
  std::atomic<std::size_t> read_{0};
  std::atomic<bool> stop_{false};
  std::string error_;
  std::unique_ptr<FrameQueue> queue_;
  std::thread thread_;
};

}  // namespace pedtrack
