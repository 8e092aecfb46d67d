// leg_people's support for a confirmed person's legs beyond leg circles: a leg seen only in scan
// returns of no circle (support_gate), and the one-leg stand that lets go of a pole or table leg
// a walker's track was left on (one_leg_stand).
#include <cmath>

#include "leg_people/leg_people_state.h"

namespace pedtrack::track {

namespace {
// m: a leg object that stays within this of where it was first holds a person up "standing" on
// the static scene.
constexpr double kOneLegStill = 0.1;
// m, rad: one that stays within this of the mean of its positions while the scanner moves this
// far round it holds a person up where a person would show their second leg (below).
constexpr double kOneLegStillMean = 0.25, kOneLegParallax = M_PI / 4;
// m: returns this close to a person's no_support_at are not their leg; a leg object of theirs
// seen farther than kNoSupportClear from it lifts that.
constexpr double kNoSupportRadius = 0.3, kNoSupportClear = 0.5;
}  // namespace

// A confirmed person's leg that no leg circle shows this scan, seen by the returns that are
// part of no leg circle: within support_gate of where the gait predicts it (`want`), nearer it
// than the other leg's prediction, off the static scene. A leg far away or all but hidden behind
// another person's returns one or two beams, too few for a circle (P3 eq. 1 needs three), and
// one close by in wide trousers returns dozens that fit no circle (leg_tracker's positive_4
// bag); in the simulated crowds 38 % of the people missed had no leg circle, only such returns.
// The returns lie on the leg's near side, so the leg's centre is a radius behind their mean. Not
// for a tentative person (it must prove itself on leg circles), nor one lost long (their
// prediction is a guess, and a return near it anyone's).
std::optional<LegSeen> LegPeopleTracker::legFromReturns(
    const Person& q, double t, const Eigen::Vector2d& want, const Eigen::Vector2d& other,
    const std::function<bool(double, double)>& is_static, const std::vector<LegReturn>& returns,
    Eigen::Vector2d& sensor) const {
  if (p_.support_gate <= 0 || !q.confirmed || lostLong(q, t) || !motion_known_) return std::nullopt;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero(), seen_by = Eigen::Vector2d::Zero();
  int n = 0;
  for (const LegReturn& r : returns) {
    const double d = (r.p - want).norm();
    if (d > p_.support_gate || d > (r.p - other).norm()) continue;
    if (is_static && is_static(r.p.x(), r.p.y())) continue;
    if (q.no_support_at && (r.p - *q.no_support_at).norm() < kNoSupportRadius) continue;
    sum += r.p, seen_by = r.sensor, ++n;
  }
  if (n == 0) return std::nullopt;
  sensor = seen_by;
  const Eigen::Vector2d mean = sum / n;
  const Eigen::Vector2d away = mean - seen_by;
  constexpr double kLegRadius = 0.05;  // m, the middle of P3's 0.03-0.07
  const Eigen::Vector2d centre =
      away.norm() > 1e-9 ? Eigen::Vector2d(mean + kLegRadius * away.normalized()) : mean;
  return LegSeen{true, centre};
}

// A confirmed person held up by one leg object alone, standing, for one_leg_stand seconds, is a
// track left on a pole or a table leg by a walker who passed it (the assignment gave the
// walker's leg object the pole's return, and the track stayed when the walker went on) when
// either
// - the static scene is there (the object within kOneLegStill of where it first stood):
//   confirmed people are never deleted on the static scene, and keep the grid from learning more
//   of it. A person standing there is kept out of the grid, so their place is static only if it
//   was before they came; or
// - the scanner moved kOneLegParallax or more round the object meanwhile (the object within
//   kOneLegStillMean of the mean of its places: circles fitted to the three or four returns of a
//   pole 3 m away scatter by up to 0.15 m, and the leg-like corner of a bin slides along its
//   edge as the view turns; a walker's leg moves farther within one step): a person standing
//   shows both legs from directions that far apart (side by side from one, the other leg comes
//   out from behind the first from the other); a pole stays one object. A moving robot sees that
//   before the static scene learns the pole, which the track kept out of the grid (a ghost on a
//   pole for 35 s in legs_crowd_10_moving's seed 223). The static test keeps its first place:
//   with the mean, a person standing 6 m away with one leg seen on a place the grid had learned
//   was let go (legs_crowd_10 seed 112).
// One standing with both legs seen is never let go. The object is let go and shunned; the person
// coasts, to be re-identified where they really are or deleted. (Refusing them any object near
// the place afterwards, where the pole's next object appears, cost real people their legs:
// MOTA 0.8485 -> 0.8483 moving, 0.8701 -> 0.8700 static, means of four seed sets.)
void LegPeopleTracker::checkOneLegStand(Person& P, double t, const std::vector<LegDetection>& legs,
                                        const Eigen::Vector2d& sensor, LegSeen& l, LegSeen& r,
                                        const std::function<bool(double, double)>& is_static) {
  if (p_.one_leg_stand <= 0 || !P.confirmed) return;
  Object* lo = findObject(objects_, P.left);
  Object* ro = findObject(objects_, P.right);
  const bool lo_seen = lo && lo->det >= 0, ro_seen = ro && ro->det >= 0;
  if (l.seen && r.seen) {
    P.on_static.since = P.in_view.since = NAN;
    return;
  }
  if (lo_seen == ro_seen) {
    // Neither object seen: the clocks go on. A leg seen in scan returns alone (legFromReturns)
    // standing while the scanner moves round it is tested as an object would be; returns there
    // then no longer hold the person up (a ghost held up for 35 s by the edge of a bin, which it
    // kept out of the static grid, in legs_crowd_10_moving's seed 216).
    if (lo_seen || l.seen == r.seen) return;
    LegSeen& s = l.seen ? l : r;
    const Eigen::Vector2d ray = s.p - sensor;
    if (P.in_view.advance(t, s.p, std::atan2(ray.y(), ray.x()), kOneLegStillMean, true) &&
        P.in_view.seenRound(t, p_.one_leg_stand, kOneLegParallax)) {
      P.no_support_at = P.in_view.at;
      s.seen = false;
      P.in_view.since = NAN;
    }
    return;
  }
  Object* o = lo_seen ? lo : ro;
  if (P.no_support_at && (o->pos() - *P.no_support_at).norm() > kNoSupportClear)
    P.no_support_at.reset();
  const Eigen::Vector2d ray = o->pos() - legs[std::size_t(o->det)].sensor;
  const double bearing = std::atan2(ray.y(), ray.x());
  const bool on_static = P.on_static.advance(t, o->pos(), bearing, kOneLegStill, false) &&
                         t - P.on_static.since >= p_.one_leg_stand && is_static &&
                         is_static(o->pos().x(), o->pos().y());
  const bool in_view = P.in_view.advance(t, o->pos(), bearing, kOneLegStillMean, true) &&
                       P.in_view.seenRound(t, p_.one_leg_stand, kOneLegParallax);
  if (!on_static && !in_view) return;
  o->shunned = true;
  o->person = -1;
  (lo_seen ? P.left : P.right) = -1;
  (lo_seen ? l : r).seen = false;
  P.on_static.since = P.in_view.since = NAN;
}

}  // namespace pedtrack::track
