// CHokuyoURG stamping every scan with the device's own clock, from the first scan of a
// connection on, and trying its start-up again when one reply is late.
//
// Why: MRPT 2.5's CHokuyoURG stamps the first 10 scans after it connects with the host's time of
// arrival, and only then anchors the device clock (each scan carries the time it was taken, in
// ms). When the reader stalls in that window (a loaded machine: 0.7 s was enough), the scans
// queued meanwhile arrive in a burst stamped 0-0.3 ms apart, although a 10 Hz scanner took them
// 100 ms apart. Trackers read that as legs moving metres in no time: a person walking in was
// never confirmed for the rest of a live session (test_hokuyo_loopback). With the device clock
// from the first scan the stamps keep the scanner's real spacing whatever the host does; the
// anchor (host time of the first scan) can only be late by the stall, the same for every scan.
//
// Why the start-up retry: MRPT's start-up (turnOn: QT, SS, SCIP2.0, BM, HS, PP, VV, MD) waits
// 200 ms for each reply on a serial line (its fixed read timeouts). A device that answers
// nothing for about 1.5 s (a host too busy to run its USB link or, in the tests, the loopback
// device's thread: the Hokuyo loopback flake of #13) fails both start-ups MRPT runs (one when the
// port opens, one in initialize()); the driver then sat in its error state until mrpt_sensor
// re-created it after reconnect_after + reconnect_delay (2.5 s) and another start-up. Here the
// start-up is tried again at once, after the late replies are purged, up to kStartupAttempts
// times (unless the run is asked to stop), and counted (startup_retries in run.json).
#pragma once

#include <mrpt/hwdrivers/CHokuyoURG.h>

#include <chrono>
#include <thread>

#include "pedtrack/stop_request.h"

namespace pedtrack::mrpt_sensor {

class DeviceTimedHokuyo : public mrpt::hwdrivers::CHokuyoURG {
 public:
  // MRPT's count of scans stamped by arrival before the device clock is used (its
  // MINIMUM_PACKETS_TO_SET_TIMESTAMP_REFERENCE, a constant of CHokuyoURG.cpp).
  static constexpr int kArrivalStampedScans = 10;

  // Called before each doProcess(): the delay counter, which the driver resets when it loses the
  // device, is kept spent. Nothing changes with disable_firmware_timestamp = true (host time
  // for every scan, as asked).
  void useDeviceClock() {
    if (!m_disable_firmware_timestamp) m_timeStartSynchDelay = kArrivalStampedScans;
  }

  // Five start-ups take about 6 s when nothing answers: a device starved for a few seconds on a
  // loaded host still comes up without an error; a dead one is then re-created by mrpt_sensor.
  static constexpr int kStartupAttempts = 5;

  // MRPT's initialize() (open the link, turnOn()) with the start-up tried again when it fails.
  void initialize() override {
    if (!ensureStreamIsOpen()) return;
    for (int attempt = 1; attempt <= kStartupAttempts; ++attempt) {
      if (turnOn()) return;
      if (attempt == kStartupAttempts || pedtrack::stopRequested()) break;
      ++startup_retries_;
      // The late replies arrive meanwhile; purged, they cannot be taken for the next ones.
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      purgeBuffers();
    }
    MRPT_LOG_ERROR("[Hokuyo] Error initializing HOKUYO scanner");
  }

  /// Start-ups tried again because one failed (a reply came too late).
  long startupRetries() const { return startup_retries_; }

 private:
  long startup_retries_ = 0;
};

}  // namespace pedtrack::mrpt_sensor
