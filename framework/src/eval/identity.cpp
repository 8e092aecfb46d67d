#include "pedtrack/eval/identity.h"

#include <cmath>
#include <map>

#include "pedtrack/assignment.h"

namespace pedtrack::eval {

double IdentityCounts::idf1() const {
  const double d = 2 * idtp + idfp + idfn;
  return d > 0 ? 2 * idtp / d : std::nan("");
}

double IdentityCounts::idp() const {
  return idtp + idfp > 0 ? idtp / (idtp + idfp) : std::nan("");
}

double IdentityCounts::idr() const {
  return idtp + idfn > 0 ? idtp / (idtp + idfn) : std::nan("");
}

IdentityCounts& IdentityCounts::operator+=(const IdentityCounts& o) {
  idtp += o.idtp;
  idfn += o.idfn;
  idfp += o.idfp;
  return *this;
}

IdentityCounts identity(const std::vector<EvalFrame>& frames, double threshold) {
  // Dense indices for the ids seen anywhere.
  std::map<long, int> truth_ix, track_ix;
  double truth_objects = 0, track_objects = 0;
  for (const EvalFrame& f : frames) {
    for (const Object& t : f.truths) truth_ix.emplace(t.id, int(truth_ix.size()));
    for (const Object& e : f.estimates) track_ix.emplace(e.id, int(track_ix.size()));
    truth_objects += double(f.truths.size());
    track_objects += double(f.estimates.size());
  }
  const int g = int(truth_ix.size()), n = int(track_ix.size());
  // Frames in which each (truth id, track id) pair is within the threshold.
  std::vector<double> together(std::size_t(g) * n, 0.0);
  for (const EvalFrame& f : frames)
    for (const Object& t : f.truths)
      for (const Object& e : f.estimates)
        if (distance(t, e) <= threshold)
          together[std::size_t(truth_ix[t.id]) * n + track_ix[e.id]] += 1;
  // Maximising the sum of `together` over a one-to-one assignment is the same as Ristani's
  // minimum of IDFP + IDFN: each unit of IDTP removes one IDFP and one IDFN. Weights are ≥ 0,
  // so assigning every possible pair never lowers the optimum.
  IdentityCounts c;
  if (g > 0 && n > 0) c.idtp = maximizeAssignment(together, g, n).cost;
  c.idfn = truth_objects - c.idtp;
  c.idfp = track_objects - c.idtp;
  return c;
}

}  // namespace pedtrack::eval
