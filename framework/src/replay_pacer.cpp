#include "pedtrack/replay_pacer.h"

#include <thread>

namespace pedtrack {

void ReplayPacer::wait(double t) {
  const auto now = std::chrono::steady_clock::now();
  if (!started_) {
    started_ = true;
    t0_ = t;
    wall0_ = now;
    return;
  }
  const auto due = wall0_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(t - t0_));
  if (due > now) std::this_thread::sleep_until(due);
}

const ParamTable<ReplayRateParams>& replayRateTable() {
  static const auto t = ParamTable<ReplayRateParams>().choice(
      &ReplayRateParams::realtime, "rate", {{"max", false}, {"realtime", true}},
      "max: as fast as the pipeline runs; realtime: at the pace the data was recorded (its "
      "timestamps)");
  return t;
}

}  // namespace pedtrack
