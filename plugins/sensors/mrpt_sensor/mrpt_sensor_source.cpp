// `mrpt_sensor`: any MRPT CGenericSensor driver (CHokuyoURG, CVelodyneScanner, ...) by class name,
// configured from its pipeline section with MRPT's own keys, so a rawlog-grabber section works
// unchanged once `plugin = mrpt_sensor` is added.
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/system/datetime.h>

#include <chrono>
#include <deque>
#include <thread>

#include "pedtrack/errors.h"
#include "pedtrack/plugin.h"
#include "pedtrack/text.h"

namespace pedtrack::mrpt_sensor {
namespace {

class MrptSensorSource : public Sensor {
 public:
  explicit MrptSensorSource(const PluginContext& ctx)
      : driver_(ctx.params.getString("driver")),
        idle_timeout_(ctx.params.getDouble("idle_timeout")),
        end_on_idle_(ctx.params.getBool("end_on_idle")) {
    sensor_ = mrpt::hwdrivers::CGenericSensor::createSensorPtr(driver_);
    if (!sensor_)
      throw ConfigError(
          "driver: '" + driver_ +
          "' is not an MRPT sensor class (e.g. CHokuyoURG, CVelodyneScanner, CSickLaserUSB)");
    try {
      sensor_->loadConfig(*ctx.config, ctx.section);
      sensor_->initialize();
    } catch (const std::exception& e) {
      throw ConfigError("driver: " + driver_ + " could not start: " + oneLine(e.what()));
    }
    period_ = sensor_->getProcessRate() > 0 ? 1.0 / sensor_->getProcessRate() : 0.01;
  }

  bool next(Frame& frame) override {
    auto last_data = std::chrono::steady_clock::now();
    while (queue_.empty()) {
      // A driver that stopped (device lost, or the end of a pcap/file input) ends the stream once
      // everything it produced has been handed out.
      if (stopped_) {
        if (end_on_idle_) return false;
        throw DataError(driver_ + ": the driver reports an error state");
      }
      try {
        sensor_->doProcess();
      } catch (const std::exception& e) {
        throw DataError(driver_ + ": " + oneLine(e.what()));
      }
      stopped_ = sensor_->getState() == mrpt::hwdrivers::CGenericSensor::ssError;
      for (const auto& [stamp, obj] : sensor_->getObservations()) {
        auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
        if (obs && isRangeObservation(*obs)) queue_.push_back(obs);
      }
      if (!queue_.empty() || stopped_) continue;
      const double idle =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - last_data).count();
      if (idle_timeout_ > 0 && idle > idle_timeout_) {
        if (end_on_idle_) return false;
        throw DataError(driver_ + ": no range data for " + std::to_string(idle_timeout_) + " s");
      }
      std::this_thread::sleep_for(std::chrono::duration<double>(period_));
    }
    auto obs = queue_.front();
    queue_.pop_front();
    frame.observations.push_back(obs);
    frame.t = mrpt::Clock::toDouble(obs->timestamp);
    obs->getSensorPose(frame.sensor_pose);  // no odometry from a lone sensor: robot = fixed frame
    frame.sensors.push_back({obs->sensorLabel, frame.sensor_pose});
    return true;
  }

 private:
  std::string driver_;
  double idle_timeout_;
  bool end_on_idle_;
  double period_ = 0.01;
  bool stopped_ = false;
  mrpt::hwdrivers::CGenericSensor::Ptr sensor_;
  std::deque<mrpt::obs::CObservation::Ptr> queue_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Live data from any MRPT sensor driver (CGenericSensor), configured with MRPT's keys";
  d.params = {
      ParamSpec::text(
          "driver", std::nullopt,
          "MRPT sensor class, as in rawlog-grabber (CHokuyoURG, CVelodyneScanner, ...)"),
      ParamSpec::real(
          "idle_timeout", 10.0, "s", 0, 3600,
          "fail (or end, see end_on_idle) after this long without range data; 0: wait forever"),
      ParamSpec::boolean("end_on_idle", false,
                         "treat idle_timeout or a stopped driver as the end of the stream (file "
                         "inputs, e.g. pcap_input)"),
  };
  d.accepts_other_keys = true;  // everything else is the driver's own MRPT configuration
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<MrptSensorSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::mrpt_sensor

PEDTRACK_PLUGIN("mrpt_sensor", pedtrack::mrpt_sensor::describe)
