// IRLS ground plane (P2 eq. 1–4): the weight, one iteration by hand, and the tracker on tilted,
// occluded and unknown-height ground.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "irls_ground/irls_ground_fit.h"

using namespace pedtrack;
using seg::IrlsParams;

namespace {

struct Cloud {
  std::vector<float> x, y, z;
  void add(double a, double b, double c) {
    x.push_back(float(a));
    y.push_back(float(b));
    z.push_back(float(c));
  }
};

// Ground z = tan(tilt)·(x cos dir + y sin dir) + h, sampled like the low VLP-16 rings (circles
// of 3.7, 4.3 and 5.1 m), the sector [a0, a1] of each left out (occluded); plus boxes standing
// on it.
Cloud scene(double tilt, double dir, double h, double a0, double a1, std::mt19937& rng) {
  Cloud c;
  std::normal_distribution<double> noise(0, 0.008);
  const double g = std::tan(tilt);
  auto ground = [&](double x, double y) { return g * (x * std::cos(dir) + y * std::sin(dir)) + h; };
  for (double r : {3.7, 4.3, 5.1, 6.2, 8.0})
    for (int i = 0; i < 1800; ++i) {
      const double a = -M_PI + 2 * M_PI * i / 1800;
      if (a >= a0 && a <= a1) continue;
      c.add(r * std::cos(a), r * std::sin(a),
            ground(r * std::cos(a), r * std::sin(a)) + noise(rng));
    }
  for (double bx : {2.0, -3.0})  // two 0.5 m boxes, 1 m tall: walls of points
    for (int i = 0; i < 20; ++i)
      for (int k = 0; k < 10; ++k) {
        const double x = bx + 0.025 * i, y = 1.0;
        c.add(x, y, ground(x, y) + 0.1 * k);
      }
  return c;
}

GroundPlane tilted(double tilt, double dir, double h) {
  const double g = std::tan(tilt);
  const Eigen::Vector3d n = Eigen::Vector3d(-g * std::cos(dir), -g * std::sin(dir), 1).normalized();
  GroundPlane p;
  p.valid = true;
  p.nx = n.x();
  p.ny = n.y();
  p.nz = n.z();
  p.d = -n.z() * h;
  return p;
}

}  // namespace

TEST_CASE("the IRLS weight is P2 eq. 4 with P2's constants", "[ground]") {
  const IrlsParams p;  // A = 0.9, B = 15, C = 0.1, D = 0.02
  // By hand: W(0) = 1/(1 + 0.9·e^−1.5) + 0.02 = 1/1.2008171 + 0.02 = 0.8527662;
  // W(0.1) = 1/1.9 + 0.02 = 0.5463158; W(1) = 1/(1 + 0.9·e^13.5) + 0.02 = 0.0200015.
  CHECK(seg::irlsWeight(0.0, p) == Approx(0.8527662).margin(1e-7));
  CHECK(seg::irlsWeight(0.1, p) == Approx(0.5463158).margin(1e-7));
  CHECK(seg::irlsWeight(1.0, p) == Approx(0.0200015).margin(1e-7));
  CHECK(seg::irlsWeight(100.0, p) == Approx(0.02).margin(1e-12));  // the floor D
}

TEST_CASE("one IRLS iteration, by hand", "[ground]") {
  // Four points on z = 0 at (±1, ±1) and one 1 m above the origin; prior z = 0. Weights 0.8527662
  // (×4) and 0.0200015; by symmetry the normal stays vertical and the plane passes through the
  // weighted mean height 0.0200015 / (4·0.8527662 + 0.0200015) = 0.0058295.
  const std::vector<Eigen::Vector3d> pts = {
      {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, 0, 1}};
  std::vector<double> w;
  const GroundPlane g = seg::irlsIteration(pts, seg::levelPlane(0), IrlsParams(), &w);
  REQUIRE(g.valid);
  CHECK(w[0] == Approx(0.8527662).margin(1e-7));
  CHECK(w[4] == Approx(0.0200015).margin(1e-7));
  CHECK(g.nz == Approx(1).margin(1e-12));
  CHECK(-g.d == Approx(0.0058295).margin(1e-7));
}

TEST_CASE("IRLS tracks a 5° slope from a level start, with P2's and refined estimates",
          "[ground]") {
  std::mt19937 rng(5);
  const double tilt = 5 * M_PI / 180, dir = 0.7;
  const GroundPlane truth = tilted(tilt, dir, 0);
  for (double refine : {0.0, 0.1}) {
    IrlsParams p;
    p.refine_band = refine;
    seg::IrlsGround g(p);
    GroundPlane est;
    for (int frame = 0; frame < 5; ++frame) {
      const Cloud c = scene(tilt, dir, 0, 9, 9, rng);
      est = g.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), nullptr, 0, 0);
    }
    REQUIRE(est.valid);
    INFO("refine_band " << refine);
    CHECK(est.angleTo(truth) * 180 / M_PI < (refine > 0 ? 0.05 : 0.5));
    CHECK(std::abs(est.d - truth.d) < 0.02);
  }
}

TEST_CASE("IRLS holds the plane when most of the ground is hidden", "[ground]") {
  std::mt19937 rng(6);
  const double tilt = 5 * M_PI / 180, dir = -0.4;
  IrlsParams p;
  p.refine_band = 0.1;
  seg::IrlsGround g(p);
  // Settle on the open slope, then lose the half of the ground in front (a crowd there).
  for (int frame = 0; frame < 3; ++frame) {
    const Cloud c = scene(tilt, dir, 0, 9, 9, rng);
    g.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), nullptr, 0, 0);
  }
  GroundPlane est;
  for (int frame = 0; frame < 10; ++frame) {
    const Cloud c = scene(tilt, dir, 0, -M_PI / 2, M_PI / 2, rng);
    est = g.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), nullptr, 0, 0);
  }
  CHECK(est.angleTo(tilted(tilt, dir, 0)) * 180 / M_PI < 1.0);
  // No ground at all: the seeds of the default plane hold it (P2's regularisation).
  seg::IrlsGround empty(IrlsParams{});
  const float none = 0;
  const GroundPlane d = empty.update(&none, &none, &none, 0, nullptr, 0, 0);
  CHECK(d.valid);
  CHECK(d.angleTo(seg::levelPlane(0)) < 1e-9);
  CHECK(d.height(0, 0, 0) == Approx(0).margin(1e-9));
}

TEST_CASE("IRLS finds the ground height when the robot frame is the sensor's", "[ground]") {
  std::mt19937 rng(7);
  IrlsParams p;  // default plane z = 0: 1.8 m above this ground
  seg::IrlsGround g(p);
  const Cloud c = scene(0, 0, -1.8, 9, 9, rng);
  const GroundPlane est = g.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), nullptr, 0, 0);
  CHECK(est.height(0, 0, -1.8) == Approx(0).margin(0.02));
  CHECK(g.defaultPlane().height(0, 0, -1.8) == Approx(0).margin(0.02));
  // Without auto_height the default plane (and its seeds) stays at the configured z = 0.
  p.auto_height = false;
  seg::IrlsGround fixed(p);
  fixed.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), nullptr, 0, 0);
  CHECK(fixed.defaultPlane().height(0, 0, 0) == Approx(0).margin(1e-12));
}

TEST_CASE("IRLS fits the lowest point of each cell, and skips removed points", "[ground]") {
  IrlsParams p;
  seg::IrlsGround g(p);
  Cloud c;
  c.add(1.01, 1.01, 0.5);  // one cell: the lowest of three is kept
  c.add(1.02, 1.03, 0.0);
  c.add(1.05, 1.08, 0.3);
  c.add(9.0, 0.0, 0.0);  // beyond max_range (5 m): not fitted
  c.add(2.01, 2.01, -0.2);
  std::vector<PointLabel> labels(c.x.size(), PointLabel::Kept);
  labels[4] = PointLabel::Removed;
  g.update(c.x.data(), c.y.data(), c.z.data(), c.x.size(), &labels, 0, 0);
  REQUIRE(g.binnedPoints().size() == 1);
  CHECK(g.binnedPoints()[0].z() == Approx(0.0));
}
