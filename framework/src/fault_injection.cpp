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
#include "pedtrack/velodyne_decode.h"

namespace pedtrack {
namespace {

using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CObservationVelodyneScan;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::set<long> frameSet(const ParamSet& p, const std::string& key) {
  std::set<long> out;
  if (p.getString(key).empty()) return out;
  for (double v : p.getNumbers(key)) {
    if (v < 0 || v != std::floor(v))
      throw ConfigError(p.where(key) + ": '" + p.getString(key) +
                        "': frame numbers are whole numbers from 0");
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
      : inner_(std::move(inner)),
        rng_(static_cast<std::uint32_t>(p.getInt("seed"))),
        nonfinite_(p.getDouble("nonfinite_ranges")),
        zero_(p.getDouble("zero_ranges")),
        max_(p.getDouble("max_ranges")),
        empty_every_(p.getInt("empty_every")),
        blind_at_(p.getInt("blind_at")),
        blind_frames_(p.getInt("blind_frames")),
        drop_every_(p.getInt("drop_every")),
        huge_points_(p.getInt("huge_cloud_points")),
        time_jump_(p.getDouble("time_jump")),
        odometry_jump_(p.getDouble("odometry_jump")),
        huge_at_(frameSet(p, "huge_cloud_at")),
        repeat_at_(frameSet(p, "repeat_time_at")),
        back_at_(frameSet(p, "backwards_time_at")),
        jump_at_(frameSet(p, "jump_time_at")),
        odometry_at_(frameSet(p, "odometry_jump_at")),
        nan_time_at_(frameSet(p, "nan_time_at")) {}

  void start(const std::string& out_dir) override { inner_->start(out_dir); }
  void finish() override { inner_->finish(); }
  double progress() const override { return inner_->progress(); }
  std::size_t entriesSkipped() const override { return inner_->entriesSkipped(); }
  bool live() const override { return inner_->live(); }

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
  static const std::vector<ParamSpec> specs{
      ParamSpec::integer("seed", 1, "", 0, 4294967295.0, "random seed of the range faults"),
      ParamSpec::real("nonfinite_ranges", 0.0, "", 0, 1,
                      "fraction of returns made NaN or +inf (flagged valid, as a buggy driver "
                      "would); a VLP-16 revolution is turned into a point cloud first"),
      ParamSpec::real("zero_ranges", 0.0, "", 0, 1, "fraction of returns made 0 m"),
      ParamSpec::real("max_ranges", 0.0, "", 0, 1,
                      "fraction of returns put at the scanner's maximum range (100 m for clouds)"),
      ParamSpec::integer("empty_every", 0, "frames", 0, 1e9,
                         "every N-th frame's scans and clouds are emptied (0: never)"),
      ParamSpec::integer("blind_at", -1, "frame", -1, 1e9,
                         "from this frame the sensor is blind (every scan and cloud empty) for "
                         "blind_frames frames (-1: never)"),
      ParamSpec::integer("blind_frames", 30, "frames", 1, 1e9, "how long the sensor is blind"),
      ParamSpec::integer("drop_every", 0, "frames", 0, 1e9,
                         "every N-th frame of the source is never delivered (0: never)"),
      ParamSpec::text("huge_cloud_at", std::string(""),
                      "frames (0-based, of the source) that get an extra cloud of "
                      "huge_cloud_points points"),
      ParamSpec::integer("huge_cloud_points", 1000000, "", 1, 1e8,
                         "points of that cloud, spread over 60 m x 60 m x 3 m"),
      ParamSpec::text("repeat_time_at", std::string(""),
                      "frames stamped with the previous frame's time"),
      ParamSpec::text("backwards_time_at", std::string(""),
                      "frames stamped 1 s before the previous frame"),
      ParamSpec::text("jump_time_at", std::string(""),
                      "frames from which every stamp is time_jump later"),
      ParamSpec::real("time_jump", 600.0, "s", -1e9, 1e9, "size of each time jump"),
      ParamSpec::text("nan_time_at", std::string(""), "frames stamped NaN"),
      ParamSpec::text("odometry_jump_at", std::string(""),
                      "frames from which the robot pose is odometry_jump further along x"),
      ParamSpec::real("odometry_jump", 5.0, "m", -1e6, 1e6, "size of each odometry jump"),
  };
  return specs;
}

std::unique_ptr<Sensor> wrapWithFaults(std::unique_ptr<Sensor> source, const ParamSet& params) {
  return std::make_unique<FaultInjector>(std::move(source), params);
}

}  // namespace pedtrack
