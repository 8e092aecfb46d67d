#include "pedtrack/frame_guard.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace pedtrack {
namespace {

const char* const kNames[] = {
    "bad_time",  "time_repeats",   "time_backwards", "clock_resets",   "time_jumps",  "frame_gaps",
    "bad_poses", "odometry_jumps", "invalid_ranges", "invalid_points", "empty_frames"};

bool finitePose(const mrpt::poses::CPose3D& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) &&
         std::isfinite(p.yaw()) && std::isfinite(p.pitch()) && std::isfinite(p.roll());
}

}  // namespace

void FrameGuard::count(Kind k, const Frame& f, long n, const std::string& what) {
  if (n <= 0) return;
  if (counts_[k] == 0 && warn_)
    std::cerr << "warning: frame " << f.index << ": " << what << " (counted in run.json "
              << "input_warnings." << kNames[k] << "; warned once)\n";
  counts_[k] += n;
}

bool FrameGuard::admit(Frame& f) {
  if (!std::isfinite(f.t)) {
    count(kBadTime, f, 1, "timestamp is not a number; frame skipped");
    return false;
  }
  if (!finitePose(f.robot_pose) || !finitePose(f.sensor_pose)) {
    count(kBadPose, f, 1, "robot or sensor pose is not finite; frame skipped");
    return false;
  }
  if (have_last_) {
    const double dt = f.t - last_t_;
    if (dt == 0) {
      count(kTimeRepeat, f, 1, "same timestamp as the previous frame; frame skipped");
      return false;
    }
    if (dt < 0 && dt >= -kClockReset) {
      count(kTimeBackwards, f, 1, "timestamp went back; frame skipped");
      return false;
    }
    if (dt < 0) count(kClockResets, f, 1, "timestamp went back by more than 10 s: clock reset");
    if (dt > kTimeJump) {
      count(kTimeJumps, f, 1, "more than 5 s since the previous frame");
    } else if (dt > 0) {
      // Frames missing from a regular stream: a gap of well over the usual period (the median
      // of the recent ones), as a driver that loses scans or a full queue leaves.
      const double period = typicalPeriod();
      if (period > 0 && dt > kGapFactor * period)
        count(kFrameGaps, f, 1, "frames missing: a gap of more than 1.8 usual periods");
      periods_[n_periods_++ % periods_.size()] = dt;
    }
    const double moved =
        std::hypot(f.robot_pose.x() - last_pose_.x(), f.robot_pose.y() - last_pose_.y(),
                   f.robot_pose.z() - last_pose_.z());
    if (f.has_odometry &&
        moved > kOdometryJumpMetres + kOdometryJumpSpeed * std::max(0.0, std::min(dt, 1.0)))
      count(kOdometryJumps, f, 1, "the robot pose jumped between frames (odometry reset?)");
  }
  have_last_ = true;
  last_t_ = f.t;
  last_pose_ = f.robot_pose;
  // A source of detections (a detector's output replayed) has no range data, by design.
  if (clean(f) == 0 && !(detections_only_ && f.observations.empty()))
    count(kEmptyFrames, f, 1, "no range data in the frame");
  return true;
}

std::size_t FrameGuard::clean(Frame& f) {
  std::size_t points = 0;
  long bad_ranges = 0, bad_points = 0;
  for (auto& obs : f.observations) {
    if (auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(obs.get())) {
      for (std::size_t i = 0; i < scan->getScanSize(); ++i) {
        if (!scan->getScanRangeValidity(i)) continue;
        const float r = scan->getScanRange(i);
        if (!std::isfinite(r) || r <= 0) {
          scan->setScanRangeValidity(i, false);
          ++bad_ranges;
        } else {
          ++points;
        }
      }
    } else if (auto* pc = dynamic_cast<mrpt::obs::CObservationPointCloud*>(obs.get())) {
      if (!pc->pointcloud) continue;
      auto& map = *pc->pointcloud;
      const auto &xs = map.getPointsBufferRef_x(), &ys = map.getPointsBufferRef_y(),
                 &zs = map.getPointsBufferRef_z();
      // Not finite, or exactly at the sensor: how drivers of organised clouds mark "no return".
      const auto bad = [&](std::size_t i) {
        return !std::isfinite(xs[i]) || !std::isfinite(ys[i]) || !std::isfinite(zs[i]) ||
               (xs[i] == 0 && ys[i] == 0 && zs[i] == 0);
      };
      long n_bad = 0;
      for (std::size_t i = 0; i < map.size(); ++i) n_bad += bad(i);
      if (n_bad > 0) {  // the mask is built only for a cloud that needs it
        std::vector<bool> drop(map.size());
        for (std::size_t i = 0; i < map.size(); ++i) drop[i] = bad(i);
        map.applyDeletionMask(drop);
      }
      bad_points += n_bad;
      points += map.size();
    } else if (auto* velo = dynamic_cast<mrpt::obs::CObservationVelodyneScan*>(obs.get())) {
      points += velo->scan_packets.size();  // integer ranges: nothing to clean
    } else if (isRangeObservation(*obs)) {
      ++points;  // another range type: passed on as it is
    }
  }
  count(kInvalidRanges, f, bad_ranges, "ranges that are not finite or not positive were dropped");
  count(kInvalidPoints, f, bad_points,
        "cloud points that are not finite or lie at the sensor were dropped");
  return points;
}

double FrameGuard::typicalPeriod() const {
  if (n_periods_ < 8) return 0;
  std::array<double, 32> p = periods_;
  const std::size_t n = std::min<std::size_t>(n_periods_, p.size());
  std::nth_element(p.begin(), p.begin() + n / 2, p.begin() + n);
  return p[n / 2];
}

std::vector<std::pair<std::string, long>> FrameGuard::counts() const {
  std::vector<std::pair<std::string, long>> out;
  for (int k = 0; k < kKinds; ++k) out.emplace_back(kNames[k], counts_[k]);
  return out;
}

long FrameGuard::total() const {
  long n = 0;
  for (long c : counts_) n += c;
  return n;
}

}  // namespace pedtrack
