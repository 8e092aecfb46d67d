// Shape fits: the algebraic and P3-bounded circle (the bounded one checked against Ipopt solving
// P3 eq. 1 directly), the direct ellipse fit (checked against OpenCV's), the weighted plane.
#include <catch2/catch.hpp>
#include <cmath>
#include <coin/IpIpoptApplication.hpp>
#include <coin/IpTNLP.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "irls_ground/plane.h"
#include "pedtrack/fit/circle.h"
#include "pedtrack/fit/ellipse.h"
#include "test_support.h"

using namespace pedtrack;
using fit::Circle;
using fit::Points2;
using pedtrack::test::kSanitized;

namespace {

double p3Cost(const Points2& pts, double x, double y, double r) {
  double f = 0;
  for (const auto& p : pts) {
    const double e = (p.x() - x) * (p.x() - x) + (p.y() - y) * (p.y() - y) - r * r;
    f += e * e;
  }
  return f;
}

// P3 eq. 1 as Ipopt sees it: min Σ((xᵢ−x)² + (yᵢ−y)² − r²)² over (x, y, r), r in bounds, with
// the exact gradient and Hessian.
class P3Circle : public Ipopt::TNLP {
 public:
  P3Circle(const Points2& pts, double rmin, double rmax, Circle start)
      : pts_(pts), rmin_(rmin), rmax_(rmax), start_(start) {}
  Circle result;
  double cost = INFINITY;

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac, Ipopt::Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = 3;
    m = 0;
    nnz_jac = 0;
    nnz_h = 6;
    style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index, Ipopt::Number* xl, Ipopt::Number* xu, Ipopt::Index,
                       Ipopt::Number*, Ipopt::Number*) override {
    xl[0] = xl[1] = -1e19;
    xu[0] = xu[1] = 1e19;
    xl[2] = rmin_;
    xu[2] = rmax_;
    return true;
  }
  bool get_starting_point(Ipopt::Index, bool, Ipopt::Number* x, bool, Ipopt::Number*,
                          Ipopt::Number*, Ipopt::Index, bool, Ipopt::Number*) override {
    x[0] = start_.x;
    x[1] = start_.y;
    x[2] = std::clamp(start_.r, rmin_, rmax_);
    return true;
  }
  bool eval_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number& f) override {
    f = p3Cost(pts_, x[0], x[1], x[2]);
    return true;
  }
  bool eval_grad_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number* g) override {
    g[0] = g[1] = g[2] = 0;
    for (const auto& p : pts_) {
      const double dx = p.x() - x[0], dy = p.y() - x[1];
      const double e = dx * dx + dy * dy - x[2] * x[2];
      g[0] += 2 * e * (-2 * dx);
      g[1] += 2 * e * (-2 * dy);
      g[2] += 2 * e * (-2 * x[2]);
    }
    return true;
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Number*) override {
    return true;
  }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Index,
                  Ipopt::Index*, Ipopt::Index*, Ipopt::Number*) override {
    return true;
  }
  bool eval_h(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number obj, Ipopt::Index,
              const Ipopt::Number*, bool, Ipopt::Index, Ipopt::Index* row, Ipopt::Index* col,
              Ipopt::Number* h) override {
    if (!h) {  // lower triangle, row-major
      const int r[6] = {0, 1, 1, 2, 2, 2}, c[6] = {0, 0, 1, 0, 1, 2};
      for (int k = 0; k < 6; ++k) {
        row[k] = r[k];
        col[k] = c[k];
      }
      return true;
    }
    double H[3][3] = {};
    for (const auto& p : pts_) {
      const double dx = p.x() - x[0], dy = p.y() - x[1];
      const double e = dx * dx + dy * dy - x[2] * x[2];
      const double d[3] = {-2 * dx, -2 * dy, -2 * x[2]};
      const double dd[3] = {2, 2, -2};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j <= i; ++j) H[i][j] += 2 * (d[i] * d[j] + (i == j ? e * dd[i] : 0));
    }
    const int r[6] = {0, 1, 1, 2, 2, 2}, c[6] = {0, 0, 1, 0, 1, 2};
    for (int k = 0; k < 6; ++k) h[k] = obj * H[r[k]][c[k]];
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index, const Ipopt::Number* x,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Index,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Number f,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result = {x[0], x[1], x[2]};
    cost = f;
  }

 private:
  Points2 pts_;
  double rmin_, rmax_;
  Circle start_;
};

// Ipopt from several starts (it is a local method on this non-convex cost): the best result.
Circle ipoptBest(const Points2& pts, double rmin, double rmax, const std::vector<Circle>& starts,
                 double& best_cost) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetNumericValue("tol", 1e-14);
  app->Options()->SetIntegerValue("max_iter", 500);
  // Ipopt relaxes bounds by 1e-8 by default: the radius may not leave [r_min, r_max] at all.
  app->Options()->SetNumericValue("bound_relax_factor", 0);
  REQUIRE(app->Initialize() == Ipopt::Solve_Succeeded);
  best_cost = INFINITY;
  Circle best;
  for (const Circle& s : starts) {
    Ipopt::SmartPtr<P3Circle> nlp = new P3Circle(pts, rmin, rmax, s);
    app->OptimizeTNLP(nlp);
    if (nlp->cost < best_cost) {
      best_cost = nlp->cost;
      best = nlp->result;
    }
  }
  return best;
}

Points2 arc(double cx, double cy, double r, double from, double to, int n, double noise,
            std::mt19937& rng) {
  std::normal_distribution<double> g(0, noise);
  Points2 pts;
  for (int i = 0; i < n; ++i) {
    const double a = from + (to - from) * i / std::max(1, n - 1);
    pts.emplace_back(cx + r * std::cos(a) + g(rng), cy + r * std::sin(a) + g(rng));
  }
  return pts;
}

}  // namespace

TEST_CASE("algebraic circle: exact points give the circle, degenerate input is refused",
          "[fit][circle]") {
  std::mt19937 rng(1);
  const Points2 pts = arc(1.5, -0.3, 0.055, -1.0, 1.2, 9, 0, rng);
  Circle c;
  REQUIRE(fit::fitCircleAlgebraic(pts, c));
  CHECK(c.x == Approx(1.5).margin(1e-12));
  CHECK(c.y == Approx(-0.3).margin(1e-12));
  CHECK(c.r == Approx(0.055).margin(1e-12));
  CHECK(fit::circleResidual(pts, c) < 1e-12);
  CHECK_FALSE(fit::fitCircleAlgebraic({{0, 0}, {1, 1}}, c));
  CHECK_FALSE(fit::fitCircleAlgebraic({{0, 0}, {1, 1}, {2, 2}}, c));  // collinear
  // Residual by hand: points at distances 1 and 3 from a unit circle's centre → errors 0 and 2.
  CHECK(fit::circleResidual({{1, 0}, {0, 3}}, {0, 0, 1}) == Approx(std::sqrt(2.0)));
}

TEST_CASE("P3 bounded circle: inside the bounds it is the algebraic fit", "[fit][circle]") {
  std::mt19937 rng(2);
  const Points2 pts = arc(0, 2, 0.05, 3.5, 5.5, 12, 0.002, rng);
  Circle free, bounded;
  REQUIRE(fit::fitCircleAlgebraic(pts, free));
  REQUIRE(fit::fitCircleBounded(pts, 0.03, 0.07, bounded));
  CHECK(bounded.x == free.x);
  CHECK(bounded.y == free.y);
  CHECK(bounded.r == free.r);
}

TEST_CASE("P3 bounded circle: a symmetric case solved by hand", "[fit][circle]") {
  // (−1, 0), (1, 0), (0, 1) lie on the unit circle; with r ≤ 0.5 symmetry puts the centre at
  // (0, y) with f(y) = 2(1 + y² − 0.25)² + ((1 − y)² − 0.25)². f'(y) = 0 ⇔
  // 8y(y² + 0.75) − 4(1 − y)((1 − y)² − 0.25) = 0, whose root in (0, 1) we bisect here.
  auto df = [](double y) {
    return 8 * y * (y * y + 0.75) - 4 * (1 - y) * ((1 - y) * (1 - y) - 0.25);
  };
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) ((df(0.5 * (lo + hi)) > 0) ? hi : lo) = 0.5 * (lo + hi);
  Circle c;
  REQUIRE(fit::fitCircleBounded({{-1, 0}, {1, 0}, {0, 1}}, 0.1, 0.5, c));
  CHECK(c.r == 0.5);
  CHECK(c.x == Approx(0).margin(1e-12));
  CHECK(c.y == Approx(0.5 * (lo + hi)).margin(1e-9));
}

TEST_CASE("P3 bounded circle equals Ipopt's solution of P3 eq. 1 (or beats it)",
          "[fit][circle][ipopt]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0, better = 0, on_bound = 0;
  const int trials = kSanitized ? 60 : 300;  // Ipopt from six starts per trial is slow there
  for (int trial = 0; trial < trials; ++trial) {
    // Leg-like arcs: radius 1-12 cm, 40-200° of it seen, 3-30 points, 0-1.5 cm noise.
    const double r = 0.01 + 0.11 * u(rng), span = (40 + 160 * u(rng)) * M_PI / 180;
    const double a0 = 2 * M_PI * u(rng);
    const int n = 3 + int(28 * u(rng));
    const Points2 pts = arc(3 * u(rng), 3 * u(rng), r, a0, a0 + span, n, 0.015 * u(rng), rng);
    Circle ours, kasa;
    REQUIRE(fit::fitCircleBounded(pts, 0.03, 0.07, ours));
    // Ipopt starts from the middle point, the algebraic fit and random circles: never from ours.
    std::vector<Circle> starts = {{pts[n / 2].x(), pts[n / 2].y(), 0.05}};
    if (fit::fitCircleAlgebraic(pts, kasa)) starts.push_back(kasa);
    for (int k = 0; k < 4; ++k)  // around the points, radii across the bounds
      starts.push_back({pts[n / 2].x() + 0.2 * (u(rng) - 0.5),
                        pts[n / 2].y() + 0.2 * (u(rng) - 0.5), 0.03 + 0.04 * u(rng)});
    double ipopt_cost = 0;
    const Circle ip = ipoptBest(pts, 0.03, 0.07, starts, ipopt_cost);
    const double our_cost = p3Cost(pts, ours.x, ours.y, ours.r);
    // Never worse than Ipopt's best local solution, and the same point when the costs agree.
    CHECK(our_cost <= ipopt_cost * (1 + 1e-9) + 1e-18);
    if (std::abs(our_cost - ipopt_cost) <= 1e-9 * ipopt_cost + 1e-18) {
      ++compared;
      CHECK(std::hypot(ours.x - ip.x, ours.y - ip.y) < 1e-5);
      CHECK(ours.r == Approx(ip.r).margin(1e-6));
    } else {
      ++better;  // every Ipopt start ended in another local minimum
    }
    on_bound += ours.r == 0.03 || ours.r == 0.07;
  }
  // Ipopt, started elsewhere, finds our answer in most trials and never anything lower.
  CHECK(compared + better == trials);
  CHECK(compared >= trials * 4 / 5);
  CHECK(on_bound > trials / 6);  // the bounds were active in many trials
}

TEST_CASE("P3 bounded circle: collinear points, uneven too, get the largest circle",
          "[fit][circle]") {
  // Uneven spacing on y = 2: the best r_max circle, checked against a dense search over its
  // centre (x, y) on the r = 0.07 surface.
  const Points2 line = {{0, 2}, {0.01, 2}, {0.025, 2}, {0.05, 2}, {0.09, 2}};
  Circle u;
  REQUIRE(fit::fitCircleBounded(line, 0.03, 0.07, u));
  CHECK(u.r == 0.07);
  const double ours = p3Cost(line, u.x, u.y, u.r);
  double best = INFINITY;
  for (double x = -0.1; x <= 0.2; x += 0.0005)
    for (double y = 1.9; y <= 2.1; y += 0.0005) best = std::min(best, p3Cost(line, x, y, 0.07));
  CHECK(ours <= best + 1e-12);
  CHECK(ours >= best * 0.98);
  Circle c;
  REQUIRE(fit::fitCircleBounded({{0, 0}, {0.02, 0}, {0.04, 0}, {0.06, 0}}, 0.03, 0.07, c));
  CHECK(c.r == 0.07);
  CHECK(c.x == Approx(0.03).margin(1e-9));
  // By hand: with the centre at (0.03, y) the cost is Σ(uᵢ + y² − 0.07²)², uᵢ = (xᵢ − 0.03)² ∈
  // {9, 1, 1, 9}·10⁻⁴, minimal at y² = 0.07² − mean(uᵢ) = 0.0049 − 0.0005.
  CHECK(std::abs(c.y) == Approx(std::sqrt(0.0044)).margin(1e-9));
}

TEST_CASE("direct ellipse fit: exact points recover the ellipse", "[fit][ellipse]") {
  const double cx = 2, cy = -1, a = 0.3, b = 0.15, th = 30 * M_PI / 180;
  Points2 pts;
  for (int i = 0; i < 12; ++i) {
    const double t = -0.5 + 2.0 * i / 11;  // an arc of ~115°, as a torso seen from one side
    pts.emplace_back(cx + a * std::cos(t) * std::cos(th) - b * std::sin(t) * std::sin(th),
                     cy + a * std::cos(t) * std::sin(th) + b * std::sin(t) * std::cos(th));
  }
  fit::Ellipse e;
  REQUIRE(fit::fitEllipseDirect(pts, e));
  CHECK(e.x == Approx(cx).margin(1e-9));
  CHECK(e.y == Approx(cy).margin(1e-9));
  CHECK(e.a == Approx(a).margin(1e-9));
  CHECK(e.b == Approx(b).margin(1e-9));
  CHECK(e.angle == Approx(th).margin(1e-9));
  CHECK(fit::ellipseResidual(pts, e) < 1e-9);
  CHECK_FALSE(fit::fitEllipseDirect({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, e));
}

TEST_CASE("direct ellipse fit agrees with OpenCV's cv::fitEllipseDirect", "[fit][ellipse]") {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double a = 0.15 + 0.15 * u(rng), b = 0.08 + 0.07 * u(rng), th = M_PI * u(rng);
    const double t0 = 2 * M_PI * u(rng), span = M_PI * (0.6 + 1.4 * u(rng));
    std::normal_distribution<double> g(0, 0.004);
    Points2 pts;
    std::vector<cv::Point2f> f;
    for (int i = 0; i < 25; ++i) {
      const double t = t0 + span * i / 24;
      const double x = 1 + a * std::cos(t) * std::cos(th) - b * std::sin(t) * std::sin(th) + g(rng);
      const double y = a * std::cos(t) * std::sin(th) + b * std::sin(t) * std::cos(th) + g(rng);
      pts.emplace_back(x, y);
      f.emplace_back(float(x - 1), float(y));  // OpenCV fits floats: near the origin
    }
    fit::Ellipse e;
    REQUIRE(fit::fitEllipseDirect(pts, e));
    const cv::RotatedRect r = cv::fitEllipseDirect(f);
    const double ca = 0.5 * std::max(r.size.width, r.size.height),
                 cb = 0.5 * std::min(r.size.width, r.size.height);
    if (!(ca < 10)) continue;  // a near-degenerate conic: nothing to compare
    ++checked;
    CHECK(e.x == Approx(1 + r.center.x).margin(2e-3 * ca));
    CHECK(e.y == Approx(r.center.y).margin(2e-3 * ca));
    CHECK(e.a == Approx(ca).epsilon(2e-3));
    CHECK(e.b == Approx(cb).epsilon(2e-3));
    // OpenCV's angle is of its `width` axis, in degrees: the major axis is that or 90° off.
    const double cv_major = (r.size.width >= r.size.height ? r.angle : r.angle + 90) * M_PI / 180;
    if (ca - cb > 0.02)  // a clear major axis
      CHECK(std::abs(std::remainder(e.angle - cv_major, M_PI)) < 0.01);
  }
  CHECK(checked > 190);
}

TEST_CASE("weighted plane fit: exact plane, and zero weights drop outliers", "[fit][plane]") {
  // z = 0.1 x − 0.05 y + 0.3 on a grid, plus two outliers with weight 0.
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> w;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      pts.emplace_back(i, j, 0.1 * i - 0.05 * j + 0.3);
      w.push_back(1 + 0.1 * (i + 2));
    }
  pts.emplace_back(0, 0, 5);
  w.push_back(0);
  pts.emplace_back(1, 1, -3);
  w.push_back(0);
  const GroundPlane g = fit::fitPlaneWeighted(pts, w);
  REQUIRE(g.valid);
  const Eigen::Vector3d n = Eigen::Vector3d(-0.1, 0.05, 1).normalized();
  CHECK(g.nx == Approx(n.x()).margin(1e-12));
  CHECK(g.ny == Approx(n.y()).margin(1e-12));
  CHECK(g.nz == Approx(n.z()).margin(1e-12));
  CHECK(g.height(0, 0, 0.3) == Approx(0).margin(1e-12));
  CHECK(g.height(0, 0, 1.3) == Approx(n.z()).margin(1e-12));  // 1 m above along z
  CHECK_FALSE(fit::fitPlaneWeighted({{0, 0, 0}, {1, 0, 0}}, {1, 1}).valid);
}
