// `mrpt_sensor`: any MRPT CGenericSensor driver (CHokuyoURG, CVelodyneScanner, ...) by class name,
// configured from its pipeline section with MRPT's own keys, so a rawlog-grabber section works
// unchanged once `plugin = mrpt_sensor` is added.
//
// A live device that fails is not the end of the run. Failures are counted (run.json) and warned
// about once; a driver in its error state is left to retry (CHokuyoURG reconnects a lost socket
// itself), one that throws or gives no range data for reconnect_after s is re-created after a
// back-off, a bounded number of times in a row. idle_timeout still ends or fails the stream.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/C2DRangeFinderAbstract.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/hwdrivers/CHokuyoURG.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/system/datetime.h>
#include <pthread.h>

#include <chrono>
#include <csignal>
#include <ctime>
#include <deque>
#include <iostream>
#include <thread>

#include "bounded_tcp_socket.h"
#include "device_timed_hokuyo.h"
#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/stop_request.h"
#include "pedtrack/text.h"

namespace pedtrack::mrpt_sensor {
namespace {

using Clock = std::chrono::steady_clock;

// MRPT's TCP client writes with send() without MSG_NOSIGNAL, so writing to a connection the device
// has reset raises SIGPIPE, whose default action kills the whole process. Around driver calls
// SIGPIPE is blocked on this thread, and one raised meanwhile is taken off before unblocking: the
// write fails instead and the driver sees a lost connection.
class SigpipeShield {
 public:
  SigpipeShield() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
  }
  ~SigpipeShield() {
    sigset_t pending;
    sigpending(&pending);
    if (!was_pending_ && sigismember(&pending, SIGPIPE) == 1) {
      const timespec now{0, 0};
      sigtimedwait(&pipe_, nullptr, &now);
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeShield(const SigpipeShield&) = delete;
  SigpipeShield& operator=(const SigpipeShield&) = delete;

 private:
  sigset_t pipe_, old_;
  bool was_pending_ = false;
};

double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

struct MrptSensorParams {
  std::string driver;          // an MRPT CGenericSensor class name
  double idle_timeout = 10.0;  // s
  bool end_on_idle = false;
  bool reconnect = true;
  double reconnect_after = 2.0;  // s
  double reconnect_delay = 0.5;  // s
  long max_reconnects = 10;
};

const ParamTable<MrptSensorParams>& table() {
  using P = MrptSensorParams;
  static const auto t =
      ParamTable<P>()
          .text(&P::driver, "driver",
                "MRPT sensor class, as in rawlog-grabber (CHokuyoURG, CVelodyneScanner, ...)")
          .required()
          .real(&P::idle_timeout, "idle_timeout", "s", 0, 3600,
                "fail (or end, see end_on_idle) after this long without range data; 0: wait "
                "forever")
          .boolean(&P::end_on_idle, "end_on_idle",
                   "treat idle_timeout or a stopped driver as the end of the stream (file "
                   "inputs, e.g. pcap_input)")
          .boolean(&P::reconnect, "reconnect",
                   "live devices: a driver that throws, reports an error or stalls is counted "
                   "and re-created instead of ending the run")
          .real(&P::reconnect_after, "reconnect_after", "s", 0, 3600,
                "re-create a live driver that gave no range data for this long; 0: only when "
                "it throws")
          .real(&P::reconnect_delay, "reconnect_delay", "s", 0, 60,
                "wait between dropping a failed driver and creating a new one")
          .integer(&P::max_reconnects, "max_reconnects", "", 0, 1000000,
                   "re-creations in a row without range data before the stream fails (or ends, "
                   "see end_on_idle); 0: no limit");
  return t;
}

class MrptSensorSource : public Sensor {
 public:
  explicit MrptSensorSource(const PluginContext& ctx)
      : MrptSensorSource(ctx, table().read(ctx.params)) {}
  MrptSensorSource(const PluginContext& ctx, const MrptSensorParams& p)
      : driver_(p.driver),
        section_(ctx.section),
        idle_timeout_(p.idle_timeout),
        end_on_idle_(p.end_on_idle),
        reconnect_(p.reconnect),
        reconnect_after_(p.reconnect_after),
        reconnect_delay_(p.reconnect_delay),
        max_reconnects_(p.max_reconnects) {
    // A copy of the configuration the driver reads: a reconnection configures a new driver from
    // it, whatever becomes of the pipeline's.
    std::vector<std::string> sections, keys;
    ctx.config->getAllSections(sections);
    for (const auto& sec : sections) {
      ctx.config->getAllKeys(sec, keys);
      for (const auto& k : keys) config_.write(sec, k, ctx.config->read_string(sec, k, ""));
    }
    try {
      open();
    } catch (const ConfigError&) {
      throw;
    } catch (const std::exception& e) {
      throw ConfigError("driver: " + driver_ + " could not start: " + oneLine(e.what()));
    }
    live_ = ctx.config->read_string(ctx.section, "pcap_input", "").empty();
    period_ = sensor_->getProcessRate() > 0 ? 1.0 / sensor_->getProcessRate() : 0.01;
  }

  // At the end of the run a driver that is delivering is stopped politely (see release()).
  ~MrptSensorSource() override {
    release(sensor_, !in_error_ && seconds(Clock::now() - last_data_) < 0.5);
  }

  // A device streams at its own pace; a file input (CVelodyneScanner's pcap_input) waits to be
  // read and must not lose frames.
  bool live() const override { return live_; }

  bool next(Frame& frame) override {
    const auto call_start = Clock::now();
    auto cycle_start = call_start;
    while (queue_.empty()) {
      // Asked to stop (SIGINT/SIGTERM): a live run's reading thread must not wait on a quiet
      // device for idle_timeout.
      if (live_ && stopRequested()) return false;
      // A driver that stopped (device lost for good, or the end of a pcap/file input) ends the
      // stream once everything it produced has been handed out.
      if (stopped_) {
        if (end_on_idle_) return false;
        throw DataError(driver_ + ": " + stop_reason_);
      }
      auto now = Clock::now();
      if (sensor_) {
        poll();
      } else if (now >= retry_at_) {
        reopen();
      }
      if (!queue_.empty() || stopped_) continue;
      now = Clock::now();
      // A live driver that produced nothing for reconnect_after s (counted from this call or from
      // its creation, whichever is later: data may wait in its buffers between calls) is
      // re-created. Some recover by themselves (CHokuyoURG reconnects a lost socket), not all
      // (CHokuyoURG never restarts a stream that a silent device did not start).
      if (sensor_ && reconnecting() && reconnect_after_ > 0 &&
          seconds(now - std::max(call_start, opened_at_)) > reconnect_after_) {
        ++stalls_;
        failed("no range data for " + shortNumber(reconnect_after_) + " s", false);
      }
      const double idle = seconds(now - call_start);
      if (idle_timeout_ > 0 && idle > idle_timeout_) {
        if (end_on_idle_) return false;
        throw DataError(driver_ + ": no range data for " + std::to_string(idle_timeout_) + " s");
      }
      // process_rate is a rate, as in rawlog-grabber: the time a call took counts. Drivers that
      // read one packet per call and wait inside it (CVelodyneScanner polls each of its sockets
      // for 1 ms) would otherwise fall behind a device sending 754 packets/s and lose data.
      std::this_thread::sleep_until(cycle_start + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(period_)));
      cycle_start = Clock::now();
    }
    auto obs = queue_.front();
    queue_.pop_front();
    frame.observations.push_back(obs);
    frame.t = mrpt::Clock::toDouble(obs->timestamp);
    obs->getSensorPose(frame.sensor_pose);  // no odometry from a lone sensor: robot = fixed frame
    frame.sensors.push_back({obs->sensorLabel, frame.sensor_pose});
    return true;
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    std::vector<std::pair<std::string, long>> c = {
        {"driver_errors", driver_errors_}, {"stalls", stalls_}, {"reconnects", reconnects_}};
    if (driver_ == "CHokuyoURG")
      c.emplace_back("startup_retries",
                     startup_retries_ + (hokuyo_ ? hokuyo_->startupRetries() : 0));
    return c;
  }

 private:
  bool reconnecting() const { return reconnect_ && live_; }

  void open() {
    SigpipeShield shield;
    // CHokuyoURG as MRPT's, but stamped by the device's clock from the first scan.
    mrpt::hwdrivers::CGenericSensor::Ptr s =
        driver_ == "CHokuyoURG" ? std::make_shared<DeviceTimedHokuyo>()
                                : mrpt::hwdrivers::CGenericSensor::createSensorPtr(driver_);
    if (!s)
      throw ConfigError(
          "driver: '" + driver_ +
          "' is not an MRPT sensor class (e.g. CHokuyoURG, CVelodyneScanner, CSickLaserUSB)");
    try {
      s->loadConfig(config_, section_);
      bindEthernetLink(*s);
      s->initialize();
    } catch (...) {
      release(s, false);
      throw;
    }
    sensor_ = std::move(s);
    hokuyo_ = dynamic_cast<DeviceTimedHokuyo*>(sensor_.get());  // looked up once, not per call
    opened_at_ = Clock::now();
    in_error_ = false;
  }

  // An Ethernet Hokuyo gets a link whose writes cannot hang (bounded_tcp_socket.h), connected here
  // as CHokuyoURG would connect its own: a refused connection throws the same way.
  void bindEthernetLink(mrpt::hwdrivers::CGenericSensor& s) const {
    auto* hokuyo = dynamic_cast<mrpt::hwdrivers::CHokuyoURG*>(&s);
    const std::string ip = config_.read_string(section_, "IP_DIR", "");
    if (!hokuyo || ip.empty()) return;
    auto link = std::make_shared<BoundedTcpSocket>();
    link->connect(ip, static_cast<unsigned short>(config_.read_int(section_, "PORT_DIR", 10940)));
    hokuyo->bindIO(link);
  }

  // Destroys a driver. A 2D range finder's destructor first tells the device to stop (CHokuyoURG
  // sends QT), but after a failed connection MRPT 2.5's own TCP client (a driver on a link this
  // source did not bind) still holds the dead socket, and its write loop retries the failing
  // send() for ever. So unless the driver has just delivered data, its I/O is unbound first and
  // the socket closes without a word to the device.
  static void release(mrpt::hwdrivers::CGenericSensor::Ptr& s, bool healthy) {
    SigpipeShield shield;  // the destructor may still talk to the device
    if (!healthy)
      if (auto* rf = dynamic_cast<mrpt::hwdrivers::C2DRangeFinderAbstract*>(s.get()))
        rf->bindIO(nullptr);
    s.reset();
  }

  // One doProcess() of the driver, keeping the range observations it made.
  void poll() {
    bool error = false;
    try {
      SigpipeShield shield;
      if (hokuyo_) hokuyo_->useDeviceClock();
      sensor_->doProcess();
      error = sensor_->getState() == mrpt::hwdrivers::CGenericSensor::ssError;
    } catch (const std::exception& e) {
      return failed(oneLine(e.what()), true);
    }
    for (const auto& [stamp, obj] : sensor_->getObservations()) {
      auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
      if (obs && isRangeObservation(*obs)) queue_.push_back(obs);
    }
    if (!queue_.empty()) {
      consecutive_reconnects_ = 0;
      last_data_ = Clock::now();
    }
    // Counted when the driver enters its error state; while it stays there it is retrying (a
    // live one may recover by itself; the stall check re-creates it otherwise).
    const bool entered = error && !in_error_;
    in_error_ = error;
    if (entered) {
      ++driver_errors_;
      if (!reconnecting()) return stop("the driver reports an error state");
      warnOnce("the driver reports an error state");
    }
  }

  // The driver threw (`error`) or stalled: drop it and try a new one after reconnect_delay.
  void failed(const std::string& why, bool error) {
    in_error_ = true;
    if (!reconnecting()) throw DataError(driver_ + ": " + why);
    if (error) ++driver_errors_;
    warnOnce(why);
    if (hokuyo_) startup_retries_ += hokuyo_->startupRetries();
    release(sensor_, false);
    hokuyo_ = nullptr;
    retry_at_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(reconnect_delay_));
  }

  void reopen() {
    if (max_reconnects_ > 0 && consecutive_reconnects_ >= max_reconnects_)
      return stop("no range data after " + std::to_string(max_reconnects_) +
                  " reconnections in a row");
    ++reconnects_;
    ++consecutive_reconnects_;
    try {
      open();
    } catch (const std::exception& e) {
      failed(oneLine(e.what()), true);
    }
  }

  void stop(const std::string& why) {
    stopped_ = true;
    stop_reason_ = why;
  }

  // One line on the first failure; the rest only in the counters (run.json), so a device that
  // keeps failing does not flood the log.
  void warnOnce(const std::string& why) {
    if (warned_) return;
    warned_ = true;
    std::cerr << "warning: mrpt_sensor: " << driver_ << ": " << why
              << "; going on, reconnecting when needed (counted in run.json: driver_errors, "
                 "stalls, reconnects)\n";
  }

  std::string driver_, section_;
  mrpt::config::CConfigFileMemory config_;
  DeviceTimedHokuyo* hokuyo_ = nullptr;  // sensor_ when it is a CHokuyoURG, else null
  double idle_timeout_;
  bool end_on_idle_;
  bool reconnect_;
  double reconnect_after_, reconnect_delay_;
  long max_reconnects_;
  double period_ = 0.01;
  bool stopped_ = false;
  std::string stop_reason_;
  bool live_ = true;
  bool in_error_ = false, warned_ = false;
  long driver_errors_ = 0, stalls_ = 0, reconnects_ = 0, consecutive_reconnects_ = 0;
  long startup_retries_ = 0;  // of the drivers already released
  Clock::time_point opened_at_, retry_at_, last_data_;
  mrpt::hwdrivers::CGenericSensor::Ptr sensor_;
  std::deque<mrpt::obs::CObservation::Ptr> queue_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Live data from any MRPT sensor driver (CGenericSensor), configured with MRPT's keys";
  d.params = table().specs();
  d.accepts_other_keys = true;  // everything else is the driver's own MRPT configuration
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<MrptSensorSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::mrpt_sensor

PEDTRACK_PLUGIN("mrpt_sensor", pedtrack::mrpt_sensor::describe)
