#include "scene_objects.h"

#include <algorithm>
#include <cmath>

#include "pedtrack/errors.h"

namespace pedtrack::sim {
namespace {

// The radius of a round object (pole, bin, tree trunk): `radius`, else its type's default.
double roundRadius(const std::string& type, double radius) {
  if (radius > 0) return radius;
  return type == "bin" ? 0.25 : type == "tree" ? 0.15 : 0.05;
}

double uniform(std::mt19937_64& g, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}

// Boxes along the segment a-b (≤1 m each, so ray culling stays tight), `half` thick each side
// of the line moved `offset` along its left normal, z in [z0, z1].
void lineBoxes(std::vector<Primitive>& out, Eigen::Vector2d a, Eigen::Vector2d b, double offset,
               double half, double z0, double z1, int owner, double foliage = 0) {
  const Eigen::Vector2d e = b - a;
  const double len = e.norm();
  if (len < 1e-6 || z1 <= z0) return;
  const Eigen::Vector2d n = Eigen::Vector2d(-e.y(), e.x()) / len * offset;
  const int k = std::max(1, static_cast<int>(std::ceil(len)));
  const double yaw = std::atan2(e.y(), e.x());
  for (int i = 0; i < k; ++i) {
    const Eigen::Vector2d c = a + e * ((i + 0.5) / k) + n;
    Primitive p = Primitive::box(c.x(), c.y(), yaw, 0.5 * len / k, half, z0, z1, owner);
    p.foliage = foliage;
    out.push_back(p);
  }
}

// A facade from a to b: walls of `height` with doorways every 4-9 m (1.0-1.6 m wide, 2.1-2.5 m
// high, their door 0.3-0.8 m back in a recess), its street side on the segment's left.
void facade(std::vector<Primitive>& out, Eigen::Vector2d a, Eigen::Vector2d b, double height,
            double thick, int owner, std::mt19937_64& g) {
  const Eigen::Vector2d e = b - a;
  const double len = e.norm(), half = 0.5 * thick;
  const Eigen::Vector2d u = e / len;
  double s = uniform(g, 1.0, 5.0);  // where the next doorway starts
  double from = 0;
  while (s + 1.0 < len) {
    const double w = uniform(g, 1.0, 1.6), door_h = uniform(g, 2.1, 2.5);
    const double recess = uniform(g, 0.3, 0.8), to = std::min(len, s + w);
    lineBoxes(out, a + u * from, a + u * s, 0, half, 0, height, owner);
    // Above the doorway, and its door deep in the recess, with the recess's sides.
    lineBoxes(out, a + u * s, a + u * to, 0, half, door_h, height, owner);
    lineBoxes(out, a + u * s, a + u * to, -recess, half, 0, door_h, owner);
    const Eigen::Vector2d n(-u.y(), u.x());
    for (const double at : {s, to}) {
      const Eigen::Vector2d p = a + u * at;
      lineBoxes(out, p, p - n * recess, 0, 0.05, 0, door_h, owner);
    }
    from = to;
    s = to + uniform(g, 3.0, 8.0);
  }
  lineBoxes(out, a + u * from, b, 0, half, 0, height, owner);
}

// A car or a van along `yaw` centred at (x, y): a body on its wheels, a cabin on top.
void vehicle(std::vector<Primitive>& out, bool van, double x, double y, double yaw, int owner,
             std::mt19937_64& g) {
  const double L = van ? uniform(g, 4.8, 5.4) : uniform(g, 4.2, 4.8);
  const double W = van ? uniform(g, 1.9, 2.0) : uniform(g, 1.7, 1.85);
  const double sill = van ? 0.35 : 0.3, body = van ? 1.05 : uniform(g, 0.9, 1.0);
  const double roof = van ? uniform(g, 1.9, 2.3) : uniform(g, 1.4, 1.5);
  const double c = std::cos(yaw), s = std::sin(yaw);
  auto at = [&](double along, double across, double hu, double hv, double z0, double z1) {
    out.push_back(Primitive::box(x + c * along - s * across, y + s * along + c * across, yaw, hu,
                                 hv, z0, z1, owner));
  };
  at(0, 0, L / 2, W / 2, sill, body);
  // A car's cabin sits back from its bonnet; a van's rises behind a short bonnet.
  if (van)
    at(-0.1 * L, 0, 0.4 * L, W / 2, body, roof);
  else
    at(-0.08 * L, 0, 0.28 * L, W / 2 - 0.06, body, roof);
  for (const double along : {-0.32 * L, 0.32 * L})
    for (const double side : {-1.0, 1.0}) at(along, side * (W / 2 - 0.12), 0.3, 0.1, 0, sill);
}

// A bicycle standing along `yaw`: two wheels (thin discs as slabs), a frame and handlebars of
// thin tubes: few, scattered returns.
void bicycle(std::vector<Primitive>& out, double x, double y, double yaw, int owner) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  auto p = [&](double along, double across, double z) {
    return Eigen::Vector3d(x + c * along - s * across, y + s * along + c * across, z);
  };
  // Each wheel a rim of eight tube segments (0.34 m radius): seen from the side, a beam meets
  // the rim twice, not a disc.
  for (const double along : {-0.52, 0.52})
    for (int k = 0; k < 8; ++k) {
      const double a0 = k * M_PI / 4, a1 = (k + 1) * M_PI / 4, R = 0.34;
      out.push_back(Primitive::capsule(p(along + R * std::cos(a0), 0, 0.36 + R * std::sin(a0)),
                                       p(along + R * std::cos(a1), 0, 0.36 + R * std::sin(a1)),
                                       0.02, owner));
    }
  const double r = 0.02;
  out.push_back(Primitive::capsule(p(-0.52, 0, 0.35), p(-0.12, 0, 0.85), r, owner));   // seat stay
  out.push_back(Primitive::capsule(p(0, 0, 0.3), p(-0.12, 0, 0.85), r, owner));        // seat tube
  out.push_back(Primitive::capsule(p(0, 0, 0.3), p(0.42, 0, 0.9), r, owner));          // down tube
  out.push_back(Primitive::capsule(p(-0.12, 0, 0.8), p(0.42, 0, 0.9), r, owner));      // top tube
  out.push_back(Primitive::capsule(p(0.52, 0, 0.35), p(0.42, 0, 1.0), r, owner));      // fork
  out.push_back(Primitive::capsule(p(0.42, -0.3, 1.0), p(0.42, 0.3, 1.0), r, owner));  // bars
  out.push_back(Primitive::box(p(-0.14, 0, 0).x(), p(-0.14, 0, 0).y(), yaw, 0.12, 0.07, 0.86, 0.92,
                               owner));  // saddle
}

// A park bench along `yaw`: a seat, a backrest behind it, four legs.
void bench(std::vector<Primitive>& out, double x, double y, double yaw, int owner,
           std::mt19937_64& g) {
  const double L = uniform(g, 1.6, 2.0), seat = uniform(g, 0.42, 0.47);
  const double c = std::cos(yaw), s = std::sin(yaw);
  auto at = [&](double along, double across, double hu, double hv, double z0, double z1) {
    out.push_back(Primitive::box(x + c * along - s * across, y + s * along + c * across, yaw, hu,
                                 hv, z0, z1, owner));
  };
  at(0, 0, L / 2, 0.22, seat - 0.05, seat);
  at(0, -0.22, L / 2, 0.03, seat + 0.05, seat + 0.45);
  for (const double along : {-L / 2 + 0.1, L / 2 - 0.1})
    for (const double across : {-0.18, 0.18}) at(along, across, 0.03, 0.03, 0, seat - 0.05);
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& objectTypeDocs() {
  static const std::vector<std::pair<std::string, std::string>> d = {
      {"wall", "a straight wall from (x, y) to (x2, y2), `thickness` thick, 2.5 m high"},
      {"pole", "a round post, `radius` 0.05 m, 2.5 m high"},
      {"box", "a box `width` x `depth`, 0.8 m high, turned by `yaw`"},
      {"bin", "a round bin, `radius` 0.25 m, 0.9 m high"},
      {"tree",
       "a trunk (`radius` 0.15 m) under a ball crown (`crown` 1.5 m) topping out at 5 m; "
       "the crown solid unless `foliage` is set"},
      {"facade",
       "a building front from (x, y) to (x2, y2), 5-12 m high and at least 0.2 m thick, "
       "with a doorway every 4-9 m (1.0-1.6 m wide, 2.1-2.5 m high, its door 0.3-0.8 m "
       "back in a recess); the street side is on the left of (x, y) -> (x2, y2)"},
      {"hedge",
       "foliage from (x, y) to (x2, y2), 0.6-1.0 m thick, 1.0-1.8 m high (`foliage` 0.3 m)"},
      {"bush",
       "one foliage ball (`radius` 0.35-0.8 m) on the ground, 0.6-1.6 m high, a tall one "
       "on a second, lower ball (`foliage` 0.3 m)"},
      {"car",
       "a car along `yaw`: 4.2-4.8 x 1.7-1.85 m, its body from 0.3 m to 0.9-1.0 m on four "
       "wheels, a cabin set back to 1.4-1.5 m"},
      {"van",
       "a van along `yaw`: 4.8-5.4 x 1.9-2.0 m, its body from 0.35 m, a box behind a short "
       "bonnet to 1.9-2.3 m"},
      {"bicycle",
       "a bicycle standing along `yaw`: two 0.68 m rims, a frame, handlebars and a "
       "saddle of 2 cm tubes (a few scattered returns)"},
      {"bench",
       "a park bench along `yaw`: a 1.6-2.0 m seat 0.42-0.47 m up, a backrest to 0.9 m "
       "behind it (on its right of `yaw`), four legs"},
      {"signpost",
       "a 3.5 cm post 2.4-3.0 m high with a 0.6 x 0.6 m plate at its top, the plate "
       "across `yaw`"},
  };
  return d;
}

const std::vector<std::string>& objectTypes() {
  static const std::vector<std::string> t = [] {
    std::vector<std::string> names;
    for (const auto& [name, doc] : objectTypeDocs()) names.push_back(name);
    return names;
  }();
  return t;
}

bool isLineObject(const std::string& type) {
  return type == "wall" || type == "facade" || type == "hedge";
}

void addObject(Scenario& s, const ObjectRequest& r, const std::string& where, std::mt19937_64& g) {
  auto h = [&](double def) { return r.height > 0 ? r.height : def; };
  const int owner = objectOwner(++s.object_count);
  const std::string& type = r.type;
  const Eigen::Vector2d a(r.x, r.y), b(r.x2, r.y2);
  if (isLineObject(type) && (b - a).norm() < 1e-6)
    throw ConfigError(where + ": a " + type + " needs two ends");
  auto& out = s.objects;
  if (type == "wall") {
    lineBoxes(out, a, b, 0, 0.5 * r.thickness, 0, h(2.5), owner);
  } else if (type == "pole") {
    const double rr = roundRadius(type, r.radius);
    out.push_back(Primitive::ellipticCylinder(r.x, r.y, 0, rr, rr, 0, h(2.5), owner));
  } else if (type == "bin") {
    const double rr = roundRadius(type, r.radius);
    out.push_back(Primitive::ellipticCylinder(r.x, r.y, 0, rr, rr, 0, h(0.9), owner));
  } else if (type == "box") {
    out.push_back(Primitive::box(r.x, r.y, r.yaw, 0.5 * r.width, 0.5 * r.depth, 0, h(0.8), owner));
  } else if (type == "tree") {
    const double rr = roundRadius(type, r.radius), top = h(5.0);
    const double cr = std::min(r.crown, 0.5 * top);
    out.push_back(Primitive::ellipticCylinder(r.x, r.y, 0, rr, rr, 0, top - cr, owner));
    if (cr > 0) {
      Primitive crown = Primitive::sphere({r.x, r.y, top - cr}, cr, owner);
      crown.foliage = std::max(0.0, r.foliage);
      out.push_back(crown);
    }
  } else if (type == "facade") {
    facade(out, a, b, h(uniform(g, 5, 12)), std::max(0.2, r.thickness), owner, g);
  } else if (type == "hedge") {
    const double half = uniform(g, 0.3, 0.5);  // 0.6-1.0 m thick
    lineBoxes(out, a, b, 0, half, 0, h(uniform(g, 1.0, 1.8)), owner,
              r.foliage < 0 ? 0.3 : r.foliage);
  } else if (type == "bush") {
    // One or two overlapping foliage balls on the ground, 0.6-1.6 m high.
    const double rr = r.radius > 0 ? r.radius : uniform(g, 0.35, 0.8);
    const double top = h(uniform(g, 0.6, 1.6)), mfp = r.foliage < 0 ? 0.3 : r.foliage;
    const double zc = std::max(rr * 0.6, top - rr);
    Primitive ball = Primitive::sphere({r.x, r.y, zc}, rr, owner);
    ball.foliage = mfp;
    out.push_back(ball);
    if (zc - rr > 0.3) {  // a tall bush: a second ball down to the ground
      Primitive low = Primitive::sphere({r.x, r.y, 0.8 * rr}, 0.8 * rr, owner);
      low.foliage = mfp;
      out.push_back(low);
    }
  } else if (type == "car" || type == "van") {
    vehicle(out, type == "van", r.x, r.y, r.yaw, owner, g);
  } else if (type == "bicycle") {
    bicycle(out, r.x, r.y, r.yaw, owner);
  } else if (type == "bench") {
    bench(out, r.x, r.y, r.yaw, owner, g);
  } else if (type == "signpost") {
    const double top = h(uniform(g, 2.4, 3.0)), rr = r.radius > 0 ? r.radius : 0.035;
    out.push_back(Primitive::ellipticCylinder(r.x, r.y, 0, rr, rr, 0, top, owner));
    out.push_back(Primitive::box(r.x, r.y, r.yaw, 0.3, 0.015, top - 0.6, top, owner));
  }
}

double robotPathDistance(const Trajectory& path, const ObjectRequest& o) {
  double best = INFINITY;
  // The footprint's radius round its centre (line objects: the segment).
  const double reach = o.type == "box"                      ? 0.5 * std::hypot(o.width, o.depth)
                       : o.type == "car" || o.type == "van" ? 2.8
                       : o.type == "bicycle" || o.type == "bench" ? 1.0
                       : o.type == "bush"                         ? std::max(o.radius, 0.8)
                                                                  : roundRadius(o.type, o.radius);
  for (const MotionSample& m : path.samples()) {
    const Eigen::Vector2d r(m.x, m.y);
    double d;
    if (isLineObject(o.type)) {
      const Eigen::Vector2d p0(o.x, o.y), p1(o.x2, o.y2), e = p1 - p0;
      const double u = std::clamp((r - p0).dot(e) / e.squaredNorm(), 0.0, 1.0);
      d = (r - (p0 + u * e)).norm() - 0.5 * std::max(o.thickness, o.type == "hedge" ? 1.0 : 0.0);
    } else {
      d = (r - Eigen::Vector2d(o.x, o.y)).norm() - reach;
    }
    best = std::min(best, d);
  }
  return best;
}

}  // namespace pedtrack::sim
