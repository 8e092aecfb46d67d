// Adoption of a free leg-like object by a person's missing leg (leg_people): which objects a
// person may take there, within which gate, and the nearest claim on each object.
#include <algorithm>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "leg_people/leg_people_state.h"

namespace pedtrack::track {

// The gate within which P's missing leg takes a free object: leg_gate, and behind an occlusion
// a confirmed person's prediction grows uncertain, so the gate widens with the time unseen (a
// tentative person must still prove itself on its own legs). Not where the robot's motion is
// unknown: the gait's prediction is then made in a frame that moves by an unknown amount, and
// clutter streams past it.
double LegPeopleTracker::adoptGate(const Person& P, double t) const {
  double gate = p_.pose.leg_gate;
  if (P.confirmed && motion_known_)
    gate += std::min(p_.reacquire_spread * (t - P.last_seen), p_.reacquire_max);
  return gate;
}

// Where the robot's motion is unknown, the followed person has the first claim on legs where their
// gait predicts them (followed_).
bool LegPeopleTracker::takesFollowedClaim(const Person& P) const {
  return P.confirmed && P.id == followed_ && !motion_known_;
}

// Whether a person's leg slot (an object id, -1 none; `held` that object) takes a free object this
// scan: it holds none, or it is the followed person's (takesFollowedClaim) and went unseen.
bool LegPeopleTracker::wantsLeg(long slot, const Object* held, bool followed) {
  return slot < 0 || (followed && held && held->det < 0);
}

// Whether P's missing leg may take o, apart from how far it is. `predicted`: P's gait still
// predicts where the leg is (a confirmed person seen this scan or not lost long), so an object
// there needs only the score a walking object needs (far legs have few points and score low); not
// once they are lost long: a chair there would hold the track for good (confirmed people are never
// deleted on the static scene, and keep the grid from learning it). `followed`: see followed_.
bool LegPeopleTracker::mayAdopt(const Object& o, bool predicted, bool followed,
                                const std::function<bool(double, double)>& is_static) const {
  if (o.det < 0 || o.shunned) return false;
  if (o.person >= 0) {  // only the followed person takes a tentative person's leg
    if (!followed) return false;
    const Person* owner = personById(o.person);
    if (!owner || owner->confirmed) return false;
  }
  if (!legLike(o) && !(predicted && o.meanScore() >= p_.moving_leg_score)) return false;
  // A door jamb or table leg next to a passing person must not become their leg: once adopted
  // it would hold the track on the furniture after the person left.
  return !(is_static && is_static(o.pos().x(), o.pos().y()));
}

// Object id -> the distance from the nearest confirmed person's missing leg that may take it this
// scan (its prediction, within that person's adoptGate). A free object within the gates of
// several people's missing legs goes to the nearest confirmed claim, whoever is updated first:
// in a crowd the person updated first otherwise took, within a gate widened while they were
// hidden, a passer-by's leg whose object their own track had just lost, and followed the
// passer-by off. Tentative people's claims do not count: on negative_2 a tentative pair of
// furniture legs then kept an object it would have swapped for a nearer one (starting its travel
// over), and walked into confirmation (confirmed tracks over its 9 runs 23 -> 41).
std::unordered_map<long, double> LegPeopleTracker::nearestClaims(
    double t, const std::function<bool(double, double)>& is_static) const {
  std::unordered_map<long, double> claims;
  for (const auto& person : people_) {
    const Person& P = *person;
    if (!P.confirmed) continue;
    const Object* lo = findObject(objects_, P.left);
    const Object* ro = findObject(objects_, P.right);
    const bool l_seen = lo && lo->det >= 0, r_seen = ro && ro->det >= 0;
    const bool followed = takesFollowedClaim(P);
    const bool predicted = l_seen || r_seen || !lostLong(P, t);  // P is confirmed
    const double gate = adoptGate(P, t);
    for (int side = 0; side < 2; ++side) {
      if (!wantsLeg(side == 0 ? P.left : P.right, side == 0 ? lo : ro, followed)) continue;
      const Eigen::Vector2d want = side == 0 ? P.est.predictedLeft() : P.est.predictedRight();
      for (const auto& o : objects_) {
        const double d = (o->pos() - want).norm();
        if (d >= gate || !mayAdopt(*o, predicted, followed, is_static)) continue;
        auto [it, fresh] = claims.emplace(o->id, d);
        if (!fresh) it->second = std::min(it->second, d);
      }
    }
  }
  return claims;
}

}  // namespace pedtrack::track
