#include "pedtrack/frame_supply.h"

namespace pedtrack {

FrameSupply::FrameSupply(Sensor& source, const RunOptions& options, RawlogRecorder* recorder)
    : source_(source), max_frames_(options.max_frames), recorder_(recorder), live_(source.live()) {
  if (!live_) return;
  queue_ = std::make_unique<FrameQueue>(options.live_queue);
  thread_ = std::thread([this] { readLoop(); });
}

FrameSupply::~FrameSupply() {
  stop();
}

bool FrameSupply::read(Frame& frame, Clock::time_point& arrival) {
  if (max_frames_ >= 0 && static_cast<long>(read_) >= max_frames_) return false;
  frame = Frame();
  frame.index = read_;
  try {
    if (!source_.next(frame)) return false;
    arrival = Clock::now();
    if (recorder_) recorder_->write(frame);
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
  ++read_;
  return true;
}

void FrameSupply::readLoop() {
  Frame frame;
  Clock::time_point arrival;
  while (!stop_ && !stopRequested() && read(frame, arrival))
    queue_->push(std::move(frame), arrival);
  queue_->close();
}

bool FrameSupply::next(Frame& frame, Clock::time_point& arrival) {
  if (!live_) return !stopRequested() && read(frame, arrival);
  FrameQueue::Item item;
  // Short waits, so a stop request is seen while the device is quiet.
  while (!stopRequested()) {
    if (queue_->pop(item, std::chrono::milliseconds(50))) {
      frame = std::move(item.frame);
      arrival = item.arrival;
      return true;
    }
    if (queue_->closedAndEmpty()) return false;
  }
  return false;
}

void FrameSupply::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

}  // namespace pedtrack
