#include "scan_odometry/scan_matcher.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/slam/CICP.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <unordered_set>

namespace pedtrack::track {

using mrpt::poses::CPose2D;

namespace {

// CICP's goodness is the share of the queried scan points that have a keyframe point within
// the last round's correspondence distance (~6 cm); with decimated queries it can exceed 1 a
// little. Scans within keyframe_distance of their keyframe in a static scene give 0.97-1.0 (in
// the tests), a scan of unrelated clutter 0.03; people walking past, glass and newly uncovered
// space cost a few tenths. Below half, most of the scan agrees with nothing in the keyframe: the
// match rests on too little to trust (or found a wrong alignment), the prediction is safer.
constexpr double kMinGoodness = 0.5;

// Points queried per ICP iteration: one in this many (see Impl()); all of a sparse scan.
constexpr unsigned kQueryDecimation = 3;

std::uint64_t cellKey(double x, double y, double inv_cell) {
  const auto cx = static_cast<std::int32_t>(std::floor(x * inv_cell));
  const auto cy = static_cast<std::int32_t>(std::floor(y * inv_cell));
  return (std::uint64_t(std::uint32_t(cx)) << 32) | std::uint32_t(cy);
}

}  // namespace

struct ScanOdometry::Impl {
  ScanOdometryOptions opt;
  mrpt::slam::CICP icp;
  // The keyframe (CICP's m1, the reference whose kd-tree answers every query) is kept denser
  // than the scan (m2, the queried points): point-to-point ICP between two sparse samplings of
  // the same wall pulls the samples onto each other, a bias of up to half a cell per match that
  // adds up over keyframes (over the test drive 1.9 cm / 0.6° mean error with both thinned to
  // 5 cm, 1.1 cm / 0.35° with a dense keyframe). Query cost grows only with log(size), and the
  // kd-tree is built once per keyframe. Both maps are refilled in place (buffers reused).
  mrpt::maps::CSimplePointsMap keyframe, scan;
  // The last local_keyframes keyframes' points in the odometry frame, and their union (thinned
  // as a keyframe is): the reference of a sparse scan, built when one first needs it after a new
  // keyframe (a room's dense scans never do).
  std::deque<std::vector<Eigen::Vector2d>> recent;
  mrpt::maps::CSimplePointsMap local_map;
  bool local_map_stale = true;
  std::vector<Eigen::Vector2d> local_points;  // buffer, reused
  bool have_keyframe = false;
  CPose2D kf_pose;  // keyframe's pose in the odometry frame
  CPose2D pose;     // last returned pose
  // The last two accepted poses (and their times) give the constant-velocity prediction.
  CPose2D last_pose, prev_pose;
  double last_t = 0, prev_t = 0;
  int n_accepted = 0;
  long matched = 0, rejected = 0, skipped = 0;
  std::deque<std::size_t> counts;           // thinned points of the last recent_scans scans
  int rejected_run = 0;                     // rejections in a row
  bool last_matched = false;                // the last update() placed its scan by a match
  std::unordered_set<std::uint64_t> cells;  // thinning grid, reused (clear() keeps the buckets)

  explicit Impl(const ScanOdometryOptions& o) : opt(o) {
    auto& io = icp.options;
    // Classic ICP (a closed-form SE(2) fit per iteration), not icpLevenbergMarquardt: on the
    // test drive LM took 1.7× as long and ended 10 cm / 2.6° off (its numeric derivatives use
    // 5 cm steps, coarse for cm alignment), classic 1-2 cm / 0.4°.
    io.ICP_algorithm = mrpt::slam::icpClassic;
    io.maxIterations = static_cast<unsigned>(std::max(1, o.max_iterations));
    io.thresholdDist = o.max_match_distance;
    // Each time ICP converges it shrinks the correspondence distance by ALFA and stops once it
    // is below smallestThresholdDist: 0.5 → 0.175 → 0.06 m, three rounds where MRPT's ALFA = 0.5
    // takes four for the same end. The last round must pair points only a few cm apart: ending
    // at 0.125 m (MRPT's default 0.1 stop) let stray pairs double the error over the test drive.
    io.ALFA = 0.35;
    io.smallestThresholdDist = 0.05;
    // A round ends when a step moves < 0.3 mm and < 0.02°, far below what matters here; MRPT's
    // 1e-6 defaults add iterations that only polish noise.
    io.minAbsStep_trans = 3e-4;
    io.minAbsStep_rot = 3e-4;
    // Nearly all of the time goes into kd-tree queries, one per queried scan point per
    // iteration. Each iteration queries a third of the thinned scan (a different third each
    // round; MRPT's default is a fifth): about half the cost of querying all for ~0.3 cm more
    // error over the test drive, where a fifth cost ~1 cm more in the worst case.
    io.corresponding_points_decimation = kQueryDecimation;
    // Only the mean pose is used: the covariance and quality estimates would cost extra passes.
    io.skip_cov_calculation = true;
    io.skip_quality_calculation = true;
    io.doRANSAC = false;
    cells.reserve(4096);
    keyframe.reserve(4096);
    local_map.reserve(4096);
    scan.reserve(4096);
  }

  // Constant velocity: the motion between the last two accepted poses, as a body-frame
  // increment, scaled to the time since the last one (so a run of unmatched scans keeps going
  // at the same speed instead of compounding its own extrapolations).
  CPose2D predict(double t) const {
    if (n_accepted == 0) return pose;
    if (n_accepted < 2 || !(last_t > prev_t)) return last_pose;
    const CPose2D d = last_pose - prev_pose;  // prev⁻¹ ⊕ last
    const double s = std::min(t - last_t, opt.predict_for) / (last_t - prev_t);
    return last_pose + CPose2D(d.x() * s, d.y() * s, d.phi() * s);
  }

  // No scan matched yet, or none for longer than the prediction is trusted.
  bool guessing(double t) const { return n_accepted == 0 || !(t - last_t <= opt.predict_for); }

  // Whether reaching p at t from the last accepted pose is faster than max_speed.
  bool tooFast(const CPose2D& p, double t) const {
    if (!(opt.max_speed > 0) || n_accepted == 0 || !(t > last_t)) return false;
    return (p - last_pose).norm() > opt.max_speed * (t - last_t);
  }

  void accept(const CPose2D& p, double t) {
    prev_pose = last_pose;
    prev_t = last_t;
    last_pose = p;
    last_t = t;
    ++n_accepted;
  }

  // Fills m with the finite points of pts, one per grid cell of the given size.
  void thin(const std::vector<Eigen::Vector2d>& pts, double cell, mrpt::maps::CSimplePointsMap& m) {
    m.resize(0);  // keeps the capacity (clear() would free it)
    cells.clear();
    const double inv = cell > 0 ? 1.0 / cell : 0.0;
    for (const auto& p : pts) {
      if (!p.allFinite()) continue;
      if (inv > 0 && !cells.insert(cellKey(p.x(), p.y(), inv)).second) continue;
      m.insertPointFast(float(p.x()), float(p.y()), 0.f);
    }
    m.mark_as_modified();  // insertPointFast does not: the kd-tree must be rebuilt
  }

  // This scan becomes the keyframe. Thinned to a fifth of the scan's cell (1 cm by default):
  // dense enough for the reason above, but the keyframe of several scanners that see the same
  // wall does not hold every one of their returns.
  // A keyframe taken after matching kept failing (re-anchoring at the prediction) disagrees
  // with the views before it: those leave the local map.
  void takeKeyframe(const std::vector<Eigen::Vector2d>& pts, const CPose2D& p, bool reanchor) {
    thin(pts, opt.decimation_cell / 5, keyframe);
    kf_pose = p;
    have_keyframe = true;
    if (opt.local_keyframes <= 1) return;
    if (reanchor) recent.clear();
    // The thinned keyframe, not the scan, in the odometry frame.
    std::vector<Eigen::Vector2d> in_odometry(keyframe.size());
    for (std::size_t i = 0; i < keyframe.size(); ++i) {
      float x, y, z;
      keyframe.getPoint(i, x, y, z);
      p.composePoint(x, y, in_odometry[i].x(), in_odometry[i].y());
    }
    recent.push_back(std::move(in_odometry));
    while (recent.size() > opt.local_keyframes) recent.pop_front();
    local_map_stale = true;
  }

  const mrpt::maps::CSimplePointsMap& localMap() {
    if (local_map_stale) {
      local_points.clear();
      for (const auto& v : recent) local_points.insert(local_points.end(), v.begin(), v.end());
      thin(local_points, opt.decimation_cell / 5, local_map);
      local_map_stale = false;
    }
    return local_map;
  }

  // Whether this scan has too few points against the recent ones (min_points_share); records
  // its count either way.
  bool suddenlySparse(std::size_t n) {
    bool few = false;
    if (opt.min_points_share > 0 && counts.size() >= opt.recent_scans) {
      std::vector<std::size_t> c(counts.begin(), counts.end());
      auto mid = c.begin() + std::ptrdiff_t(c.size() / 2);
      std::nth_element(c.begin(), mid, c.end());
      few = double(n) < opt.min_points_share * double(*mid);
    }
    counts.push_back(n);
    while (counts.size() > std::max<std::size_t>(opt.recent_scans, 1)) counts.pop_front();
    return few;
  }

  CPose2D update(const std::vector<Eigen::Vector2d>& pts, double t) {
    const CPose2D pred = predict(t);
    last_matched = false;
    thin(pts, opt.decimation_cell, scan);
    const bool few = suddenlySparse(scan.size());
    if (scan.size() < opt.min_points) return pose = pred;
    if (few && have_keyframe) {
      ++skipped;
      return pose = pred;
    }
    if (!have_keyframe) {
      takeKeyframe(pts, pred, false);
      accept(pred, t);
      last_matched = true;  // the origin: where the robot is, by definition
      return pose = pred;
    }
    // CICP estimates the pose of m2 (this scan) in m1's frame (the keyframe, or for a sparse
    // scan the local map, which is in the odometry frame); its kd-tree is built on m1. The guess
    // is the prediction in that frame.
    const bool sparse = scan.size() < opt.sparse_points;
    icp.options.corresponding_points_decimation = sparse ? 1 : kQueryDecimation;
    const bool local = sparse && opt.local_keyframes > 1;
    const CPose2D origin = local ? CPose2D() : kf_pose;
    mrpt::slam::CICP::TReturnInfo info;
    const auto pdf = icp.Align(local ? &localMap() : &keyframe, &scan, pred - origin, info);
    const CPose2D est = origin + pdf->getMeanVal();
    const bool ok = info.goodness >= kMinGoodness && (est - pred).norm() <= opt.max_step &&
                    std::abs(mrpt::math::wrapToPi(est.phi() - pred.phi())) <= opt.max_turn_step &&
                    !tooFast(est, t);
    if (ok) {
      ++matched;
      last_matched = true;
      rejected_run = 0;
      accept(est, t);
      pose = est;
    } else {
      ++rejected;
      ++rejected_run;
      pose = pred;
    }
    // Far enough from the keyframe: this scan becomes the next one. A rejected scan only when
    // the one before was rejected too: a single odd scan (someone right in front of a scanner)
    // must not become the reference the next scans fail against, but when matching keeps
    // failing the keyframe is stale (the view changed) and the robot must re-anchor somewhere.
    // Failing for longer than the prediction is trusted, the pose is held and would never get
    // far from the keyframe: the robot re-anchors where it is.
    const CPose2D rel = pose - kf_pose;
    const bool far = rel.norm() >= opt.keyframe_distance ||
                     std::abs(mrpt::math::wrapToPi(rel.phi())) >= opt.keyframe_angle;
    const bool lost = rejected_run >= 2 && guessing(t);
    if ((ok || rejected_run >= 2) && (far || lost)) takeKeyframe(pts, pose, !ok);
    return pose;
  }
};

ScanOdometry::ScanOdometry(const ScanOdometryOptions& o) : impl_(std::make_unique<Impl>(o)) {}
ScanOdometry::~ScanOdometry() = default;
ScanOdometry::ScanOdometry(ScanOdometry&&) noexcept = default;
ScanOdometry& ScanOdometry::operator=(ScanOdometry&&) noexcept = default;

CPose2D ScanOdometry::update(const std::vector<Eigen::Vector2d>& points, double t) {
  return impl_->update(points, t);
}
CPose2D ScanOdometry::pose() const {
  return impl_->pose;
}
bool ScanOdometry::started() const {
  return impl_->have_keyframe;
}
long ScanOdometry::matched() const {
  return impl_->matched;
}
long ScanOdometry::rejected() const {
  return impl_->rejected;
}
bool ScanOdometry::lastMatched() const {
  return impl_->last_matched;
}
bool ScanOdometry::guessing(double t) const {
  return impl_->guessing(t);
}
long ScanOdometry::skipped() const {
  return impl_->skipped;
}

}  // namespace pedtrack::track
