#include "pedtrack/fault_injection.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <set>

#include "pedtrack/errors.h"
#include "pedtrack/frame.h"
#include "pedtrack/param_table.h"
#include "pedtrack/text.h"
#include "pedtrack/velodyne_decode.h"

namespace pedtrack {
namespace {

using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CObservationVelodyneScan;

constexpr double kInf = std::numeric_limits<double>::infinity();

struct FaultParams {
  long seed = 1;
  double nonfinite_ranges = 0, zero_ranges = 0, max_ranges = 0;  // fractions of returns
  long empty_every = 0, blind_at = -1, blind_frames = 30, drop_every = 0;
  std::string huge_cloud_at;  // frame lists: numbers separated by spaces or commas
  long huge_cloud_points = 1000000;
  std::string repeat_time_at, backwards_time_at, jump_time_at;
  double time_jump = 600;  // s
  std::string nan_time_at, odometry_jump_at;
  double odometry_jump = 5;  // m
};

const ParamTable<FaultParams>& table() {
  using P = FaultParams;
  static const auto t =
      ParamTable<P>()
          .integer(&P::seed, "seed", "", 0, 4294967295.0, "random seed of the range faults")
          .real(&P::nonfinite_ranges, "nonfinite_ranges", "", 0, 1,
                "fraction of returns made NaN or +inf (flagged valid, as a buggy driver would); a "
                "VLP-16 revolution is turned into a point cloud first")
          .real(&P::zero_ranges, "zero_ranges", "", 0, 1, "fraction of returns made 0 m")
          .real(&P::max_ranges, "max_ranges", "", 0, 1,
                "fraction of returns put at the scanner's maximum range (100 m for clouds)")
          .integer(&P::empty_every, "empty_every", "frames", 0, 1e9,
                   "every N-th frame's scans and clouds are emptied (0: never)")
          .integer(&P::blind_at, "blind_at", "frame", -1, 1e9,
                   "from this frame the sensor is blind (every scan and cloud empty) for "
                   "blind_frames frames (-1: never)")
          .integer(&P::blind_frames, "blind_frames", "frames", 1, 1e9,
                   "how long the sensor is blind")
          .integer(&P::drop_every, "drop_every", "frames", 0, 1e9,
                   "every N-th frame of the source is never delivered (0: never)")
          .text(&P::huge_cloud_at, "huge_cloud_at",
                "frames (0-based, of the source) that get an extra cloud of huge_cloud_points "
                "points")
          .integer(&P::huge_cloud_points, "huge_cloud_points", "", 1, 1e8,
                   "points of that cloud, spread over 60 m x 60 m x 3 m")
          .text(&P::repeat_time_at, "repeat_time_at",
                "frames stamped with the previous frame's time")
          .text(&P::backwards_time_at, "backwards_time_at",
                "frames stamped 1 s before the previous frame")
          .text(&P::jump_time_at, "jump_time_at",
                "frames from which every stamp is time_jump later")
          .real(&P::time_jump, "time_jump", "s", -1e9, 1e9, "size of each time jump")
          .text(&P::nan_time_at, "nan_time_at", "frames stamped NaN")
          .text(&P::odometry_jump_at, "odometry_jump_at",
                "frames from which the robot pose is odometry_jump further along x")
          .real(&P::odometry_jump, "odometry_jump", "m", -1e6, 1e6, "size of each odometry jump");
  return t;
}

// The frame numbers of a frame-list key (`member` of `f`).
std::set<long> frameSet(const ParamSet& p, const FaultParams& f, std::string FaultParams::*member) {
  std::set<long> out;
  const std::string& text = f.*member;
  if (text.empty()) return out;
  const std::string where = table().where(p, member);
  for (const double v : parseNumbers(text, 0, where)) {
    if (v < 0 || v != std::floor(v))
      throw ConfigError(where + ": '" + text + "': frame numbers are whole numbers from 0");
    out.insert(static_cast<long>(v));
  }
  return out;
}

// A VLP-16 revolution as the point cloud a ROS driver would publish (sensor frame): the
// range faults then reach single points, which raw packets of integer ranges cannot carry.
mrpt::obs::CObservation::Ptr asPointCloud(const CObservationVelodyneScan& velo) {
  auto pc = CObservationPointCloud::Create();
  auto map = mrpt::maps::CSimplePointsMap::Create();
  if (velo.calibration.laser_corrections.size() == 16) {
    for (const auto& p : decodeVelodyne(velo)) map->insertPointFast(p.x, p.y, p.z);
  }
  map->mark_as_modified();
  pc->pointcloud = map;
  pc->sensorPose = velo.sensorPose;
  pc->sensorLabel = velo.sensorLabel;
  pc->timestamp = velo.timestamp;
  return pc;
}

class FaultInjector : public Sensor {
 public:
  FaultInjector(std::unique_ptr<Sensor> inner, const ParamSet& p)
      : FaultInjector(std::move(inner), p, table().read(p)) {}
  FaultInjector(std::unique_ptr<Sensor> inner, const ParamSet& p, const FaultParams& f)
      : inner_(std::move(inner)),
        rng_(static_cast<std::uint32_t>(f.seed)),
        nonfinite_(f.nonfinite_ranges),
        zero_(f.zero_ranges),
        max_(f.max_ranges),
        empty_every_(f.empty_every),
        blind_at_(f.blind_at),
        blind_frames_(f.blind_frames),
        drop_every_(f.drop_every),
        huge_points_(f.huge_cloud_points),
        time_jump_(f.time_jump),
        odometry_jump_(f.odometry_jump),
        huge_at_(frameSet(p, f, &FaultParams::huge_cloud_at)),
        repeat_at_(frameSet(p, f, &FaultParams::repeat_time_at)),
        back_at_(frameSet(p, f, &FaultParams::backwards_time_at)),
        jump_at_(frameSet(p, f, &FaultParams::jump_time_at)),
        odometry_at_(frameSet(p, f, &FaultParams::odometry_jump_at)),
        nan_time_at_(frameSet(p, f, &FaultParams::nan_time_at)) {}

  void start(const std::string& out_dir) override { inner_->start(out_dir); }
  void finish() override { inner_->finish(); }
  double progress() const override { return inner_->progress(); }
  std::size_t entriesSkipped() const override { return inner_->entriesSkipped(); }
  bool live() const override { return inner_->live(); }
  void results(const Frame& f) override { inner_->results(f); }
  bool detectionsOnly() const override { return inner_->detectionsOnly(); }

  std::vector<std::pair<std::string, long>> counters() const override {
    auto c = inner_->counters();
    c.insert(c.end(), {{"faults_frames_dropped", dropped_},
                       {"faults_nonfinite_ranges", n_nonfinite_},
                       {"faults_zero_ranges", n_zero_},
                       {"faults_max_ranges", n_max_},
                       {"faults_empty_frames", n_empty_},
                       {"faults_huge_clouds", n_huge_},
                       {"faults_time", n_time_},
                       {"faults_odometry_jumps", n_odometry_}});
    return c;
  }

  bool next(Frame& f) override {
    for (;;) {
      const std::size_t index = f.index;
      if (!inner_->next(f)) return false;
      const long k = count_++;  // position in the wrapped stream, dropped frames included
      if (drop_every_ > 0 && (k + 1) % drop_every_ == 0) {
        ++dropped_;
        f = Frame();
        f.index = index;
        continue;
      }
      spoil(f, k);
      return true;
    }
  }

 private:
  void spoil(Frame& f, long k) {
    // Time: a repeat or a step back of one frame's worth, a jump that stays, a NaN.
    if (jump_at_.count(k)) time_offset_ += time_jump_, ++n_time_;
    f.t += time_offset_;
    const double true_t = f.t;
    if (repeat_at_.count(k) && have_t_) f.t = last_t_, ++n_time_;
    if (back_at_.count(k) && have_t_) f.t = last_t_ - 1.0, ++n_time_;
    if (nan_time_at_.count(k)) f.t = std::numeric_limits<double>::quiet_NaN(), ++n_time_;
    last_t_ = true_t;
    have_t_ = true;
    // Odometry: from this frame on the robot is placed `odometry_jump` m further along x.
    if (odometry_at_.count(k)) odometry_offset_ += odometry_jump_, ++n_odometry_;
    if (odometry_offset_ != 0) {
      const mrpt::poses::CPose3D shift(odometry_offset_, 0, 0, 0, 0, 0);
      f.robot_pose = shift + f.robot_pose;
      f.sensor_pose = shift + f.sensor_pose;
      for (auto& s : f.sensors) s.pose = shift + s.pose;
    }
    const bool empty = (empty_every_ > 0 && (k + 1) % empty_every_ == 0) ||
                       (blind_at_ >= 0 && k >= blind_at_ && k < blind_at_ + blind_frames_);
    const bool ranges = nonfinite_ > 0 || zero_ > 0 || max_ > 0;
    for (auto& obs : f.observations) {
      if (auto* velo = dynamic_cast<CObservationVelodyneScan*>(obs.get());
          velo && (ranges || empty))
        obs = asPointCloud(*velo);
      if (auto* scan = dynamic_cast<CObservation2DRangeScan*>(obs.get())) {
        if (empty) {
          scan->resizeScan(0);
          continue;
        }
        if (!ranges) continue;  // no draw per return when no range fault is asked for
        for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
          const auto v = spoiledRange(scan->maxRange);
          if (!v) continue;
          scan->setScanRange(i, static_cast<float>(*v));
          scan->setScanRangeValidity(i, true);
        }
      } else if (auto* pc = dynamic_cast<CObservationPointCloud*>(obs.get())) {
        if (!pc->pointcloud) continue;
        if (empty) {
          pc->pointcloud->clear();
          continue;
        }
        if (!ranges) continue;
        auto& map = *pc->pointcloud;
        for (std::size_t i = 0; i < map.size(); ++i) {
          float x, y, z;
          map.getPoint(i, x, y, z);
          const auto v = spoiledRange(100.0);
          if (!v) continue;
          const double r = std::sqrt(double(x) * x + double(y) * y + double(z) * z);
          const double s = !std::isfinite(*v) || r == 0 ? *v : *v / r;
          map.setPoint(i, static_cast<float>(x * s), static_cast<float>(y * s),
                       static_cast<float>(z * s));
        }
        map.mark_as_modified();
      }
    }
    if (empty) ++n_empty_;
    if (huge_at_.count(k)) addHugeCloud(f);
  }

  // The spoiled range for one return, or nothing to leave it: with the configured probabilities
  // a NaN or an infinity (in turn, as drivers report "no return" either way), 0 or the maximum.
  std::optional<double> spoiledRange(double max_range) {
    const double u = uniform_(rng_);
    if (u < nonfinite_) {
      ++n_nonfinite_;
      return (n_nonfinite_ % 2) ? kInf : std::numeric_limits<double>::quiet_NaN();
    }
    if (u < nonfinite_ + zero_) return ++n_zero_, 0.0;
    if (u < nonfinite_ + zero_ + max_) return ++n_max_, max_range;
    return std::nullopt;
  }

  // A cloud of `huge_cloud_points` points spread over 60 m x 60 m x 3 m around the robot.
  void addHugeCloud(Frame& f) {
    auto pc = CObservationPointCloud::Create();
    auto map = mrpt::maps::CSimplePointsMap::Create();
    map->reserve(static_cast<std::size_t>(huge_points_));
    std::uniform_real_distribution<float> xy(-30.f, 30.f), z(-0.5f, 2.5f);
    for (long i = 0; i < huge_points_; ++i) map->insertPointFast(xy(rng_), xy(rng_), z(rng_));
    map->mark_as_modified();
    pc->pointcloud = map;
    pc->sensorLabel = "FAULT_HUGE_CLOUD";
    f.observations.push_back(pc);
    ++n_huge_;
  }

  std::unique_ptr<Sensor> inner_;
  std::mt19937 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  const double nonfinite_, zero_, max_;
  const long empty_every_, blind_at_, blind_frames_, drop_every_, huge_points_;
  const double time_jump_, odometry_jump_;
  const std::set<long> huge_at_, repeat_at_, back_at_, jump_at_, odometry_at_, nan_time_at_;
  long count_ = 0;
  double time_offset_ = 0, odometry_offset_ = 0, last_t_ = 0;
  bool have_t_ = false;
  long dropped_ = 0, n_nonfinite_ = 0, n_zero_ = 0, n_max_ = 0, n_empty_ = 0, n_huge_ = 0,
       n_time_ = 0, n_odometry_ = 0;
};

}  // namespace

const std::vector<ParamSpec>& faultParams() {
  static const std::vector<ParamSpec> specs = table().specs();
  return specs;
}

std::unique_ptr<Sensor> wrapWithFaults(std::unique_ptr<Sensor> source, const ParamSet& params) {
  return std::make_unique<FaultInjector>(std::move(source), params);
}

}  // namespace pedtrack
