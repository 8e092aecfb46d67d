#include "scan_thinning.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

namespace pedtrack::cli {
namespace {

using mrpt::obs::CObservation2DRangeScan;

CObservation2DRangeScan::Ptr thinnedScan(const CObservation2DRangeScan& s, int step, int offset) {
  auto out = std::make_shared<CObservation2DRangeScan>(s);
  const int n = int(s.getScanSize());
  if (n < 2 || step <= 1) return out;
  offset %= step;
  const int kept = (n - 1 - offset) / step + 1;
  if (kept < 2) return out;
  // MRPT spreads a scan's beams evenly over its aperture, centred on the sensor's x axis:
  // beam i points at ∓aperture/2 ± i·Δ (right to left or not). The kept beams span a narrower,
  // off-centre aperture, so the sensor turns by the shift of their centre.
  const double delta = s.aperture / (n - 1);
  const double aperture = step * delta * (kept - 1);
  const double centre = offset * delta + aperture / 2 - s.aperture / 2;
  out->resizeScan(std::size_t(kept));
  for (int j = 0; j < kept; ++j) {
    const std::size_t b = std::size_t(offset + j * step);
    out->setScanRange(std::size_t(j), s.getScanRange(b));
    out->setScanRangeValidity(std::size_t(j), s.getScanRangeValidity(b));
    if (s.hasIntensity()) out->setScanIntensity(std::size_t(j), s.getScanIntensity(b));
  }
  out->aperture = float(aperture);
  out->sensorPose =
      s.sensorPose + mrpt::poses::CPose3D(0, 0, 0, s.rightToLeft ? centre : -centre, 0, 0);
  return out;
}

}  // namespace

Frame thinnedFrame(const Frame& f, int step, int offset) {
  Frame g = f.sameTimeAndPoses();
  for (const auto& obs : f.observations) {
    const auto* scan = dynamic_cast<const CObservation2DRangeScan*>(obs.get());
    g.observations.push_back(scan ? thinnedScan(*scan, step, offset) : obs);
  }
  return g;
}

}  // namespace pedtrack::cli
