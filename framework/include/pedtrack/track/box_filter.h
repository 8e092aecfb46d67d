#pragma once
// What a track learns of a 3D detector's output over time: the person's box (the sizes and the
// bottom's height change slowly for a person, the detector's boxes jitter) and how sure the
// detector was of them (its scores, smoothed the same way).
#include <algorithm>
#include <cmath>

#include "pedtrack/frame.h"

namespace pedtrack::track {

struct BoxFilter {
  /// A detection moves the box and the score by this share: about ten detections decide them.
  static constexpr double kGain = 0.2;
  Box3 box;          ///< unknown (h = 0) until a detection with a box updates the track
  double yaw = 0;    ///< rad, the boxes' heading, smoothed (meaningful once box.known())
  double score = 0;  ///< the detections' scores, smoothed; the first one's until then
  /// Moves the box and score towards a detection's by `gain` × `weight` (weight: how sure the
  /// update is that the detection is this person's, PDA's β or 1); the first are taken as they
  /// are.
  void update(const Box3& d, double detection_yaw, double detection_score, double weight,
              double gain = kGain) {
    if (!(weight > 0)) return;
    const double k = std::min(1.0, gain * weight);
    score = updates_++ ? score + k * (detection_score - score) : detection_score;
    if (!d.known()) return;
    if (!box.known()) {
      box = d;
      yaw = detection_yaw;
      return;
    }
    yaw = std::remainder(yaw + k * std::remainder(detection_yaw - yaw, 2 * M_PI), 2 * M_PI);
    box.z += k * (d.z - box.z);
    box.h += k * (d.h - box.h);
    box.w += k * (d.w - box.w);
    box.l += k * (d.l - box.l);
  }

 private:
  long updates_ = 0;
};

}  // namespace pedtrack::track
