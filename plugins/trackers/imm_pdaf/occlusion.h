#pragma once
// Whether the sensor can see a place this frame: hidden when a cluster nearer to the sensor
// covers its bearing. Trackers lower their detection probability there, so a person walking
// behind another keeps its track (P4 §3.2's occlusion) instead of being judged gone.
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::track {

class OcclusionMap {
 public:
  /// From the frame's clusters, as seen from its (first) sensor; `margin` (m) is how much
  /// nearer an occluder must be, and is also added to each cluster's half-width.
  OcclusionMap(const Frame& f, double margin = 0.3);
  /// True when the fixed-frame point (x, y) with radius `radius` (m) is behind a cluster.
  bool hidden(double x, double y, double radius = 0.2) const;

 private:
  struct Shadow {
    double bearing, half_width, range;  // rad, rad, m (sensor frame)
  };
  std::vector<Shadow> shadows_;
  mrpt::poses::CPose3D sensor_;
  double margin_;
};

}  // namespace pedtrack::track
