// `sim` sensor: runs a simulation scenario (configs/scenarios/*.ini) live, frame by frame, so a
// pipeline sees exactly what `pedtrack sim` would write to a rawlog — without the file.
#include <filesystem>
#include <memory>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"
#include "pedtrack/plugin.h"
#include "pedtrack/replay_pacer.h"
#include "pedtrack/sim/simulator.h"

namespace pedtrack::simsource {
namespace {

// The scenario with its [scenario] duration replaced when `duration` > 0: shorter for a quick
// look, longer for a soak (a [crowd]'s random walkers keep choosing new goals).
sim::Scenario withDuration(sim::Scenario s, double duration) {
  if (duration > 0) s.duration = duration;
  return s;
}

struct SimParams {
  std::string scenario;
  long seed = -1;       // -1: the scenario's own
  double duration = 0;  // s, 0: the scenario's own
  ReplayRateParams rate;
  std::string truth = "auto";  // auto (truth.csv in --out), none, or a path
  bool point_truth = true;
  bool odometry = true;
};

const ParamTable<SimParams>& table() {
  using P = SimParams;
  static const auto t =
      ParamTable<P>()
          .inputFile(&P::scenario, "scenario", "scenario file (configs/scenarios/*.ini)")
          .integer(&P::seed, "seed", "", -1, 4294967295.0,
                   "random seed (-1: the scenario's own [scenario] seed)")
          .real(&P::duration, "duration", "s", 0, 36000,
                "simulated time (0: the scenario's own [scenario] duration)")
          .include(&P::rate, replayRateTable())
          .text(&P::truth, "truth",
                "ground truth CSV: auto = truth.csv in the run's --out, none, or a path")
          .boolean(&P::point_truth, "point_truth",
                   "also write truth_points.bin (what each return hit) next to the truth CSV")
          .boolean(&P::odometry, "odometry",
                   "false: the frames carry no robot motion (a robot without wheel odometry: "
                   "the robot stays at the origin, has_odometry is false); score such runs in "
                   "the sensor frame (pedtrack eval --frame sensor)");
  return t;
}

class SimSource : public Sensor {
 public:
  explicit SimSource(const PluginContext& ctx)
      : SimSource(table().read(ctx.params), table().where(ctx.params, &SimParams::truth)) {}
  SimSource(const SimParams& p, std::string truth_where)
      : sim_(withDuration(sim::loadScenario(p.scenario, p.seed), p.duration)),
        realtime_(p.rate.realtime),
        truth_key_(p.truth),
        point_truth_(p.point_truth),
        odometry_(p.odometry),
        where_(std::move(truth_where)) {}

  void finish() override {
    if (truth_) truth_->close();
    if (point_truth_out_) point_truth_out_->close();
  }

  void start(const std::string& out_dir) override {
    // auto: next to the run's tracks.csv; none: nowhere; anything else: that path.
    std::string path = truth_key_;
    if (truth_key_ == "auto") path = out_dir.empty() ? "" : out_dir + "/truth.csv";
    sim_.setPointTruth(false);  // on again below when it is written
    if (truth_key_ == "none" || path.empty()) return;
    std::error_code ec;
    if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
      std::filesystem::create_directories(dir, ec);
    // Per-point truth goes next to truth.csv.
    const std::string points =
        (std::filesystem::path(path).parent_path() / "truth_points.bin").string();
    try {
      truth_ = std::make_unique<sim::TruthCsvWriter>(path);
      if (point_truth_)
        point_truth_out_ = std::make_unique<LabelFileWriter>(points, LabelKind::Truth);
      sim_.setPointTruth(point_truth_);
    } catch (const DataError&) {
      throw ConfigError(where_ + ": cannot write '" + (truth_ ? points : path) + "'");
    }
  }

  bool next(Frame& frame) override {
    sim::SimFrame f;
    if (!sim_.next(f)) return false;
    frame.t = f.t;
    // Without odometry (a wheelchair with no wheel encoders) the robot stays at the identity and
    // nothing says it moves, as with a bag that has no /tf.
    frame.robot_pose = odometry_ ? f.robot_odometry : mrpt::poses::CPose3D();
    frame.has_odometry = odometry_;  // with it, a standing scanner's is the identity, and known
    // The scan (the odometry observation's content is the robot pose itself).
    frame.observations.push_back(f.observations.back());
    frame.sensor_pose = frame.robot_pose + sim_.scenario().sensor.mount;
    frame.sensors.push_back({frame.observations.back()->sensorLabel, frame.sensor_pose});
    if (truth_) truth_->write(f);
    if (point_truth_out_) point_truth_out_->write(sim::pointTruth(f));
    done_ = f.index + 1;
    if (realtime_) pacer_.wait(frame.t);
    return true;
  }

  double progress() const override {
    return sim_.frameCount() ? double(done_) / sim_.frameCount() : -1;
  }

 private:
  sim::Simulator sim_;
  bool realtime_;
  std::string truth_key_, where_;
  bool point_truth_;
  bool odometry_;
  std::unique_ptr<sim::TruthCsvWriter> truth_;
  std::unique_ptr<LabelFileWriter> point_truth_out_;
  std::size_t done_ = 0;
  ReplayPacer pacer_;
};

PluginDescriptor describe() {
  PluginDescriptor d;
  d.category = Category::Sensor;
  d.doc = "Simulates a scenario (people, objects, 2D Hokuyo or VLP-16) and yields its scans";
  d.params = table().specs();
  d.create = [](const PluginContext& ctx) -> std::unique_ptr<Plugin> {
    return std::make_unique<SimSource>(ctx);
  };
  return d;
}

}  // namespace
}  // namespace pedtrack::simsource

PEDTRACK_PLUGIN("sim", pedtrack::simsource::describe)
