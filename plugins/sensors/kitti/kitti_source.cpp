// `kitti` sensor: replays KITTI Velodyne HDL-64 scans (`.bin`: float32 x, y, z, reflectance per
// point), one file or a folder of them as a sequence, with the vehicle's motion from its OXTS
// (GPS/IMU) records when there are any. The robot frame stands on the road under the scanner.
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/system/datetime.h>

#include <filesystem>
#include <optional>

#include "kitti_sequence.h"
#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"

namespace pedtrack::kitti {
namespace {

struct KittiParams {
  std::string file;
  KittiRig rig;
  std::string oxts = "auto";
  ReplayRateParams replay;
};

const ParamTable<KittiParams>& table() {
  using P = KittiParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::file, "file",
                     "a KITTI Velodyne scan (.bin) or a folder of them, replayed in name order "
                     "(raw velodyne_points/data, tracking velodyne/SSSS, object velodyne)",
                     /*folder_ok=*/true)
          .include(&P::rig, kittiRigTable())
          .text(&P::oxts, "oxts",
                "the vehicle's OXTS records: auto (raw oxts/data beside velodyne_points, or "
                "tracking oxts/SSSS.txt), none (no motion known), a folder (a file per scan) or "
                "a file (a line per scan)")
          .include(&P::replay, replayRateTable());
  return t;
}

class KittiSource : public Sensor {
 public:
  explicit KittiSource(const PluginContext& ctx)
      : KittiSource(table().read(ctx.params), table().where(ctx.params, &KittiParams::oxts)) {}
  KittiSource(const KittiParams& p, const std::string& oxts_where)
      : scans_(listScans(p.file, p.rig.scan_rate)),
        mount_(0, 0, p.rig.mount_z, 0, 0, 0),
        realtime_(p.replay.realtime) {
    const std::string oxts = p.oxts == "auto" ? findOxts(p.file) : p.oxts == "none" ? "" : p.oxts;
    if (p.oxts != "auto" && p.oxts != "none" && !std::filesystem::exists(p.oxts))
      throw ConfigError(oxts_where + ": '" + p.oxts + "' does not exist");
    if (!oxts.empty()) oxts_.emplace(oxts, p.rig);
  }

  bool next(Frame& frame) override {
    if (done_ >= scans_.size()) return false;
    const Scan& s = scans_[done_];
    auto obs = mrpt::obs::CObservationPointCloud::Create();
    obs->pointcloud = readScan(s.path);
    obs->sensorPose = mount_;
    obs->sensorLabel = "velodyne";
    obs->timestamp = mrpt::Clock::fromDouble(s.t);
    frame.t = s.t;
    if (oxts_) {
      frame.robot_pose = oxts_->robotPose(s.index);
      frame.has_odometry = true;
    }
    frame.observations.push_back(obs);
    frame.sensor_pose = frame.robot_pose + mount_;
    frame.sensors.push_back({obs->sensorLabel, frame.sensor_pose});
    ++done_;
    if (realtime_) pacer_.wait(frame.t);
    return true;
  }

  double progress() const override { return double(done_) / double(scans_.size()); }

 private:
  std::vector<Scan> scans_;
  mrpt::poses::CPose3D mount_;
  std::optional<OxtsTrajectory> oxts_;
  bool realtime_;
  std::size_t done_ = 0;
  ReplayPacer pacer_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Replays KITTI Velodyne scans (.bin, or a folder of them) with OXTS motion if any";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<KittiSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::kitti

PEDTRACK_PLUGIN("kitti", pedtrack::kitti::describe)
