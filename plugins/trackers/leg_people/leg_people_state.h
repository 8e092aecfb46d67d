// Private to the leg_people tracker's sources: the state of a tracked leg-like object and of a
// person (two leg objects and their pose), shared by leg_people_tracker.cpp,
// leg_people_reidentify.cpp and leg_people_support.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <utility>

#include "leg_people/leg_people_tracker.h"
#include "pedtrack/track/gaussian.h"
#include "pedtrack/track/kalman.h"

namespace pedtrack::track {

// Objects are appended with increasing ids and erased in place, so a tracker's objects stay
// sorted by id: the object with `id`, or null.
template <class V>
auto findObject(V& objects, long id) -> decltype(objects.front().get()) {
  auto it = std::lower_bound(objects.begin(), objects.end(), id,
                             [](const auto& o, long v) { return o->id < v; });
  return it != objects.end() && (*it)->id == id ? it->get() : nullptr;
}

struct LegPeopleTracker::Object {
  long id = 0;
  Gaussian g;
  double last_seen = 0;
  double score_sum = 0;
  int detections = 0;
  long person = -1;
  int det = -1;  // this scan's detection, -1 none
  Eigen::Vector2d predicted = Eigen::Vector2d::Zero();
  // Held a person up alone, standing on the static scene, for one_leg_stand s (a pole or a
  // table leg a track was left on): never a person's leg again.
  bool shunned = false;
  double meanScore() const { return detections ? score_sum / detections : 0; }
  double speed() const { return g.x.segment<2>(2).norm(); }
  Eigen::Vector2d pos() const { return g.x.head<2>(); }
};

// One leg object alone holding a person up, standing: since when (NaN: not now), where (the
// first position, or the mean of all so far), and how far round it the scanner has moved (the
// range of the change of the bearing from the scanner to it, unwrapped, rad).
struct OneLegStand {
  double since = NAN;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  int n = 0;
  double bearing = 0, turn_min = 0, turn_max = 0;
  // The object at p, seen on bearing b at t: restarts the stand when p is farther than `still`
  // from `at` (the mean of the positions when `average`, else the first); returns whether the
  // stand went on.
  bool advance(double t, const Eigen::Vector2d& p, double b, double still, bool average) {
    if (std::isnan(since) || (p - at).norm() > still) {
      since = t, at = p, n = 1, bearing = b, turn_min = turn_max = 0;
      return false;
    }
    ++n;
    if (average) at += (p - at) / n;
    const double turn = wrapAngle(b - bearing);
    turn_min = std::min(turn_min, turn), turn_max = std::max(turn_max, turn);
    return true;
  }
  // Whether the stand has lasted `stand` s while the scanner moved `parallax` rad or more round it.
  bool seenRound(double t, double stand, double parallax) const {
    return t - since >= stand && turn_max - turn_min >= parallax;
  }
};

struct LegPeopleTracker::Person {
  long id = 0;
  LegPoseEstimator est;
  long left = -1, right = -1;  // object ids of the legs, -1 none
  Eigen::Vector2d origin;
  // Position and velocity when a leg was last seen.
  Eigen::Vector2d seen_at = Eigen::Vector2d::Zero(), seen_v = Eigen::Vector2d::Zero();
  double travelled = 0, last_seen = 0, backwards = 0, last_step = 0;
  double tracked = 0;  // s seen while confirmed (coastLimit)
  double since = 0;    // when the pose last (re)started: the person formed or re-identified
  double hidden = 0;   // s unseen while something nearer the scanner hid their place
  // s not seen by both legs, unexplained by anything nearer, since both were last seen
  // (max_one_leg; see updatePeople), and the unexplained time of the current gap in sightings
  double one_leg = 0, one_leg_gap = 0;
  // one_leg_stand: since when (NaN: not now) one leg object alone has held the person up
  // standing, and where, tested two ways (checkOneLegStand).
  OneLegStand on_static, in_view;
  // Where scan returns no longer count as this person's leg (legFromReturns): a leg seen only in
  // returns stood there while the scanner moved round it (checkOneLegStand).
  std::optional<Eigen::Vector2d> no_support_at;
  // Reported heading (report_heading_speed): the direction of motion when last seen moving.
  std::optional<double> motion_yaw;
  // The centre's positions when seen (t, centre; oldest first) over the longer of
  // report_heading_window and lost_velocity_window: both read their window's start from it.
  std::deque<std::pair<double, Eigen::Vector2d>> centres;
  // Seen last scan (lost_velocity_window acts on the scan a person is lost).
  bool was_seen = false;
  // Range of the leg vector's sagittal part while tentative (both legs seen, moving).
  double stride_min = INFINITY, stride_max = -INFINITY;
  // The legs' separation when both were seen (t, metres; oldest first) over the last
  // kGaitWindow: how a tentative person shows gait where the robot's motion is unknown.
  std::deque<std::pair<double, double>> separations;
  // Since when both legs have been seen in every scan where a person is expected (NaN: not now).
  double expected_since = NAN;
  double score_sum = 0;
  int score_n = 0;
  bool confirmed = false, seen = false;
  int cluster = -1;
  explicit Person(const LegPoseParams& p) : est(p) {}
};

}  // namespace pedtrack::track
