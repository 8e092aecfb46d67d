#pragma once
// The static objects of a scene, built from primitives: the P2-era kinds (wall, pole, box, bin,
// tree) and what real streets are full of (facades with doorways, hedges and bushes, parked cars
// and vans, bicycles, benches, sign posts). Private to the scenario loader.
#include <random>
#include <string>
#include <vector>

#include "pedtrack/sim/scenario.h"

namespace pedtrack::sim {

/// One object as a scenario declares it (or [clutter] draws it). Zero sizes mean the type's
/// default, which the street objects draw from their real range with `details`.
struct ObjectRequest {
  std::string type;
  double x = 0, y = 0, x2 = 0, y2 = 0;  ///< m; a line object (wall, facade, hedge) ends at x2, y2
  double radius = 0, height = 0, yaw = 0, width = 0, depth = 0, thickness = 0.15, crown = 1.5;
  /// m, mean free path of a ray in foliage (tree crown, bush, hedge): returns come from inside
  /// the volume and some rays pass through; 0 solid; < 0 the type's (trees solid, bushes and
  /// hedges 0.3 m).
  double foliage = -1;
};

/// Every object type, in documentation order.
const std::vector<std::string>& objectTypes();
/// Types drawn along a line from (x, y) to (x2, y2).
bool isLineObject(const std::string& type);

/// Appends the object's primitives to `s.objects` under one new object id. `where` starts the
/// error for a line object without length. `details` draws the street objects' sizes and layout
/// (a stream of the scene's own, so the other draws do not depend on it).
void addObject(Scenario& s, const ObjectRequest& r, const std::string& where,
               std::mt19937_64& details);

/// How close (m) a robot path comes to the object's footprint at leg height (a tree by its
/// trunk); INFINITY without a path.
double robotPathDistance(const Trajectory& path, const ObjectRequest& r);

}  // namespace pedtrack::sim
