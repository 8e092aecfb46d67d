// Thinning a 2D scan's beams for training (host/scan_thinning.h, the `beam_steps` key of a
// training dataset): the kept beams are exactly every Nth beam of the scan, each still pointing
// where it pointed, whichever way the scan turns and wherever the sensor is mounted.
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/frame.h"
#include "scan_thinning.h"

using pedtrack::Frame;
using pedtrack::cli::thinnedFrame;

namespace {

// 181 beams over 180° (1° apart), beam i at 2 + 0.01·i m; beam 7 has no return.
Frame scanFrame(bool right_to_left) {
  auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  scan->aperture = float(M_PI);
  scan->rightToLeft = right_to_left;
  scan->sensorPose = mrpt::poses::CPose3D(0.2, -0.1, 0.3, 0.4, 0, 0);
  scan->resizeScan(181);
  for (std::size_t i = 0; i < 181; ++i) {
    scan->setScanRange(i, float(2 + 0.01 * double(i)));
    scan->setScanRangeValidity(i, i != 7);
  }
  Frame f;
  f.observations.push_back(scan);
  return f;
}

}  // namespace

TEST_CASE("a thinned scan keeps every Nth beam where it pointed", "[train]") {
  for (bool right_to_left : {true, false}) {
    const Frame f = scanFrame(right_to_left);
    const auto& full = f.cloud();
    REQUIRE(full.size() == 180);  // beam 7 left out
    const Frame g = thinnedFrame(f, 3, 1);
    const auto& thin = g.cloud();
    // Beams 1, 4, 7, ..., 178: 60 of them, beam 7 without a return.
    REQUIRE(thin.size() == 59);
    std::size_t k = 0;
    for (std::size_t beam = 1; beam <= 178; beam += 3) {
      if (beam == 7) continue;
      const std::size_t i = beam < 7 ? beam : beam - 1;  // its point in the full cloud
      INFO("right to left " << right_to_left << ", beam " << beam);
      CHECK(thin.getPointsBufferRef_x()[k] == Approx(full.getPointsBufferRef_x()[i]).margin(1e-5));
      CHECK(thin.getPointsBufferRef_y()[k] == Approx(full.getPointsBufferRef_y()[i]).margin(1e-5));
      ++k;
    }
    // The source frame is untouched, and a step of 1 is the scan itself.
    CHECK(f.cloud().size() == 180);
    const Frame same = thinnedFrame(f, 1, 0);
    REQUIRE(same.cloud().size() == 180);
    for (std::size_t i = 0; i < 180; ++i)
      CHECK(same.cloud().getPointsBufferRef_x()[i] == full.getPointsBufferRef_x()[i]);
  }
}

TEST_CASE("a scan thinned by N spaces its beams N times as far apart", "[train]") {
  // So a body at range r gets as many beams, as far apart in metres, as the full scan gives it
  // at N·r: what lets legs recorded near stand in for far ones.
  const double delta = M_PI / 180;
  const Frame g = thinnedFrame(scanFrame(true), 3, 0);
  const auto* s = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(g.observations[0].get());
  REQUIRE(s);
  CHECK(s->getScanSize() == 61);
  CHECK(s->aperture / 60 == Approx(3 * delta));
  // Beams 0 and 180 of the full scan are the thinned scan's first and last.
  const auto& thin = g.cloud();
  const Frame f = scanFrame(true);
  const auto& full = f.cloud();
  CHECK(thin.getPointsBufferRef_x()[0] == Approx(full.getPointsBufferRef_x()[0]).margin(1e-5));
  REQUIRE(thin.size() == 61);
  CHECK(thin.getPointsBufferRef_y()[60] == Approx(full.getPointsBufferRef_y()[179]).margin(1e-5));
}
