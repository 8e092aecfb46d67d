#pragma once
// Paces a replay so frames come out at the rate they were recorded (`rate = realtime`).
#include <chrono>

#include "pedtrack/param_table.h"

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

/// The `rate` key every replaying source declares (include() it into the source's table).
struct ReplayRateParams {
  bool realtime = false;  ///< paced by the data's own timestamps, not as fast as possible
};
const ParamTable<ReplayRateParams>& replayRateTable();

}  // namespace pedtrack
