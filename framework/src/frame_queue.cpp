#include "pedtrack/frame_queue.h"

#include <algorithm>

namespace pedtrack {

FrameQueue::FrameQueue(std::size_t capacity) : capacity_(std::max<std::size_t>(1, capacity)) {}

void FrameQueue::push(Frame&& frame, Clock::time_point arrival) {
  {
    std::lock_guard<std::mutex> lock(m_);
    while (items_.size() >= capacity_) {
      items_.pop_front();
      ++dropped_;
    }
    items_.push_back({std::move(frame), arrival});
  }
  cv_.notify_one();
}

void FrameQueue::close() {
  {
    std::lock_guard<std::mutex> lock(m_);
    closed_ = true;
  }
  cv_.notify_all();
}

bool FrameQueue::pop(Item& out, std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(m_);
  if (!cv_.wait_for(lock, wait, [this] { return !items_.empty() || closed_; })) return false;
  if (items_.empty()) return false;  // closed
  out = std::move(items_.front());
  items_.pop_front();
  return true;
}

bool FrameQueue::closedAndEmpty() const {
  std::lock_guard<std::mutex> lock(m_);
  return closed_ && items_.empty();
}

std::size_t FrameQueue::dropped() const {
  std::lock_guard<std::mutex> lock(m_);
  return dropped_;
}

}  // namespace pedtrack
