#include "pedtrack/seg/scan_segments.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/fit/ellipse.h"

namespace pedtrack::seg {

std::vector<ScanRun> scanRuns(const Frame& frame, bool beams) {
  std::vector<ScanRun> runs;
  for (const CloudSpan& span : frame.cloudSpans()) {
    const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(
        frame.observations[span.observation].get());
    if (!scan) continue;  // 3D observations form no run
    ScanRun run;
    run.first = span.first;
    run.count = span.count;
    run.sx = scan->sensorPose.x();
    run.sy = scan->sensorPose.y();
    if (beams) {
      for (std::size_t b = 0; b < scan->getScanSize(); ++b)
        if (scan->getScanRangeValidity(b)) run.beam.push_back(int(b));
      if (run.beam.size() != run.count)
        throw DataError("scan segments: a scan put " + std::to_string(run.count) +
                        " points in the cloud but has " + std::to_string(run.beam.size()) +
                        " valid beams");
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

std::vector<std::vector<std::uint32_t>> splitRun(const Frame& frame, const ScanRun& run,
                                                 const SegmentParams& p) {
  const auto& c = frame.cloud();
  const auto& xs = c.getPointsBufferRef_x();
  const auto& ys = c.getPointsBufferRef_y();
  std::vector<std::vector<std::uint32_t>> out;
  std::vector<std::uint32_t> cur;
  auto flush = [&] {
    if (int(cur.size()) >= p.min_points) out.push_back(cur);
    cur.clear();
  };
  int last = -1;  // previous kept point, index within the run
  for (std::size_t k = 0; k < run.count; ++k) {
    const std::size_t i = run.first + k;
    if (!frame.isKept(i)) continue;
    if (last >= 0) {
      const std::size_t j = run.first + last;
      const double dx = xs[i] - xs[j], dy = ys[i] - ys[j];
      const double d = std::sqrt(dx * dx + dy * dy);
      double limit = p.gap;
      if (p.adaptive_angle > 0 && k > 0) {
        // The largest step a surface at angle λ to the beam makes between these two beams.
        const double r = std::hypot(xs[j] - run.sx, ys[j] - run.sy);
        const double dphi = std::abs(std::atan2(ys[i] - run.sy, xs[i] - run.sx) -
                                     std::atan2(ys[j] - run.sy, xs[j] - run.sx));
        const double step = std::min(dphi, 2 * M_PI - dphi);
        if (p.adaptive_angle > step)
          limit = std::max(limit, r * std::sin(step) / std::sin(p.adaptive_angle - step));
      }
      const bool hole = p.max_missing >= 0 && !run.beam.empty() &&
                        run.beam[k] - run.beam[last] - 1 > p.max_missing;
      if (d > limit || hole) flush();
    }
    cur.push_back(static_cast<std::uint32_t>(i));
    last = static_cast<int>(k);
  }
  flush();
  return out;
}

const std::vector<std::string>& segmentFeatureNames() {
  static const std::vector<std::string> names = {
      "points",         "width",           "std",
      "mad_median",     "linearity",       "circularity",
      "radius",         "boundary_length", "boundary_regularity",
      "mean_curvature", "mean_angle_diff", "jump_prev",
      "jump_next",      "distance",        "ellipse_a",
      "ellipse_b",      "ellipse_residual"};
  return names;
}

std::vector<double> segmentFeatures(const fit::Points2& pts, double sx, double sy, double jump_prev,
                                    double jump_next) {
  const std::size_t n = pts.size();
  if (n == 0) return std::vector<double>(segmentFeatureNames().size(), 0.0);
  std::vector<double> f;
  f.reserve(segmentFeatureNames().size() + 2);  // room for a leg stage's two without a copy
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(std::max<std::size_t>(n, 1));
  // Spread: standard deviation and mean deviation from the (per-axis) median.
  double ss = 0;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) {
    ss += (p - mean).squaredNorm();
    S += (p - mean) * (p - mean).transpose();
  }
  // Per-axis median; the buffers persist across calls (one scan has dozens of segments).
  thread_local std::vector<double> xs, ys;
  xs.clear();
  ys.clear();
  for (const auto& p : pts) {
    xs.push_back(p.x());
    ys.push_back(p.y());
  }
  std::nth_element(xs.begin(), xs.begin() + n / 2, xs.end());
  std::nth_element(ys.begin(), ys.begin() + n / 2, ys.end());
  const Eigen::Vector2d median(xs[n / 2], ys[n / 2]);
  double mad = 0;
  for (const auto& p : pts) mad += (p - median).norm();
  // Line fit (total least squares): RMS distance to the line.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(S);
  const double linearity = std::sqrt(std::max(0.0, es.eigenvalues()(0)) / double(n));
  fit::Circle circle;
  double radius = 100, circularity = linearity;
  if (fit::fitCircleAlgebraic(pts, circle) && circle.r < 100) {
    radius = circle.r;
    circularity = fit::circleResidual(pts, circle);
  }
  // Boundary: consecutive steps, their regularity, curvature and turning angles.
  double blen = 0, bsq = 0, curv = 0, ang = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double d = (pts[i] - pts[i - 1]).norm();
    blen += d;
    bsq += d * d;
  }
  const double steps = double(n > 1 ? n - 1 : 1);
  const double bmean = blen / steps;
  const double breg = std::sqrt(std::max(0.0, bsq / steps - bmean * bmean));
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Eigen::Vector2d a = pts[i - 1] - pts[i], b = pts[i + 1] - pts[i];
    const double la = a.norm(), lb = b.norm(), lc = (pts[i + 1] - pts[i - 1]).norm();
    const double cross = a.x() * b.y() - a.y() * b.x();
    if (la * lb * lc > 0) curv += 2 * std::abs(cross) / (la * lb * lc);  // 4·area / (abc)
    if (la * lb > 0) ang += std::atan2(std::abs(cross), a.dot(b));
  }
  const double triples = double(n > 2 ? n - 2 : 1);
  fit::Ellipse e;
  double ea = radius, eb = radius, eres = circularity;
  if (fit::fitEllipseDirect(pts, e)) {
    // A nearly straight segment fits a huge ellipse: cap the axes like the circle's radius.
    ea = std::min(e.a, 100.0);
    eb = std::min(e.b, 100.0);
    eres = fit::ellipseResidual(pts, e);
  }
  f = {double(n),
       (pts.back() - pts.front()).norm(),
       std::sqrt(ss / double(n > 1 ? n - 1 : 1)),
       mad / double(n),
       linearity,
       circularity,
       radius,
       blen,
       breg,
       curv / triples,
       ang / triples,
       jump_prev,
       jump_next,
       std::sqrt((mean.x() - sx) * (mean.x() - sx) + (mean.y() - sy) * (mean.y() - sy)),
       ea,
       eb,
       eres};
  return f;
}

}  // namespace pedtrack::seg
