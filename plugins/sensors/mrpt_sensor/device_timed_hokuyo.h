// CHokuyoURG stamping every scan with the device's own clock, from the first scan of a
// connection on.
//
// Why: MRPT 2.5's CHokuyoURG stamps the first 10 scans after it connects with the host's time of
// arrival, and only then anchors the device clock (each scan carries the time it was taken, in
// ms). When the reader stalls in that window (a loaded machine: 0.7 s was enough), the scans
// queued meanwhile arrive in a burst stamped 0-0.3 ms apart, although a 10 Hz scanner took them
// 100 ms apart. Trackers read that as legs moving metres in no time: a person walking in was
// never confirmed for the rest of a live session (test_hokuyo_loopback). With the device clock
// from the first scan the stamps keep the scanner's real spacing whatever the host does; the
// anchor (host time of the first scan) can only be late by the stall, the same for every scan.
#pragma once

#include <mrpt/hwdrivers/CHokuyoURG.h>

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
};

}  // namespace pedtrack::mrpt_sensor
