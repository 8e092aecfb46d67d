#include "leg_people/leg_people_tracker.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <tuple>

#include "leg_people/leg_people_state.h"
#include "pedtrack/assignment.h"

namespace pedtrack::track {

namespace {
// m/s: below this the filter's velocity (and so the sagittal axis) is mostly noise.
constexpr double kStrideMinSpeed = 0.2;
// s: the window over which the legs' separation must swing where the robot's motion is unknown
// (confirm_stride): about half a gait cycle and more, too short for noise to add up.
constexpr double kGaitWindow = 1.0;
// A confirmed person is standing (standing_gate) when their centre moved less than
// kStandingTravel over the last kStandingWindow (s; of which 80 % must be on record): a standing
// person's estimate wanders a few cm, a slow walker's 0.5 m.
constexpr double kStandingWindow = 1.0, kStandingTravel = 0.2;
// s: a tentative person where one is expected counts as standing after this long (three scans
// at 10 Hz); a scan seeing neither leg of theirs within this long of the last keeps their
// follow_confirm_time running (two scans missed at 10 Hz).
constexpr double kZoneStandingTime = 0.3, kDropoutGap = 0.25;
// Half-widths (m) of what the occlusion test hides: a person's body (max_coast_occluded), a leg
// with a few cm of prediction error (max_one_leg).
constexpr double kBodyHalfWidth = 0.25, kLegHalfWidth = 0.1;
}  // namespace

// Leg-like: the classifier says so on average, or the object walks (moves at init_speed or more)
// and the classifier does not rule it out. Far legs (few points) and legs unlike the training set
// score low although they move like legs; clutter that stands still never qualifies this way.
bool LegPeopleTracker::legLike(const Object& o) const {
  return o.meanScore() >= p_.leg_score ||
         (o.speed() >= p_.init_speed && o.meanScore() >= p_.moving_leg_score);
}

LegPeopleTracker::LegPeopleTracker(const LegPeopleParams& p) : p_(p), object_model_(p.object_q) {}
LegPeopleTracker::~LegPeopleTracker() = default;

void LegPeopleTracker::step(double t, const std::vector<LegDetection>& legs,
                            const std::function<bool(double, double)>& is_static,
                            const std::vector<LegReturn>& returns, bool motion_known,
                            const std::function<bool(double, double)>& expected,
                            const std::function<bool(double, double, double)>& occluded,
                            double turn_rate) {
  for (const LegDetection& l : legs) classified_ = classified_ || l.scored;
  motion_known_ = motion_known;
  turning_fast_ = p_.max_travel_turn_rate > 0 && turn_rate > p_.max_travel_turn_rate;
  expected_ = expected;
  occluded_ = occluded;
  const double dt = started_ ? std::clamp(t - t_, 0.0, 1.0) : 0.0;
  started_ = true;
  t_ = t;
  // Predictions: lone objects by their own filter, people's legs by the pose estimator.
  for (auto& o : objects_) {
    if (dt > 0) kalmanPredict(o->g, object_model_, dt);
    o->predicted = o->pos();
    o->det = -1;
  }
  for (auto& person : people_) {
    // Where the robot's motion is unknown a person's velocity in the tracking frame is theirs
    // less the robot's, which changes as the robot turns and speeds up: it predicts little
    // beyond a scan (unknown_motion_tau).
    if (!motion_known_ && p_.unknown_motion_tau > 0 && dt > 0)
      person->est.setVelocity(std::exp(-dt / p_.unknown_motion_tau) * person->est.velocity());
    person->est.predict(t);
    if (Object* o = findObject(objects_, person->left)) o->predicted = person->est.predictedLeft();
    if (Object* o = findObject(objects_, person->right))
      o->predicted = person->est.predictedRight();
  }
  associate(t, legs);
  updatePeople(t, legs, is_static, returns);
  formPeople(t, legs, is_static);
}

namespace {

// Where a window of `window` s ending at t starts in `centres` (oldest first): the newest
// position at least that old, the oldest one while the record is younger.
const std::pair<double, Eigen::Vector2d>& windowStart(
    const std::deque<std::pair<double, Eigen::Vector2d>>& centres, double t, double window) {
  std::size_t k = 0;
  while (k + 1 < centres.size() && t - centres[k + 1].first >= window) ++k;
  return centres[k];
}

}  // namespace

void LegPeopleTracker::associate(double t, const std::vector<LegDetection>& legs) {
  const int rows = int(objects_.size()), cols = int(legs.size());
  std::vector<double> cost(std::size_t(rows) * std::size_t(cols));
  // Confirmed people standing: their legs keep standing_gate (see there). So do tentative people
  // standing where a person is expected (a following robot's zone, step's `expected`), from
  // kZoneStandingTime on: the person to follow waits there, and one scan that misses both their
  // legs while clutter shows beside them must not drag them off before they are confirmed (on
  // the outdoor following recording this cost the followee 0.7 s at the start).
  std::vector<long> standing;
  if (p_.standing_gate > 0)
    for (const auto& q : people_) {
      if (q->centres.empty()) continue;
      const Eigen::Vector2d& now = q->centres.back().second;
      const bool waiting = !q->confirmed && expected_ && expected_(now.x(), now.y());
      if (!q->confirmed && !waiting) continue;
      const auto& [t0, c0] = windowStart(q->centres, t, kStandingWindow);
      if (t - t0 >= (waiting ? kZoneStandingTime : 0.8 * kStandingWindow) &&
          (now - c0).norm() < kStandingTravel)
        standing.push_back(q->id);
    }
  for (int i = 0; i < rows; ++i) {
    const Object& o = *objects_[std::size_t(i)];
    const bool still =
        o.person >= 0 && std::find(standing.begin(), standing.end(), o.person) != standing.end();
    for (int j = 0; j < cols; ++j) {
      const double d = (o.predicted - legs[std::size_t(j)].p).norm();
      cost[std::size_t(i) * cols + j] = still && d > p_.standing_gate ? INFINITY : d;  // forbidden
    }
  }
  const Assignment a = solveAssignment(cost, rows, cols, p_.gate);
  const LinearMeasurement m = positionMeasurement(4, p_.object_sigma);
  for (int i = 0; i < rows; ++i) {
    Object& o = *objects_[std::size_t(i)];
    const int j = a.row_to_col[std::size_t(i)];
    if (j < 0) continue;
    kalmanUpdate(o.g, m, legs[std::size_t(j)].p);
    o.last_seen = t;
    o.score_sum += legs[std::size_t(j)].score;
    ++o.detections;
    o.det = j;
  }
  objects_.erase(std::remove_if(objects_.begin(), objects_.end(),
                                [&](const std::unique_ptr<Object>& o) {
                                  return t - o->last_seen > p_.object_max_coast;
                                }),
                 objects_.end());
  for (int j = 0; j < cols; ++j) {
    if (a.col_to_row[std::size_t(j)] >= 0) continue;
    auto o = std::make_unique<Object>();
    o->id = ++next_object_;
    o->g.x = Eigen::Vector4d(legs[std::size_t(j)].p.x(), legs[std::size_t(j)].p.y(), 0, 0);
    o->g.P =
        Eigen::Vector4d(p_.object_sigma * p_.object_sigma, p_.object_sigma * p_.object_sigma, 1, 1)
            .asDiagonal();
    o->last_seen = t;
    o->score_sum = legs[std::size_t(j)].score;
    o->detections = 1;
    o->det = j;
    objects_.push_back(std::move(o));
  }
}

LegPeopleTracker::Person* LegPeopleTracker::personById(long id) const {
  for (auto& q : people_)
    if (q->id == id) return q.get();
  return nullptr;
}

// How long a person with no leg seen is kept. A confirmed person lost in a crowd or out of the
// scanner's view comes back most often where re-identification (lostPersonNear) finds them, and
// then needs no second confirmation; the longer they were seen while confirmed (time lost does
// not count), the surer they are a person worth waiting for. A track confirmed on clutter lives
// briefly, so it is dropped soon.
// Unseen longer than max_coast: where the person is predicted is then a guess, kept for
// re-identification only (not for adopting a low-scored leg, merging someone away, or keeping
// the static-scene grid out).
bool LegPeopleTracker::lostLong(const Person& q, double t) const {
  return t - q.last_seen > p_.max_coast;
}

double LegPeopleTracker::coastLimit(const Person& q) const {
  if (!q.confirmed) return p_.max_coast;
  return std::clamp(q.tracked, p_.max_coast, std::max(p_.max_coast, p_.max_coast_confirmed));
}

bool LegPeopleTracker::expired(const Person& q, double t) const {
  const double unseen = t - q.last_seen, limit = coastLimit(q);
  if (q.confirmed && p_.max_one_leg > 0 && q.one_leg > p_.max_one_leg) return true;
  if (p_.max_coast_occluded <= 0) return unseen > limit;
  return unseen - q.hidden > limit || unseen > std::max(limit, p_.max_coast_occluded);
}

// The way the centre moved over the last report_heading_window, when fast enough: the newest
// position at least that old is the reference, the first one while the person is younger.
// Either way they must have moved report_heading_speed times the window (0.15 m): scan-to-scan
// jitter of a new or re-identified pose is not a direction. Then c joins the record, kept as
// long as the longer of the two windows needs it.
void LegPeopleTracker::recordCentre(Person& q, double t, const Eigen::Vector2d& c) const {
  // Time that does not advance adds nothing; time that went back (a bag replayed in a loop, a
  // clock reset) makes every stored position meaningless.
  if (!q.centres.empty() && t <= q.centres.back().first) {
    if (t == q.centres.back().first) return;
    q.centres.clear();
  }
  if (p_.report_heading_speed > 0 && !q.centres.empty()) {
    const auto& [t0, c0] = windowStart(q.centres, t, p_.report_heading_window);
    const Eigen::Vector2d moved = c - c0;
    const double span = std::max(t - t0, p_.report_heading_window);
    if (moved.norm() >= p_.report_heading_speed * span)
      q.motion_yaw = std::atan2(moved.y(), moved.x());
  }
  const double keep = std::max(p_.report_heading_speed > 0 ? p_.report_heading_window : 0.0,
                               p_.lost_velocity_window);
  q.centres.emplace_back(t, c);
  while (q.centres.size() > 1 && t - q.centres[1].first >= keep) q.centres.pop_front();
}

void LegPeopleTracker::updateLostVelocity(Person& q) const {
  const bool lost_now = !q.seen && q.was_seen;
  q.was_seen = q.seen;
  if (p_.lost_velocity_window <= 0 || !lost_now || !q.confirmed || q.centres.size() < 2) return;
  const auto& [t1, c1] = q.centres.back();
  const auto& [t0, c0] = windowStart(q.centres, t1, p_.lost_velocity_window);
  // Seen for less than a fifth of the window: too short a stretch to tell a walk.
  const double span = t1 - t0;
  if (span < 0.2 * p_.lost_velocity_window) return;
  const Eigen::Vector2d mean_v = (c1 - c0) / span;
  if (mean_v.norm() < q.est.velocity().norm()) q.est.setVelocity(mean_v);
}

void LegPeopleTracker::updatePeople(double t, const std::vector<LegDetection>& legs,
                                    const std::function<bool(double, double)>& is_static,
                                    const std::vector<LegReturn>& returns) {
  // Legs' object ids that no longer exist are freed.
  for (auto& person : people_) {
    if (!findObject(objects_, person->left)) person->left = -1;
    if (!findObject(objects_, person->right)) person->right = -1;
  }
  const auto claims = nearestClaims(t, is_static);
  for (auto& person : people_) {
    Person& P = *person;
    Object* lo = findObject(objects_, P.left);
    Object* ro = findObject(objects_, P.right);
    LegSeen l, r;
    Eigen::Vector2d sensor = Eigen::Vector2d::Zero();
    P.cluster = -1;
    const double dt_person = t - P.last_step;
    P.last_step = t;
    if (lo && lo->det >= 0) l = {true, lo->pos()};
    if (ro && ro->det >= 0) r = {true, ro->pos()};
    // A free leg-like object near the person's missing leg becomes that leg (for a confirmed
    // person whose gait still predicts it, any object from moving_leg_score on: below).
    // Where the robot's motion is unknown, the followed person's leg object unseen this scan is
    // replaced, like a missing one, by a seen object where the gait predicts that leg, and a
    // tentative person's leg there becomes theirs (see followed_).
    const bool followed = takesFollowedClaim(P);
    for (int side = 0; side < 2; ++side) {
      long& slot = side == 0 ? P.left : P.right;
      Object* held = side == 0 ? lo : ro;
      if (!wantsLeg(slot, held, followed)) continue;
      const Eigen::Vector2d want = side == 0 ? P.est.predictedLeft() : P.est.predictedRight();
      Object* best = nullptr;
      // A confirmed person's gait predicts where their leg is (mayAdopt).
      const bool predicted = P.confirmed && (l.seen || r.seen || !lostLong(P, t));
      double bd = adoptGate(P, t);
      for (auto& o : objects_) {
        const double d = (o->pos() - want).norm();
        if (d >= bd || !mayAdopt(*o, predicted, followed, is_static)) continue;
        // A confirmed person's missing leg is predicted nearer it (nearestClaims).
        if (auto c = claims.find(o->id); c != claims.end() && c->second < d - 1e-9) continue;
        bd = d, best = o.get();
      }
      if (!best) continue;
      if (Person* owner = best->person >= 0 ? personById(best->person) : nullptr)
        for (long* leg : {&owner->left, &owner->right})
          if (*leg == best->id) *leg = -1;
      if (held) held->person = -1;
      best->person = P.id;
      slot = best->id;
      // A tentative person proves itself by walking on its own legs: one that hops from object to
      // object (a cluster of chair and table legs) starts its travel over with each new leg.
      if (!P.confirmed) {
        P.origin = {P.est.x(), P.est.y()};
        P.travelled = 0;
        P.stride_min = INFINITY, P.stride_max = -INFINITY;
        P.separations.clear();
      }
      (side == 0 ? l : r) = {true, best->pos()};
    }
    if (!l.seen && !r.seen)
      if (Object* o = reidentifyByOneLeg(P, t, is_static))
        (P.left == o->id ? l : r) = {true, o->pos()};
    // Legs no circle shows, from the returns of no circle near where they are predicted.
    const Eigen::Vector2d want_l = P.est.predictedLeft(), want_r = P.est.predictedRight();
    if (!l.seen)
      if (auto s = legFromReturns(P, t, want_l, want_r, is_static, returns, sensor)) l = *s;
    if (!r.seen)
      if (auto s = legFromReturns(P, t, want_r, want_l, is_static, returns, sensor)) r = *s;
    checkOneLegStand(P, t, legs, sensor, l, r, is_static);
    P.seen = l.seen || r.seen;
    // Not seen by both legs where nothing nearer explains it (max_one_leg): scans with one leg
    // seen and the other's place open to view, and the gaps between such sightings in which the
    // person's place was open to view, each gap counted up to max_coast (a person lost long and
    // found again by one leg is re-identification's case, not a track living on single
    // sightings).
    if (l.seen && r.seen) {
      P.one_leg = P.one_leg_gap = 0;
    } else if (P.confirmed) {
      const auto hidden = [&](const Eigen::Vector2d& p, double half_width) {
        return occluded_ && occluded_(p.x(), p.y(), half_width);
      };
      if (!P.seen) {
        if (!hidden({P.est.x(), P.est.y()}, kBodyHalfWidth)) P.one_leg_gap += dt_person;
      } else {
        P.one_leg += std::min(P.one_leg_gap, p_.max_coast);
        P.one_leg_gap = 0;
        if (!hidden(l.seen ? want_r : want_l, kLegHalfWidth)) P.one_leg += dt_person;
      }
    }
    if (P.seen) {
      P.last_seen = t;
      for (Object* o : {findObject(objects_, P.left), findObject(objects_, P.right)})
        if (o && o->det >= 0) {
          P.score_sum += o->meanScore();
          ++P.score_n;
        }
    }
    // The scanner that saw the visible leg is the apex of eq. 6's hidden area.
    for (Object* o : {findObject(objects_, P.left), findObject(objects_, P.right)})
      if (o && o->det >= 0) {
        sensor = legs[std::size_t(o->det)].sensor;
        P.cluster = legs[std::size_t(o->det)].cluster;
      }
    P.est.update(l, r, sensor);
    if (P.est.legsSwapped()) std::swap(P.left, P.right);
    const Eigen::Vector2d c(P.est.x(), P.est.y());
    // Travel counts only where a leg was seen: a coasting filter that extrapolates a jump (a leg
    // re-associated to clutter) would otherwise confirm a ghost without any measurement. Nor
    // where the robot's motion is unknown: the way starts again where the person is. Nor the way
    // seen while the robot turns fast (max_travel_turn_rate): it is left out of the travel.
    if (!motion_known_)
      P.origin = c;
    else if (!P.confirmed && P.seen && turning_fast_)
      P.origin += c - P.seen_at;
    if (P.seen) P.travelled = std::max(P.travelled, (c - P.origin).norm());
    if (P.seen) P.seen_at = c, P.seen_v = P.est.velocity();
    if (P.seen && P.confirmed) P.tracked += dt_person;
    // Unseen where something nearer hides them: their absence is explained (max_coast_occluded).
    if (P.seen)
      P.hidden = 0;
    else if (P.confirmed && occluded_ && occluded_(P.est.x(), P.est.y(), kBodyHalfWidth))
      P.hidden += dt_person;
    if (P.seen) recordCentre(P, t, c);
    updateLostVelocity(P);
    const Eigen::Vector2d v = P.est.velocity();
    // Gait evidence: the legs' separation along the direction of motion swings as they scissor.
    if (!P.confirmed && l.seen && r.seen && v.norm() > kStrideMinSpeed) {
      const double sagittal = (l.p - r.p).dot(v.normalized());
      P.stride_min = std::min(P.stride_min, sagittal);
      P.stride_max = std::max(P.stride_max, sagittal);
    }
    const bool strode = p_.confirm_stride <= 0 || P.stride_max - P.stride_min >= p_.confirm_stride;
    // Gait without a frame: the distance between the legs, which neither the robot's turn nor
    // its travel changes, swinging as they scissor (see confirm_stride).
    if (!P.confirmed && l.seen && r.seen) {
      P.separations.emplace_back(t, (l.p - r.p).norm());
      while (t - P.separations.front().first > kGaitWindow) P.separations.pop_front();
    }
    bool gait_alone = false;
    if (!motion_known_ && !P.confirmed && p_.confirm_stride > 0 && P.separations.size() >= 3) {
      const auto [lo, hi] =
          std::minmax_element(P.separations.begin(), P.separations.end(),
                              [](const auto& a, const auto& b) { return a.second < b.second; });
      gait_alone = hi->second - lo->second >= p_.confirm_stride;
    }
    // Nor is a person confirmed while faster than a brisk walk: that speed is, far more often
    // than a runner, the filter reacting to a leg that jumped to a neighbouring object. Legs the
    // classifier is sure of need less travel: a person standing by the robot, shifting their
    // weight, is a person before they walk off.
    // (Only where a classifier scored the legs: unscored legs all score 1.)
    const double score = P.score_sum / std::max(1, P.score_n);
    const bool sure = classified_ && p_.sure_leg_score < 1 && score >= p_.sure_leg_score;
    const double travel =
        sure ? std::min(p_.sure_confirm_travel, p_.confirm_travel) : p_.confirm_travel;
    // Where a person is expected (a following robot's zone), legs seen standing are enough.
    const bool both_expected =
        !P.confirmed && l.seen && r.seen && expected_ && expected_(c.x(), c.y());
    // A scan that sees neither leg (a dropout: on the outdoor following recording two scans
    // within 0.3 s missed a standing followee whole) says nothing against their standing there.
    const bool dropout = !P.seen && t - P.last_seen <= kDropoutGap;
    if (both_expected) {
      if (std::isnan(P.expected_since)) P.expected_since = t;
    } else if (!dropout) {
      P.expected_since = NAN;
    }
    const bool stood_expected = p_.follow_confirm_time > 0 && both_expected &&
                                t - P.expected_since >= p_.follow_confirm_time;
    const bool walked = strode && P.travelled >= travel &&
                        (score >= p_.leg_score || P.travelled >= p_.moving_confirm_travel);
    if (!P.confirmed && P.seen && v.norm() <= p_.max_confirm_speed &&
        (walked || ((gait_alone || stood_expected) && score >= p_.leg_score))) {
      P.confirmed = true;
      // From now on the walker's own (smoother) noise: see legPeoplePoseDefaults().
      P.est.retune(p_.pose);
    }
    // Walking backwards fast for long is a facing chosen wrong at the start.
    const Eigen::Vector2d fwd(std::cos(P.est.yaw()), std::sin(P.est.yaw()));
    P.backwards = v.norm() > p_.flip_speed && v.dot(fwd) < 0 ? P.backwards + dt_person : 0;
    if (P.backwards >= p_.flip_time) {
      P.est.turnAround();
      std::swap(P.left, P.right);
      P.backwards = 0;
    }
    // Legs drifting apart: the one farther from the body is someone else's.
    lo = findObject(objects_, P.left);
    ro = findObject(objects_, P.right);
    if (lo && ro && (lo->pos() - ro->pos()).norm() > p_.max_leg_spread) {
      Object* far = (lo->pos() - c).norm() > (ro->pos() - c).norm() ? lo : ro;
      far->person = -1;
      (far == lo ? P.left : P.right) = -1;
    }
  }
  // A tentative person on the static scene (a start-up pair of furniture legs, before the grid
  // knew them) is deleted: no person starts there. Confirmed people stay, however long they
  // stand still.
  if (is_static)
    for (auto& person : people_)
      if (!person->confirmed && is_static(person->est.left().x(), person->est.left().y()) &&
          is_static(person->est.right().x(), person->est.right().y()))
        person->last_seen = -INFINITY;
  // Two people closer than merge_distance are one: bodies do not interpenetrate. It is a person
  // split in two (each leg seen twice by scanners merged out of step) or a lost track that
  // coasted beside its person's new one. The tentative one goes, else the one seen less
  // recently, else the one whose legs were found last (formed or re-identified later: the less
  // sure of whom it follows; a person re-identified onto a passer-by's legs had taken the
  // passer-by's id away: ID switches in the crowds -2 to -6 %), else the newer.
  if (p_.merge_distance > 0)
    for (auto& a : people_)
      for (auto& b : people_) {
        if (a == b || a->last_seen == -INFINITY || b->last_seen == -INFINITY) continue;
        // A confirmed person coasting beside one seen is likely hidden by them, not a copy.
        if (a->confirmed && b->confirmed && !(a->seen && b->seen)) continue;
        // One lost long is only kept for re-identification: where they were predicted says too
        // little to delete someone seen there.
        if ((a->confirmed && lostLong(*a, t)) || (b->confirmed && lostLong(*b, t))) continue;
        if (std::hypot(a->est.x() - b->est.x(), a->est.y() - b->est.y()) >= p_.merge_distance)
          continue;
        Person* drop = a->confirmed != b->confirmed   ? (a->confirmed ? b : a).get()
                       : a->last_seen != b->last_seen ? (a->last_seen < b->last_seen ? a : b).get()
                       : a->since != b->since         ? (a->since > b->since ? a : b).get()
                                                      : (a->id > b->id ? a : b).get();
        drop->last_seen = -INFINITY;
      }
  // Deleted people free their legs.
  for (auto& person : people_) {
    if (!expired(*person, t)) continue;
    for (auto& o : objects_)
      if (o->person == person->id) o->person = -1;
  }
  people_.erase(std::remove_if(people_.begin(), people_.end(),
                               [&](const std::unique_ptr<Person>& q) { return expired(*q, t); }),
                people_.end());
}

void LegPeopleTracker::formPeople(double t, const std::vector<LegDetection>& legs,
                                  const std::function<bool(double, double)>& is_static) {
  // Free, leg-like objects seen this scan, paired closest first.
  std::vector<Object*> free;
  for (auto& o : objects_)
    if (o->person < 0 && o->det >= 0 && !o->shunned && legLike(*o)) free.push_back(o.get());
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < free.size(); ++i)
    for (std::size_t j = i + 1; j < free.size(); ++j) {
      const double d = (free[i]->pos() - free[j]->pos()).norm();
      if (d <= p_.pair_distance) pairs.emplace_back(d, i, j);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used(free.size(), false);
  for (const auto& [d, i, j] : pairs) {
    if (used[i] || used[j]) continue;
    Object* a = free[i];
    Object* b = free[j];
    if (is_static &&
        (is_static(a->pos().x(), a->pos().y()) || is_static(b->pos().x(), b->pos().y())))
      continue;
    used[i] = used[j] = true;
    // Facing: the legs' motion when they move, else towards the scanner seeing them.
    const Eigen::Vector2d mid = 0.5 * (a->pos() + b->pos());
    const Eigen::Vector2d v = 0.5 * (a->g.x.segment<2>(2) + b->g.x.segment<2>(2));
    double yaw;
    if (v.norm() >= p_.init_speed) {
      yaw = std::atan2(v.y(), v.x());
    } else {
      const Eigen::Vector2d to_sensor = legs[std::size_t(a->det)].sensor - mid;
      yaw = std::atan2(to_sensor.y(), to_sensor.x());
    }
    // A lost person re-identified keeps id, confirmation and score; the pose restarts at the
    // new legs (facing as they walk, else as last known), W0 and gait are learned afresh.
    Person* person = v.norm() <= p_.max_confirm_speed ? lostPersonNear(t, mid) : nullptr;
    if (person) {
      for (auto& o : objects_)
        if (o->person == person->id) o->person = -1;
      if (v.norm() < p_.init_speed) yaw = person->est.yaw();
      person->est = LegPoseEstimator(p_.pose);
      person->centres.clear();  // the way from where they were lost is no walk seen
      person->no_support_at.reset();
    } else {
      // A tentative person's filter follows its legs closely (P3's noise), so that a leg
      // jumping to a neighbouring object shows as a speed no walker has (max_confirm_speed) and a
      // pair whose association hops along furniture does not pass for a smooth walk.
      LegPoseParams tentative = p_.pose;
      tentative.var_ax = tentative.var_ay = p_.tentative_accel_var;
      tentative.sigma_xy = p_.tentative_sigma_xy;
      tentative.motion_heading_sigma = 0;  // its motion is still to be proven a walk
      people_.push_back(std::make_unique<Person>(tentative));
      person = people_.back().get();
      person->id = ++next_person_;
      person->origin = mid;
      person->score_sum = a->meanScore() + b->meanScore();
      person->score_n = 2;
    }
    person->est.start(t, a->pos(), b->pos(), yaw);
    person->since = t;
    const bool a_left = person->est.left() == a->pos();
    person->left = a_left ? a->id : b->id;
    person->right = a_left ? b->id : a->id;
    a->person = b->person = person->id;
    person->last_seen = person->last_step = t;
    person->seen_at = mid;
    person->seen_v = v;
    person->backwards = 0;
    person->seen = true;
    person->cluster = legs[std::size_t(a->det)].cluster;
  }
}

std::vector<PersonState> LegPeopleTracker::people() const {
  std::vector<PersonState> out;
  out.reserve(people_.size());
  for (const auto& q : people_) {
    PersonState s;
    s.id = q->id;
    s.confirmed = q->confirmed;
    s.seen = q->seen;
    s.unseen = t_ - q->last_seen;
    s.lost = lostLong(*q, t_);
    s.p = {q->est.x(), q->est.y()};
    s.v = q->est.velocity();
    s.yaw = q->motion_yaw.value_or(q->est.yaw());
    s.cov = q->est.state().P.topLeftCorner<2, 2>();
    s.score = q->score_sum / std::max(1, q->score_n);
    s.zone = q->est.zone();
    s.cluster = q->cluster;
    out.push_back(s);
  }
  return out;
}

std::vector<Eigen::Vector2d> LegPeopleTracker::occupiedByPeople() const {
  std::vector<Eigen::Vector2d> out;
  for (const auto& q : people_) {
    // A person lost long no longer keeps the grid out of where they were last predicted (a
    // chair put there meanwhile must become static scene).
    if (lostLong(*q, t_)) continue;
    // Tentative people are not kept out: a pair of table legs taken for a person at start-up
    // must still become static scene, which then deletes it (see updatePeople).
    if (!q->confirmed) continue;
    out.emplace_back(q->est.x(), q->est.y());
    out.push_back(q->est.left());
    out.push_back(q->est.right());
  }
  return out;
}

std::size_t LegPeopleTracker::objectCount() const {
  return objects_.size();
}

}  // namespace pedtrack::track
