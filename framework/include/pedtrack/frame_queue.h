#pragma once
// The bounded queue between a live source's thread and the pipeline's stages. A live device
// sends data whether or not the stages are ready; when they fall behind, the oldest waiting
// frame is dropped (counted), so the output stays current and memory stays bounded instead of
// the queue growing and every output coming later and later.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>

#include "pedtrack/frame.h"

namespace pedtrack {

class FrameQueue {
 public:
  using Clock = std::chrono::steady_clock;
  struct Item {
    Frame frame;
    Clock::time_point arrival;  ///< when the source handed the frame over
  };

  explicit FrameQueue(std::size_t capacity);
  /// Adds a frame; when the queue is full the oldest waiting one is dropped first.
  void push(Frame&& frame, Clock::time_point arrival);
  /// No more frames will come (the source ended or failed).
  void close();
  /// Waits up to `wait` for a frame. False when none came in time, or when the queue is closed
  /// and empty (then closedAndEmpty() is true).
  bool pop(Item& out, std::chrono::milliseconds wait);
  bool closedAndEmpty() const;
  std::size_t dropped() const;

 private:
  const std::size_t capacity_;
  mutable std::mutex m_;
  std::condition_variable cv_;
  std::deque<Item> items_;
  std::size_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace pedtrack
