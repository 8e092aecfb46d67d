// 2D segmentation: gaps and missing beams split segments; segment features by hand; leg circles,
// their merging across scanners and their pairing.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "leg_circles/leg_detection.h"
#include "pedtrack/errors.h"
#include "pedtrack/seg/scan_segments.h"

using namespace pedtrack;

namespace {

// 11 beams, 1° apart from −5° to +5°: beams 0-3 at 2 m, beam 4 without return, 5-7 at 2 m,
// 8-10 at 3 m.
Frame frameWithScan() {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->aperture = float(10 * M_PI / 180);
  scan->rightToLeft = true;
  scan->maxRange = 30;
  scan->resizeScan(11);
  for (int i = 0; i < 11; ++i) {
    scan->setScanRange(i, i < 8 ? 2.f : 3.f);
    scan->setScanRangeValidity(i, i != 4);
  }
  Frame f;
  f.observations.push_back(scan);
  return f;
}

std::vector<std::size_t> sizes(const std::vector<std::vector<std::uint32_t>>& segs) {
  std::vector<std::size_t> s;
  for (const auto& x : segs) s.push_back(x.size());
  return s;
}

}  // namespace

TEST_CASE("scan runs map cloud points to beams", "[segments]") {
  const Frame f = frameWithScan();
  REQUIRE(f.cloud().size() == 10);
  const auto runs = seg::scanRuns(f);
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].count == 10);
  CHECK(runs[0].beam == std::vector<int>{0, 1, 2, 3, 5, 6, 7, 8, 9, 10});
  CHECK(seg::scanRuns(f, false)[0].beam.empty());
}

TEST_CASE("segments split at gaps and at runs of missing beams", "[segments]") {
  Frame f = frameWithScan();
  const auto run = seg::scanRuns(f)[0];
  seg::SegmentParams p;  // gap 0.13 m; consecutive beams at 2 m are 3.5 cm apart
  p.max_missing = -1;
  CHECK(sizes(seg::splitRun(f, run, p)) == std::vector<std::size_t>{7, 3});
  p.max_missing = 1;  // one missing beam is a dropout
  CHECK(sizes(seg::splitRun(f, run, p)) == std::vector<std::size_t>{7, 3});
  p.max_missing = 0;  // any missing beam is a discontinuity
  CHECK(sizes(seg::splitRun(f, run, p)) == std::vector<std::size_t>{4, 3, 3});
  p.min_points = 4;
  CHECK(sizes(seg::splitRun(f, run, p)) == std::vector<std::size_t>{4});
  // Removed points take no part: without beams 0-1 the first segment is 2 points (dropped).
  f.labels()[0] = f.labels()[1] = PointLabel::Removed;
  p.min_points = 3;
  CHECK(sizes(seg::splitRun(f, run, p)) == std::vector<std::size_t>{3, 3});
}

TEST_CASE("segment features of three points on a 3 m arc, by hand", "[segments]") {
  // Points at 3°, 4° and 5° on a 3 m circle round the sensor: steps of 2·3·sin(0.5°), width
  // 2·3·sin(1°), curvature 1/3, turning angle 180° − 1° at the middle point.
  fit::Points2 pts;
  for (int k = 3; k <= 5; ++k) {
    const double a = k * M_PI / 180;
    pts.emplace_back(3 * std::cos(a), 3 * std::sin(a));
  }
  const auto f = seg::segmentFeatures(pts, 0, 0, -1.0, 0.0);
  const auto& names = seg::segmentFeatureNames();
  REQUIRE(f.size() == names.size());
  auto at = [&](const char* n) {
    return f[std::find(names.begin(), names.end(), n) - names.begin()];
  };
  const double step = 2 * 3 * std::sin(0.5 * M_PI / 180);
  CHECK(at("points") == 3);
  CHECK(at("width") == Approx(2 * 3 * std::sin(M_PI / 180)));
  CHECK(at("boundary_length") == Approx(2 * step));
  CHECK(at("boundary_regularity") == Approx(0).margin(1e-9));
  CHECK(at("radius") == Approx(3).epsilon(1e-6));  // the points lie on the sensor's 3 m circle
  CHECK(at("circularity") == Approx(0).margin(1e-9));
  CHECK(at("mean_curvature") == Approx(1.0 / 3).epsilon(1e-6));  // 1/r
  CHECK(at("mean_angle_diff") == Approx(M_PI - M_PI / 180).epsilon(1e-9));
  CHECK(at("jump_prev") == -1.0);
  // The mean of the three points is 3·(e^{i3°} + e^{i4°} + e^{i5°})/3 = e^{i4°}(1 + 2 cos 1°).
  CHECK(at("distance") == Approx(1 + 2 * std::cos(M_PI / 180)).epsilon(1e-12));
}

TEST_CASE("leg circles: a leg arc is found, a wall and a concave arc are not", "[legs]") {
  // A 5 cm leg at (1.5, 0.2) seen from the origin: the half facing the sensor, 9 points.
  fit::Points2 leg;
  const double cx = 1.5, cy = 0.2, r = 0.05, toward = std::atan2(-cy, -cx);
  for (int i = 0; i < 9; ++i) {
    const double a = toward - M_PI / 2 + M_PI * i / 8;
    leg.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
  }
  seg::LegParams p;
  seg::Leg out;
  REQUIRE(seg::detectLeg(leg, 0, 0, p, out));
  CHECK(out.circle.x == Approx(cx).margin(1e-9));
  CHECK(out.circle.y == Approx(cy).margin(1e-9));
  CHECK(out.circle.r == Approx(r).margin(1e-9));
  // Too few points, and a 1 m wall: no leg.
  CHECK_FALSE(seg::detectLeg({leg[0], leg[1]}, 0, 0, p, out));
  fit::Points2 wall;
  for (int i = 0; i < 30; ++i) wall.emplace_back(2.0, -0.5 + i / 29.0);
  CHECK_FALSE(seg::detectLeg(wall, 0, 0, p, out));
  // The same arc seen from behind is concave toward the sensor: P3 accepts it, the convexity
  // test does not.
  CHECK(seg::detectLeg(leg, 3.0, 0.4, p, out));
  p.require_convex = true;
  CHECK_FALSE(seg::detectLeg(leg, 3.0, 0.4, p, out));
  CHECK(seg::detectLeg(leg, 0, 0, p, out));
}

TEST_CASE("a segment of two legs, one just behind the other, splits at the range step", "[legs]") {
  // A person standing with one foot ahead, 1.2 m from the sensor: the far leg (5 cm, at
  // (1.32, 0.13)) shows 9 returns beside the near one (at (1.2, 0)), 0.128 m from its last
  // return, below the segmenter's 0.13 m gap: one segment, which no circle fits.
  auto arc = [](double cx, double cy, int n, double from, double to) {
    fit::Points2 pts;
    const double toward = std::atan2(-cy, -cx);
    for (int i = 0; i < n; ++i) {
      const double a = toward + from + (to - from) * i / (n - 1);
      pts.emplace_back(cx + 0.05 * std::cos(a), cy + 0.05 * std::sin(a));
    }
    return pts;
  };
  // In scan order (bearing rising): the near leg's front (-2.4 to 2.4 deg), then what shows
  // of the far leg beyond it (3.5 to 6.7 deg).
  fit::Points2 seg = arc(1.2, 0, 9, M_PI / 2, -M_PI / 2);
  const fit::Points2 far = arc(1.32, 0.13, 9, M_PI / 2, -M_PI / 6);
  seg.insert(seg.end(), far.begin(), far.end());
  seg::LegParams p;
  seg::Leg leg;
  REQUIRE_FALSE(seg::detectLeg(seg, 0, 0, p, leg));
  const std::size_t cut = seg::legSplitPoint(seg, 0, 0, 0.07, p);
  REQUIRE(cut == 9);
  // By hand: |(1.3250, 0.0801)| - |(1.2, 0.05)| = 1.3274 - 1.2010.
  CHECK(seg[9].norm() - seg[8].norm() == Approx(0.1264).margin(0.0005));
  REQUIRE(seg::detectLeg(fit::Points2(seg.begin(), seg.begin() + 9), 0, 0, p, leg));
  CHECK(leg.circle.x == Approx(1.2).margin(1e-6));
  CHECK(leg.circle.y == Approx(0).margin(1e-6));
  REQUIRE(seg::detectLeg(fit::Points2(seg.begin() + 9, seg.end()), 0, 0, p, leg));
  CHECK(leg.circle.x == Approx(1.32).margin(1e-6));
  CHECK(leg.circle.y == Approx(0.13).margin(1e-6));
  // A step below min_jump, parts shorter than min_points, or the rule off: no cut.
  CHECK(seg::legSplitPoint(seg, 0, 0, 0.15, p) == 0);
  p.min_points = 10;
  CHECK(seg::legSplitPoint(seg, 0, 0, 0.07, p) == 0);
  p.min_points = 3;
  CHECK(seg::legSplitPoint(seg, 0, 0, 0, p) == 0);
  // A smooth wall has no step.
  fit::Points2 wall;
  for (int i = 0; i < 30; ++i) wall.emplace_back(2.0, -0.5 + i / 29.0);
  CHECK(seg::legSplitPoint(wall, 0, 0, 0.07, p) == 0);
}

TEST_CASE("legs pair closest first within the separation limit", "[legs]") {
  CHECK(seg::pairLegs({{0, 0}, {0.3, 0}, {2, 0}, {2.5, 0}, {5, 0}}, 0.8) ==
        std::vector<int>{1, 0, 3, 2, -1});
  // 0.5 and 0.9 are the closest pair; 0 then has no partner left within 0.8 m.
  CHECK(seg::pairLegs({{0, 0}, {0.5, 0}, {0.9, 0}}, 0.8) == std::vector<int>{-1, 2, 1});
  CHECK(seg::pairLegs({}, 0.8).empty());
}

namespace {

// The half of a 5 cm leg at c that a sensor at s sees: 9 points on the arc facing it.
fit::Points2 legArc(const Eigen::Vector2d& c, const Eigen::Vector2d& s) {
  fit::Points2 pts;
  const double toward = std::atan2(s.y() - c.y(), s.x() - c.x());
  for (int i = 0; i < 9; ++i) {
    const double a = toward - M_PI / 2 + M_PI * i / 8;
    pts.emplace_back(c.x() + 0.05 * std::cos(a), c.y() + 0.05 * std::sin(a));
  }
  return pts;
}

seg::ScanLeg scanLeg(const Eigen::Vector2d& c, const Eigen::Vector2d& s, std::size_t scan) {
  seg::ScanLeg l;
  l.scan = scan;
  l.points = legArc(c, s);
  REQUIRE(seg::detectLeg(l.points, s.x(), s.y(), seg::LegParams(), l.leg));
  return l;
}

}  // namespace

TEST_CASE("legs of different scans merge into one refitted circle, legs of one scan never",
          "[legs]") {
  const Eigen::Vector2d a(0, 0), b(1.5, -1.0);  // two sensors, seeing the leg from two sides
  const Eigen::Vector2d c1(1.5, 0.2), c2(1.5, 0.32);
  const std::vector<seg::ScanLeg> legs = {scanLeg(c1, a, 0), scanLeg(c1, b, 1), scanLeg(c2, a, 0),
                                          scanLeg({3, 3}, b, 1)};
  const seg::LegParams p;
  // Leg 2 is 0.12 m from leg 1 (another scan) but shares scan 0 with leg 0, already merged.
  const auto m = seg::mergeLegs(legs, 0.15, p);
  REQUIRE(m.size() == 3);
  CHECK(m[0].members == std::vector<std::size_t>{0, 1});
  CHECK(m[1].members == std::vector<std::size_t>{2});
  CHECK(m[2].members == std::vector<std::size_t>{3});
  CHECK(m[0].leg.circle.x == Approx(c1.x()).margin(1e-9));
  CHECK(m[0].leg.circle.y == Approx(c1.y()).margin(1e-9));
  CHECK(m[0].leg.circle.r == Approx(0.05).margin(1e-9));
  CHECK(m[0].leg.residual < 1e-9);
  CHECK(m[1].leg.circle.y == Approx(c2.y()).margin(1e-9));  // alone: unchanged
  // Off: every leg alone.
  CHECK(seg::mergeLegs(legs, 0, p).size() == 4);
  CHECK(seg::mergeLegs({}, 0.1, p).empty());
  // Arcs that do not make one circle (a moving leg seen 4 cm apart): the mean of the centres.
  const std::vector<seg::ScanLeg> apart = {scanLeg(c1, a, 0),
                                           scanLeg(c1 + Eigen::Vector2d(0.04, 0), b, 1)};
  seg::LegParams strict;
  strict.max_residual = 0.005;
  const auto mean = seg::mergeLegs(apart, 0.1, strict);
  REQUIRE(mean.size() == 1);
  CHECK(mean[0].leg.circle.x == Approx(c1.x() + 0.02).margin(1e-9));
  CHECK(mean[0].leg.circle.y == Approx(c1.y()).margin(1e-9));
  CHECK(mean[0].leg.residual > strict.max_residual);
}
