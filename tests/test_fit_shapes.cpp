// Shape models of P1 and P0: the constrained RANSAC torso ellipse (P1 §III-B), the bounding boxes
// (minimum-area box checked against OpenCV's cv::minAreaRect, the L-shape fit), the centroids and
// the RANSAC circle.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "pedtrack/fit/boxes.h"
#include "pedtrack/fit/circle.h"
#include "pedtrack/fit/ellipse_ransac.h"

using namespace pedtrack;
using fit::Points2;
using fit::TorsoEllipse;

namespace {

double modPi(double a) {
  return std::abs(std::remainder(a, M_PI));
}

// The point of `e` at parameter t: β cos t along the facing direction θ, α sin t across it.
Eigen::Vector2d onEllipse(const TorsoEllipse& e, double t) {
  const Eigen::Vector2d f(std::cos(e.theta), std::sin(e.theta)),
      a(-std::sin(e.theta), std::cos(e.theta));
  return Eigen::Vector2d(e.x, e.y) + e.beta * std::cos(t) * f + e.alpha * std::sin(t) * a;
}

// The outward normal of `e` at parameter t.
Eigen::Vector2d normalAt(const TorsoEllipse& e, double t) {
  const Eigen::Vector2d f(std::cos(e.theta), std::sin(e.theta)),
      a(-std::sin(e.theta), std::cos(e.theta));
  return (std::cos(t) / e.beta * f + std::sin(t) / e.alpha * a).normalized();
}

// `n` points on the half of `e` seen from `origin` (outward normal towards it), noise σ.
Points2 visibleHalf(const TorsoEllipse& e, const Eigen::Vector2d& origin, int n, double sigma,
                    std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::normal_distribution<double> g(0, sigma);
  Points2 pts;
  while (int(pts.size()) < n) {
    const double t = u(rng);
    const Eigen::Vector2d p = onEllipse(e, t);
    if (normalAt(e, t).dot(origin - p) <= 0) continue;
    pts.push_back(p + Eigen::Vector2d(g(rng), g(rng)));
  }
  return pts;
}

bool satisfies(const TorsoEllipse& e, const fit::EllipseRansacParams& p, double prior) {
  const double eps = 1e-12;
  bool ok = e.alpha >= e.beta - eps && e.alpha >= p.alpha_min - eps &&
            e.alpha <= p.alpha_max + eps && e.beta >= p.beta_min - eps &&
            e.beta <= p.beta_max + eps && e.theta > -M_PI && e.theta <= M_PI;
  if (std::isfinite(prior)) ok = ok && modPi(e.theta - prior) <= p.theta_window + 1e-9;
  return ok;
}

}  // namespace

TEST_CASE("ellipse deviation (P1 eq. 7) by hand", "[fit][ellipse_ransac]") {
  const TorsoEllipse e{1, 2, 0.3, 0.2, 0.1};
  const Eigen::Vector2d c(1, 2), across(-std::sin(0.3), std::cos(0.3)),
      facing(std::cos(0.3), std::sin(0.3));
  CHECK(fit::ellipseDeviation(e, c) == Approx(-1).margin(1e-12));
  CHECK(fit::ellipseDeviation(e, c + 0.2 * across) == Approx(0).margin(1e-12));  // α across θ
  CHECK(fit::ellipseDeviation(e, c - 0.4 * across) == Approx(3).margin(1e-12));
  CHECK(fit::ellipseDeviation(e, c + 0.1 * facing) == Approx(0).margin(1e-12));  // β along θ
  CHECK(fit::ellipseDeviation(e, c + 0.2 * facing) == Approx(3).margin(1e-12));
  CHECK(fit::ellipseDeviation(e, c + 0.1 * across) == Approx(-0.75).margin(1e-12));
}

TEST_CASE("RANSAC torso ellipse recovers the torso among arm points", "[fit][ellipse_ransac]") {
  // 70 points (σ = 5 mm) on the half of the torso seen from the sensor, 30 arm points (30 %)
  // 5-25 cm outside the ellipse beside the shoulders (±α axis): 20 by one, 10 by the other.
  const TorsoEllipse truth{3, 1, 0.6, 0.18, 0.09};
  const Eigen::Vector2d o(0, 0), c(truth.x, truth.y), across(-std::sin(0.6), std::cos(0.6)),
      facing(std::cos(0.6), std::sin(0.6));
  // P1's parameters without the centre correction, which moves the centre 2-3 cm back by design
  // (its own test case below).
  fit::EllipseRansacParams params;
  params.center_correction = false;
  const int trials = 20;
  int recovered = 0, plain_recovered = 0, arms_flagged = 0;
  for (int seed = 0; seed < trials; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(100 + seed);
    Points2 pts = visibleHalf(truth, o, 70, 0.005, rng);
    std::uniform_real_distribution<double> out(0.05, 0.25), side(-0.03, 0.03);
    for (int i = 0; i < 30; ++i) {
      const double sign = (i < 20 ? 1 : -1) * (seed % 2 ? 1 : -1);
      pts.push_back(c + sign * (truth.alpha + out(rng)) * across + side(rng) * facing);
    }
    std::mt19937 ransac_rng(seed);
    const fit::EllipseRansacResult r = fit::fitEllipseRansac(pts, o, NAN, params, ransac_rng);
    REQUIRE(r.ok);
    const TorsoEllipse& e = r.ellipse;
    const double dc = std::hypot(e.x - truth.x, e.y - truth.y), dth = modPi(e.theta - 0.6);
    // Every trial: near the torso, the size within 2 cm (α may sit on its 0.2 bound), the arms
    // mostly flagged and the torso kept (worst when written: 3.4 cm, 0.14 rad, 24 and 70).
    CHECK(dc < 0.045);
    CHECK(dth < 0.25);
    CHECK(std::abs(e.alpha - truth.alpha) <= 0.02 + 1e-12);
    CHECK(std::abs(e.beta - truth.beta) <= 0.02 + 1e-12);
    int arms_out = 0, torso_in = 0;
    for (int i = 0; i < 100; ++i) (i < 70 ? torso_in : arms_out) += (r.inlier[i] != 0) == (i < 70);
    CHECK(arms_out >= 22);
    CHECK(torso_in >= 68);
    arms_flagged += arms_out;
    CHECK(r.inliers == std::count(r.inlier.begin(), r.inlier.end(), 1));
    CHECK(r.iterations >= 1);
    CHECK(r.iterations <= params.max_iterations);
    recovered += dc < 0.02 && dth < 0.1;
    // The same constrained fit on all the points at once, for contrast: the arms drag it off.
    TorsoEllipse plain;
    REQUIRE(fit::fitEllipseConstrained(pts, o, NAN, params,
                                       fit::initialEllipse(pts, o, NAN, params), plain));
    plain_recovered +=
        std::hypot(plain.x - truth.x, plain.y - truth.y) < 0.02 && modPi(plain.theta - 0.6) < 0.1;
    // Deterministic for a given rng state.
    std::mt19937 again(seed);
    const fit::EllipseRansacResult r2 = fit::fitEllipseRansac(pts, o, NAN, params, again);
    CHECK(r2.ellipse.x == r.ellipse.x);
    CHECK(r2.ellipse.theta == r.ellipse.theta);
    CHECK(r2.iterations == r.iterations);
  }
  // Centre within 2 cm and θ within 0.1 rad in most trials (14 of 20 when written; the plain fit
  // 4): the winner is fitted to 9 points, and the truncated score W prefers an α on its bound
  // that absorbs the arm points nearest the shoulders, so some trials end 2-3.5 cm off.
  CHECK(recovered >= 12);
  CHECK(plain_recovered <= 8);
  CHECK(arms_flagged >= 540);  // 90 % of the arm points (95 % when written)
}

TEST_CASE("constrained ellipse: every constraint holds on random input", "[fit][ellipse_ransac]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    fit::EllipseRansacParams p;
    p.alpha_min = 0.05 + 0.1 * u(rng);
    p.alpha_max = p.alpha_min + 0.2 * u(rng);
    p.beta_min = 0.02 + 0.1 * u(rng);
    p.beta_max = p.beta_min + 0.1 * u(rng);
    if (p.beta_min > p.alpha_max) std::swap(p.beta_min, p.alpha_max);  // keep eq. 8 feasible
    p.theta_window = 0.5 * u(rng);
    p.center_correction = u(rng) < 0.5;
    const double prior = u(rng) < 0.3 ? NAN : 10 * (u(rng) - 0.5);
    const int n = 3 + int(40 * u(rng));
    const Eigen::Vector2d at(20 * (u(rng) - 0.5), 20 * (u(rng) - 0.5));
    const double spread = 0.05 + u(rng);
    Points2 pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(at + spread * Eigen::Vector2d(u(rng) - 0.5, u(rng) - 0.5));
    const Eigen::Vector2d o(u(rng) - 0.5, u(rng) - 0.5);
    TorsoEllipse start{at.x(), at.y(), 10 * (u(rng) - 0.5), u(rng), u(rng)}, e;
    REQUIRE(fit::fitEllipseConstrained(pts, o, prior, p, start, e));
    CHECK(satisfies(e, p, prior));
    REQUIRE(fit::fitEllipseConstrained(pts, o, prior, p, fit::initialEllipse(pts, o, prior, p), e));
    CHECK(satisfies(e, p, prior));
    const fit::EllipseRansacResult r = fit::fitEllipseRansac(pts, o, prior, p, rng);
    REQUIRE(r.ok);
    CHECK(satisfies(r.ellipse, p, prior));
  }
  TorsoEllipse e;
  CHECK_FALSE(fit::fitEllipseConstrained({{0, 0}, {1, 0}}, {0, 0}, NAN, {}, {}, e));
  std::mt19937 r(1);
  CHECK_FALSE(fit::fitEllipseRansac({{0, 0}, {1, 0}}, {0, 0}, NAN, {}, r).ok);
}

TEST_CASE("constrained ellipse: the constraints are active when the data want otherwise",
          "[fit][ellipse_ransac]") {
  fit::EllipseRansacParams p;
  p.center_correction = false;
  p.solver_iterations = 100;
  const Eigen::Vector2d o(0, 0);
  SECTION("a 0.3 m circle gets the largest ellipse") {
    Points2 pts;
    for (int i = 0; i < 24; ++i)
      pts.emplace_back(4 + 0.3 * std::cos(i * M_PI / 12), 0.3 * std::sin(i * M_PI / 12));
    TorsoEllipse e;
    REQUIRE(fit::fitEllipseConstrained(pts, o, NAN, p, fit::initialEllipse(pts, o, NAN, p), e));
    CHECK(e.alpha == p.alpha_max);
    CHECK(e.beta == p.beta_max);
    CHECK(std::hypot(e.x - 4, e.y) < 1e-3);
  }
  const TorsoEllipse truth{3, 1, 0.6, 0.18, 0.09};
  Points2 arc;
  for (int i = 0; i <= 20; ++i) arc.push_back(onEllipse(truth, M_PI / 2 + i * M_PI / 20));
  SECTION("without a prior (or a prior π away) the exact ellipse comes back") {
    for (double prior : {double(NAN), 0.6 + M_PI, 0.6 - M_PI + 0.2}) {
      CAPTURE(prior);
      TorsoEllipse e;
      REQUIRE(
          fit::fitEllipseConstrained(arc, o, prior, p, fit::initialEllipse(arc, o, prior, p), e));
      CHECK(std::hypot(e.x - 3, e.y - 1) < 1e-6);
      CHECK(modPi(e.theta - 0.6) < 1e-6);
      CHECK(e.alpha == Approx(0.18).margin(1e-6));
      CHECK(e.beta == Approx(0.09).margin(1e-6));
    }
  }
  SECTION("the prior window clamps θ, modulo π") {
    for (double prior : {0.0, M_PI, -M_PI, 1.2 + M_PI}) {
      CAPTURE(prior);
      TorsoEllipse e;
      REQUIRE(
          fit::fitEllipseConstrained(arc, o, prior, p, fit::initialEllipse(arc, o, prior, p), e));
      // The window's edge nearer the data's 0.6.
      const double edge = prior + std::copysign(p.theta_window, std::remainder(0.6 - prior, M_PI));
      CHECK(modPi(e.theta - edge) < 1e-9);
      CHECK(e.theta > -M_PI);
      CHECK(e.theta <= M_PI);
    }
  }
  SECTION("a body longer front to back than across gets α = β (eq. 8)") {
    // 0.12 m along the facing direction, 0.07 across; the prior keeps θ from turning by 90°.
    p.alpha_min = 0.05;
    p.beta_max = 0.15;
    const TorsoEllipse deep{3, 1, 0.6, 0.07, 0.12};
    Points2 pts;
    for (int i = 0; i < 24; ++i) pts.push_back(onEllipse(deep, i * M_PI / 12));
    TorsoEllipse e;
    REQUIRE(fit::fitEllipseConstrained(pts, o, 0.6, p, fit::initialEllipse(pts, o, 0.6, p), e));
    CHECK(e.alpha >= e.beta);
    CHECK(e.alpha == Approx(e.beta).margin(1e-9));
    CHECK(e.alpha > 0.07);
    CHECK(e.alpha < 0.12);
    // Without the prior θ turns instead, and the ellipse comes back with its axes swapped.
    REQUIRE(fit::fitEllipseConstrained(pts, o, NAN, p, fit::initialEllipse(pts, o, NAN, p), e));
    CHECK(modPi(e.theta - 0.6 - M_PI / 2) < 1e-6);
    CHECK(e.alpha == Approx(0.12).margin(1e-6));
    CHECK(e.beta == Approx(0.07).margin(1e-6));
  }
}

TEST_CASE("the centre correction moves the centre away from the sensor", "[fit][ellipse_ransac]") {
  // The front arc of a torso facing the sensor at (0, 0).
  const TorsoEllipse truth{4, 2, std::atan2(-2.0, -4.0), 0.17, 0.08};
  Points2 arc;
  for (int i = 0; i <= 16; ++i) arc.push_back(onEllipse(truth, -M_PI / 2 + i * M_PI / 16));
  const Eigen::Vector2d o(0, 0);
  fit::EllipseRansacParams p;
  p.solver_iterations = 100;
  TorsoEllipse with, without;
  p.center_correction = false;
  REQUIRE(fit::fitEllipseConstrained(arc, o, NAN, p, fit::initialEllipse(arc, o, NAN, p), without));
  p.center_correction = true;
  REQUIRE(fit::fitEllipseConstrained(arc, o, NAN, p, fit::initialEllipse(arc, o, NAN, p), with));
  CHECK(std::hypot(without.x - 4, without.y - 2) < 1e-6);  // exact points: the truth
  const Eigen::Vector2d shift(with.x - without.x, with.y - without.y);
  const Eigen::Vector2d sight = Eigen::Vector2d(without.x, without.y).normalized();
  // P1's correction is strong: about 2 cm here, on exact points.
  CHECK(shift.norm() > 0.005);
  CHECK(shift.norm() < 0.05);
  CHECK(shift.dot(sight) > 0.9 * shift.norm());  // straight away from the sensor
}

TEST_CASE("convex hull and minimum-area box", "[fit][box]") {
  // A square with interior and collinear edge points: the four corners, counter-clockwise.
  const Points2 sq = {{0, 0}, {1, 0}, {0.5, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {1, 0.3}, {0, 0}};
  const Points2 h = fit::convexHull(sq);
  REQUIRE(h.size() == 4);
  double area2 = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const auto& a = h[i];
    const auto& b = h[(i + 1) % h.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  CHECK(area2 == Approx(2));  // positive: counter-clockwise
  // A known rectangle: centre (2, −1), sides 1 × 0.4 at 0.4 rad, corners and inside points.
  const double th = 0.4;
  const Eigen::Vector2d c(2, -1), a(std::cos(th), std::sin(th)), b(-std::sin(th), std::cos(th));
  Points2 rect;
  for (double i : {-1.0, -0.3, 0.2, 1.0})
    for (double j : {-1.0, 0.5, 1.0}) rect.push_back(c + 0.5 * i * a + 0.2 * j * b);
  fit::OrientedBox box;
  REQUIRE(fit::minAreaBox(rect, box));
  CHECK(box.x == Approx(2).margin(1e-12));
  CHECK(box.y == Approx(-1).margin(1e-12));
  CHECK(box.angle > -M_PI / 2);
  CHECK(box.angle <= M_PI / 2);
  if (std::abs(box.angle - th) < 1e-9) {
    CHECK(box.half_a == Approx(0.5));
    CHECK(box.half_b == Approx(0.2));
  } else {
    CHECK(box.angle == Approx(th - M_PI / 2));
    CHECK(box.half_a == Approx(0.2));
    CHECK(box.half_b == Approx(0.5));
  }
  CHECK_FALSE(fit::minAreaBox({}, box));
  REQUIRE(fit::minAreaBox({{1, 1}, {3, 3}, {2, 2}}, box));  // collinear: a degenerate box
  CHECK(box.half_b == Approx(0).margin(1e-12));
  CHECK(box.half_a == Approx(std::sqrt(2.0)));
  CHECK(box.angle == Approx(M_PI / 4));
}

TEST_CASE("minimum-area box equals OpenCV's cv::minAreaRect", "[fit][box]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int ties = 0;
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const int n = 3 + int(60 * u(rng));
    const double cx = 10 * (u(rng) - 0.5), cy = 10 * (u(rng) - 0.5);
    const double sx = 0.1 + 2 * u(rng), sy = 0.1 + 2 * u(rng), rot = M_PI * u(rng);
    Points2 pts;
    std::vector<cv::Point2f> f;
    for (int i = 0; i < n; ++i) {
      const double x = sx * (u(rng) - 0.5), y = sy * (u(rng) - 0.5);
      // Float coordinates for both, so OpenCV and we see the same points.
      const cv::Point2f q(float(cx + x * std::cos(rot) - y * std::sin(rot)),
                          float(cy + x * std::sin(rot) + y * std::cos(rot)));
      f.push_back(q);
      pts.emplace_back(q.x, q.y);
    }
    fit::OrientedBox box;
    REQUIRE(fit::minAreaBox(pts, box));
    const cv::RotatedRect r = cv::minAreaRect(f);
    const double ours = 4 * box.half_a * box.half_b, theirs = double(r.size.area());
    CHECK(ours == Approx(theirs).epsilon(1e-4));
    CHECK(ours <= theirs * (1 + 1e-5));
    // The same box, or a tie: OpenCV's orientation (in doubles) encloses the points in the same
    // area to 1e-6 (two hull edges giving equal areas; OpenCV, in floats, took the other one).
    if (std::hypot(box.x - r.center.x, box.y - r.center.y) > 1e-4) {
      ++ties;
      const double a = r.angle * M_PI / 180;
      const Eigen::Vector2d e1(std::cos(a), std::sin(a)), e2(-e1.y(), e1.x());
      double lo1 = INFINITY, hi1 = -INFINITY, lo2 = INFINITY, hi2 = -INFINITY;
      for (const auto& p : pts) {
        lo1 = std::min(lo1, p.dot(e1));
        hi1 = std::max(hi1, p.dot(e1));
        lo2 = std::min(lo2, p.dot(e2));
        hi2 = std::max(hi2, p.dot(e2));
      }
      CHECK((hi1 - lo1) * (hi2 - lo2) == Approx(ours).epsilon(1e-6));
    }
    // Every point inside our box.
    const Eigen::Vector2d e1(std::cos(box.angle), std::sin(box.angle)), e2(-e1.y(), e1.x());
    for (const auto& p : pts) {
      const Eigen::Vector2d d = p - Eigen::Vector2d(box.x, box.y);
      CHECK(std::abs(d.dot(e1)) <= box.half_a + 1e-9);
      CHECK(std::abs(d.dot(e2)) <= box.half_b + 1e-9);
    }
  }
  CHECK(ties <= 6);
}

TEST_CASE("L-shape box recovers the orientation of an L of points", "[fit][box]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 0.01);
  const double th = 0.3;
  const Eigen::Vector2d corner(5, 2), a(std::cos(th), std::sin(th)), b(-std::sin(th), std::cos(th));
  Points2 pts;
  for (int i = 0; i <= 40; ++i) pts.push_back(corner + 1.6 * i / 40 * a + g(rng) * b);
  for (int i = 1; i <= 20; ++i) pts.push_back(corner + 0.7 * i / 20 * b + g(rng) * a);
  fit::OrientedBox box;
  REQUIRE(fit::lShapeBox(pts, box));
  CHECK(std::abs(std::remainder(box.angle - th, M_PI / 2)) < M_PI / 180);
  // The extents: about 1.6 × 0.7, the corner at one end.
  CHECK(2 * std::max(box.half_a, box.half_b) == Approx(1.6).margin(0.05));
  CHECK(2 * std::min(box.half_a, box.half_b) == Approx(0.7).margin(0.05));
  CHECK_FALSE(fit::lShapeBox({}, box));
}

TEST_CASE("centroids", "[fit][box]") {
  const Points2 pts = {{2, 4}, {4, 4}, {3, 4}};
  CHECK(fit::centroid(pts).isApprox(Eigen::Vector2d(3, 4)));
  CHECK(fit::centroid({}) == Eigen::Vector2d::Zero());
  // |(3, 4)| = 5: 0.5 m further along the line of sight is (3, 4)·5.5/5.
  const Eigen::Vector2d c = fit::centroidBehindSurface(pts, {0, 0}, 0.5);
  CHECK(c.x() == Approx(3.3));
  CHECK(c.y() == Approx(4.4));
  const Eigen::Vector2d d = fit::centroidBehindSurface(pts, {3, 0}, 0.25);
  CHECK(d.x() == Approx(3));
  CHECK(d.y() == Approx(4.25));
  CHECK(fit::centroidBehindSurface(pts, {3, 4}, 0.5).isApprox(Eigen::Vector2d(3, 4)));
}

TEST_CASE("RANSAC circle: a circle among 30 % outliers, and the radius bounds hold",
          "[fit][circle]") {
  std::uniform_real_distribution<double> u(0, 1);
  for (int seed = 0; seed < 10; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    std::normal_distribution<double> g(0, 0.005);
    Points2 pts;
    for (int i = 0; i < 70; ++i) {
      const double t = 2 * M_PI * u(rng);
      pts.emplace_back(2 + 0.2 * std::cos(t) + g(rng), 3 + 0.2 * std::sin(t) + g(rng));
    }
    for (int i = 0; i < 30; ++i) pts.emplace_back(1.5 + u(rng), 2.5 + u(rng));
    fit::CircleRansacParams p;
    fit::Circle c;
    int inliers = 0;
    REQUIRE(fit::fitCircleRansac(pts, p, rng, c, &inliers));
    CHECK(std::hypot(c.x - 2, c.y - 3) < 0.01);
    CHECK(c.r == Approx(0.2).margin(0.01));
    CHECK(inliers >= 68);
    CHECK(inliers <= 85);  // some outliers fall within 3 cm of the circle
  }
  // Bounds: random clouds give circles within them, or none.
  std::mt19937 rng(3);
  fit::CircleRansacParams p;
  p.r_min = 0.15;
  p.r_max = 0.25;
  int found = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Points2 pts;
    const int n = 3 + int(30 * u(rng));
    for (int i = 0; i < n; ++i) pts.emplace_back(u(rng), u(rng));
    fit::Circle c;
    if (!fit::fitCircleRansac(pts, p, rng, c)) continue;
    ++found;
    CHECK(c.r >= p.r_min);
    CHECK(c.r <= p.r_max);
  }
  CHECK(found > 50);
  // Exact circles of radius 0.5 and 0.05: no sample lies within the bounds.
  for (double r : {0.5, 0.05}) {
    Points2 pts;
    for (int i = 0; i < 20; ++i) pts.emplace_back(r * std::cos(0.3 * i), r * std::sin(0.3 * i));
    fit::Circle c;
    CHECK_FALSE(fit::fitCircleRansac(pts, p, rng, c));
  }
  fit::Circle c;
  CHECK_FALSE(fit::fitCircleRansac({{0, 0}, {1, 1}}, p, rng, c));
}
