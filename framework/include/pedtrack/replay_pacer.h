#pragma once
// Paces a replay so frames come out at the rate they were recorded (`rate = realtime`).
#include <chrono>

namespace pedtrack {

class ReplayPacer {
 public:
  /// Sleeps until the wall clock has advanced as far since the first call as `t` (UNIX seconds)
  /// has advanced since the first `t`.
  void wait(double t);

 private:
  bool started_ = false;
  double t0_ = 0;
  std::chrono::steady_clock::time_point wall0_;
};

}  // namespace pedtrack
