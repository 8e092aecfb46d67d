// `velodyne_udp`: a live Velodyne VLP-16 read straight from its data port. MRPT's
// CVelodyneScanner reads one packet per doProcess() call and polls its position socket for 1 ms
// in each, so a host that is busy for a moment loses packets in the kernel and nobody counts
// them. Here a thread of its own drains the socket in batches (udp_batch_reader.h) into whole
// revolutions (revolution_assembler.h), which wait in a bounded queue for the pipeline: when the
// pipeline falls behind, the oldest whole revolution is dropped and counted, never a torn one.
// What was lost on the way is in run.json: packets missing from the device's timestamps
// (`packets_lost`), datagrams the kernel dropped (`kernel_drops`), revolutions dropped here.
// MRPT's driver (mrpt_sensor) stays the path for other sensors and for pcap replay.
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/stop_request.h"
#include "pedtrack/text.h"
#include "velodyne_udp/revolution_assembler.h"
#include "velodyne_udp/udp_batch_reader.h"

namespace pedtrack::velodyne_udp {
namespace {

using Clock = std::chrono::steady_clock;
using Velo = mrpt::obs::CObservationVelodyneScan;
constexpr double kDeg = M_PI / 180;

struct VelodyneUdpParams {
  std::string address = "0.0.0.0";
  long port = 2368;
  long rcvbuf = 8 << 20;
  long batch = 64;
  long queue = 10;
  double min_range = 0.4, max_range = 100;
  std::string label = "VELODYNE";
  double pose_x = 0, pose_y = 0, pose_z = 0, pose_yaw = 0, pose_pitch = 0, pose_roll = 0;
  double idle_timeout = 10;
  bool end_on_idle = false;
};

const ParamTable<VelodyneUdpParams>& table() {
  using P = VelodyneUdpParams;
  static const auto t =
      ParamTable<P>()
          .text(&P::address, "address", "local IPv4 address to listen on (0.0.0.0: every one)")
          .integer(&P::port, "port", "", 0, 65535,
                   "UDP data port the sensor sends to (VLP-16 default 2368; 0: any free port)")
          .integer(&P::rcvbuf, "rcvbuf", "bytes", 65536, 1 << 30,
                   "socket receive buffer asked for (granted up to net.core.rmem_max unless "
                   "root; run.json rcvbuf_bytes says what was)")
          .integer(&P::batch, "batch", "packets", 1, 1024, "datagrams taken per recvmmsg() call")
          .integer(&P::queue, "queue", "revolutions", 1, 10000,
                   "whole revolutions waiting for the pipeline; beyond it the oldest is dropped "
                   "(revolutions_dropped)")
          .real(&P::min_range, "min_range", "m", 0, 10, "returns closer than this are dropped")
          .real(&P::max_range, "max_range", "m", 1, 300, "returns farther than this are dropped")
          .text(&P::label, "label", "sensor label of the observations")
          .real(&P::pose_x, "pose_x", "m", -100, 100, "sensor mount on the robot: x")
          .real(&P::pose_y, "pose_y", "m", -100, 100, "sensor mount: y")
          .real(&P::pose_z, "pose_z", "m", -100, 100, "sensor mount: z (height above ground)")
          .real(&P::pose_yaw, "pose_yaw", "deg", -360, 360, "sensor mount: yaw")
          .real(&P::pose_pitch, "pose_pitch", "deg", -90, 90, "sensor mount: pitch")
          .real(&P::pose_roll, "pose_roll", "deg", -180, 180, "sensor mount: roll")
          .real(&P::idle_timeout, "idle_timeout", "s", 0, 3600,
                "fail (or end, see end_on_idle) after this long without a revolution; 0: wait "
                "forever")
          .boolean(&P::end_on_idle, "end_on_idle",
                   "treat idle_timeout as the end of the stream (a replay sent to the port)");
  return t;
}

class VelodyneUdpSource : public Sensor {
 public:
  explicit VelodyneUdpSource(const PluginContext& ctx)
      : VelodyneUdpSource(table().read(ctx.params)) {}
  explicit VelodyneUdpSource(const VelodyneUdpParams& p)
      : reader_(p.address, int(p.port), int(p.rcvbuf), int(p.batch)),
        queue_cap_(std::size_t(p.queue)),
        min_range_(p.min_range),
        max_range_(p.max_range),
        label_(p.label),
        mount_(p.pose_x, p.pose_y, p.pose_z, p.pose_yaw * kDeg, p.pose_pitch * kDeg,
               p.pose_roll * kDeg),
        idle_timeout_(p.idle_timeout),
        end_on_idle_(p.end_on_idle) {
    if (p.min_range >= p.max_range) throw ConfigError("min_range: not below max_range");
    calibration_ = mrpt::obs::VelodyneCalibration::LoadDefaultCalibration("VLP16");
    thread_ = std::thread([this] { readLoop(); });
  }

  ~VelodyneUdpSource() override {
    stop_ = true;
    thread_.join();
  }

  bool live() const override { return true; }

  bool next(Frame& frame) override {
    const auto since = Clock::now();
    Revolution rev;
    {
      std::unique_lock<std::mutex> lk(m_);
      while (queue_.empty()) {
        if (!error_.empty()) throw DataError("velodyne_udp: " + error_);
        if (stopRequested()) return false;
        const double idle = std::chrono::duration<double>(Clock::now() - since).count();
        if (idle_timeout_ > 0 && idle > idle_timeout_) {
          if (end_on_idle_) return false;
          throw DataError("velodyne_udp: no revolution for " + shortNumber(idle_timeout_) + " s");
        }
        cv_.wait_for(lk, std::chrono::milliseconds(100));
      }
      rev = std::move(queue_.front());
      queue_.pop_front();
    }
    auto obs = Velo::Create();
    obs->sensorLabel = label_;
    obs->timestamp = mrpt::Clock::fromDouble(rev.t);
    obs->originalReceivedTimestamp = obs->timestamp;
    obs->sensorPose = mount_;
    obs->minRange = min_range_;
    obs->maxRange = max_range_;
    obs->calibration = calibration_;
    obs->scan_packets = std::move(rev.packets);
    frame.observations.push_back(obs);
    frame.t = rev.t;
    frame.sensor_pose = mount_;  // a lone sensor: the robot is the fixed frame
    frame.sensors.push_back({label_, mount_});
    return true;
  }

  std::vector<std::pair<std::string, long>> counters() const override {
    std::lock_guard<std::mutex> lk(m_);
    return {{"packets", assembler_.packets()},
            {"packets_lost", assembler_.lostPackets()},
            {"kernel_drops", long(reader_.kernelDrops())},
            {"bad_packets", assembler_.badPackets()},
            {"dual_return_packets", assembler_.dualReturnPackets()},
            {"revolutions", revolutions_},
            {"revolutions_dropped", revolutions_dropped_},
            {"rcvbuf_bytes", reader_.receiveBuffer()}};
  }

 private:
  // The reading thread: drains the socket, never waits for the pipeline.
  void readLoop() {
    Revolution done;
    try {
      while (!stop_) {
        reader_.read(100, [&](const std::uint8_t* d, std::size_t n, double t) {
          std::lock_guard<std::mutex> lk(m_);  // the counters are read by the pipeline
          if (!assembler_.add(d, n, t, done)) return;
          ++revolutions_;
          if (queue_.size() >= queue_cap_) {  // the pipeline is behind: drop the oldest, whole
            queue_.pop_front();
            ++revolutions_dropped_;
          }
          queue_.push_back(std::move(done));
          cv_.notify_one();
        });
      }
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lk(m_);
      error_ = oneLine(e.what());
      cv_.notify_one();
    }
  }

  UdpBatchReader reader_;
  std::size_t queue_cap_;
  double min_range_, max_range_;
  std::string label_;
  mrpt::poses::CPose3D mount_;
  double idle_timeout_;
  bool end_on_idle_;
  mrpt::obs::VelodyneCalibration calibration_;
  mutable std::mutex m_;  // guards everything below
  std::condition_variable cv_;
  RevolutionAssembler assembler_;
  std::deque<Revolution> queue_;
  long revolutions_ = 0, revolutions_dropped_ = 0;
  std::string error_;
  std::atomic<bool> stop_{false};
  std::thread thread_;  // last: it starts once everything it uses exists
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc =
      "Live Velodyne VLP-16 from its UDP data port: batched reads on a thread of their own, "
      "whole revolutions, lost packets counted";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<VelodyneUdpSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::velodyne_udp

PEDTRACK_PLUGIN("velodyne_udp", pedtrack::velodyne_udp::describe)
