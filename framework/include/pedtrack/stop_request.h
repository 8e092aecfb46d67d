#pragma once
// The process-wide request to stop: set by SIGINT/SIGTERM handlers (and tests); sources, the
// frame supply and long commands check it between frames, so a run ends after the current frame
// and still writes its outputs.
#include <atomic>

namespace pedtrack {

/// The flag itself: `stopRequested() = true` asks every loop to end after its current step.
std::atomic<bool>& stopRequested();

}  // namespace pedtrack
