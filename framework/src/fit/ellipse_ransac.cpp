// P1 §III-B: the torso ellipse of eq. 6–13 fitted by RANSAC.
//
// Eq. 12 is solved by projected Levenberg–Marquardt on q = (x, y, θ, α, β). J of eq. 6 is a sum
// of squares: the residuals sᵢ (eq. 7) and gᵢ = exp((rᵢ − r_c)/2) with rᵢ = |pᵢ − o|,
// r_c = |c − o|, so gᵢ² = exp(rᵢ − r_c). With (x̃, ỹ) = pᵢ − c, u = −x̃ sin θ + ỹ cos θ (across the
// shoulders) and v = −x̃ cos θ − ỹ sin θ (minus the part along θ), s = u²/α² + v²/β² − 1 and
//     ∂s/∂x = 2u sin θ/α² + 2v cos θ/β²,   ∂s/∂y = −2u cos θ/α² + 2v sin θ/β²,
//     ∂s/∂θ = 2uv (1/α² − 1/β²),           ∂s/∂α = −2u²/α³,   ∂s/∂β = −2v²/β³,
// and ∂gᵢ/∂c = −gᵢ/2 · n with n = (c − o)/r_c. The gᵢ share their centre dependence, so their
// part collapses to G = Σ gᵢ² = E·exp(−r_c) (E = Σ exp(rᵢ), computed once per fit). All sums over
// the points reduce to moments of (u, v) (see evaluate()): no allocation, 5 × 5 normal equations.
//
// The step: the samples of a RANSAC run mostly hold an arm point or two, so their residuals are
// large, and there Gauss–Newton's JᵀJ is a poor model that crawls (20 steps without converging
// were the rule). The LM step therefore uses the exact Hessian JᵀJ + Σ rₖ∇²rₖ whenever its damped
// form is positive definite, and the damped JᵀJ otherwise (far from a minimum, typically the
// first step); both are analytic. Damping is Marquardt's λ·diag with Nielsen's update.
//
// Constraints (eq. 8–11) are kept by projecting every iterate: an iterate with β > α is first
// turned by π/2 with α and β swapped (the same ellipse) when θ may turn that far, so that a fit
// started a quarter turn off does not stall on the circle α = β (where ∂s/∂θ = 0); then α and β
// are clamped to their bounds and, when still β > α, both set to the clamped mean (the Euclidean
// projection onto eq. 8 within the boxes); θ is moved to θ' + d with d = θ − θ' wrapped to
// (−π/2, π/2] and clamped to ±θ_th (s does not change under θ → θ + π, so this is eq. 11 modulo
// π). Before that, bounded components at a bound are held for the step when the gradient or the
// step pushes them out (a simple active set), and the step is shortened to end at the first bound
// it meets, so that clipping does not spoil it.
#include "pedtrack/fit/ellipse_ransac.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "pedtrack/fit/boxes.h"  // wrapHalfPi

namespace pedtrack::fit {
namespace {

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat5 = Eigen::Matrix<double, 5, 5>;
enum : int { kX = 0, kY = 1, kTheta = 2, kAlpha = 3, kBeta = 4 };

double wrapPi(double a) {  // (−π, π]
  a = std::remainder(a, 2 * M_PI);
  return a <= -M_PI ? a + 2 * M_PI : a;
}

// A feasible set exists and every s is defined: β > 0 and some α ≥ β in the boxes.
bool validParams(const EllipseRansacParams& p) {
  return std::isfinite(p.alpha_min) && std::isfinite(p.alpha_max) && std::isfinite(p.beta_min) &&
         std::isfinite(p.beta_max) && p.beta_min > 0 && p.beta_min <= p.beta_max &&
         p.alpha_min <= p.alpha_max && p.beta_min <= p.alpha_max && p.theta_window >= 0;
}

// The constraint set of eq. 8–11 for one fit.
struct Feasible {
  double a0, a1, b0, b1;  // eq. 9, 10
  bool theta_bounded;     // eq. 11 in force (finite θ' and θ_th < π/2)
  double prior, window;

  Feasible(const EllipseRansacParams& p, double prior_theta)
      : a0(p.alpha_min),
        a1(p.alpha_max),
        b0(p.beta_min),
        b1(p.beta_max),
        theta_bounded(std::isfinite(prior_theta) && p.theta_window < M_PI / 2),
        prior(theta_bounded ? prior_theta : 0),
        window(p.theta_window) {}

  void project(Vec5& q) const {
    // β > α is the same ellipse as (θ + π/2, α ↔ β): turn it when eq. 11 allows.
    if (q(kBeta) > q(kAlpha)) {
      const double turned = q(kTheta) + M_PI / 2;
      if (!theta_bounded || std::abs(wrapHalfPi(turned - prior)) <= window) {
        std::swap(q(kAlpha), q(kBeta));
        q(kTheta) = turned;
      }
    }
    const double a = q(kAlpha), b = q(kBeta);
    double ac = std::clamp(a, a0, a1), bc = std::clamp(b, b0, b1);
    if (bc > ac) {  // only possible when the boxes overlap: max(a0, b0) ≤ min(a1, b1)
      ac = bc = std::clamp(0.5 * (a + b), std::max(a0, b0), std::min(a1, b1));
    }
    q(kAlpha) = ac;
    q(kBeta) = bc;
    if (theta_bounded) {
      q(kTheta) = prior + std::clamp(wrapHalfPi(q(kTheta) - prior), -window, window);
    }
  }

  // Component k's box, when it has one (after project(), θ lies in prior ± window).
  bool bounds(int k, double& lo, double& hi) const {
    switch (k) {
      case kTheta:
        lo = prior - window;
        hi = prior + window;
        return theta_bounded;
      case kAlpha:
        lo = a0;
        hi = a1;
        return true;
      case kBeta:
        lo = b0;
        hi = b1;
        return true;
      default:
        return false;
    }
  }
};

// J at q with its gradient and two models of its Hessian, all halved (J = Σ rₖ²: g = Jᵀr,
// Gauss–Newton's JᵀJ and the exact JᵀJ + Σ rₖ∇²rₖ).
struct Local {
  double cost = 0;
  Vec5 g;
  Mat5 gn, full;
};

// The data of one fit: the points, the sensor and E = Σ exp(rᵢ − r_ref) (scaled by the largest
// rᵢ so it cannot overflow).
struct Problem {
  const Points2& pts;
  Eigen::Vector2d origin;
  bool correction;
  double E = 0, r_ref = 0;
};

// J at q; with `L`, also its derivatives.
double evaluate(const Problem& P, const Vec5& q, Local* L = nullptr) {
  const double st = std::sin(q(kTheta)), ct = std::cos(q(kTheta));
  const double a = q(kAlpha), b = q(kBeta);
  const double ia2 = 1 / (a * a), ib2 = 1 / (b * b);
  double cost = 0;
  if (!L) {
    for (const auto& p : P.pts) {
      const double dx = p.x() - q(kX), dy = p.y() - q(kY);
      const double u = -dx * st + dy * ct, v = -dx * ct - dy * st;
      const double s = u * u * ia2 + v * v * ib2 - 1;
      cost += s * s;
    }
  } else {
    // Every derivative is a polynomial in (u, v) with coefficients fixed by (θ, α, β), so the
    // sums over the points reduce to the moments Mab = Σ uᵃvᵇ (a + b = 2…4) and the s-weighted
    // sums Σ s, Σ su, Σ sv, Σ suv, Σ su², Σ sv². With A = 1/α², B = 1/β², D = 2(A − B):
    //   ∇s = (2A sin θ u + 2B cos θ v, −2A cos θ u + 2B sin θ v, D uv, −2A u²/α, −2B v²/β)
    // and the non-zero second derivatives (for Σ s∇²s)
    //   s_xx = 2(A sin²θ + B cos²θ), s_xy = −D sin θ cos θ, s_yy = 2(A cos²θ + B sin²θ),
    //   s_xθ = D(v sin θ + u cos θ), s_yθ = D(u sin θ − v cos θ), s_θθ = D(v² − u²),
    //   s_xα = −4A u sin θ/α, s_yα = 4A u cos θ/α, s_θα = −4A uv/α, s_αα = 6A²u²,
    //   s_xβ = −4B v cos θ/β, s_yβ = −4B v sin θ/β, s_θβ = 4B uv/β, s_ββ = 6B²v².
    double m20 = 0, m11 = 0, m02 = 0, m30 = 0, m21 = 0, m12 = 0, m03 = 0, m40 = 0, m31 = 0, m22 = 0,
           m13 = 0, m04 = 0;
    double s1 = 0, su = 0, sv = 0, suv = 0, su2 = 0, sv2 = 0;
    for (const auto& p : P.pts) {
      const double dx = p.x() - q(kX), dy = p.y() - q(kY);
      const double u = -dx * st + dy * ct, v = -dx * ct - dy * st;
      const double u2 = u * u, v2 = v * v, uv = u * v;
      const double s = u2 * ia2 + v2 * ib2 - 1;
      cost += s * s;
      m20 += u2;
      m11 += uv;
      m02 += v2;
      m30 += u2 * u;
      m21 += u2 * v;
      m12 += u * v2;
      m03 += v2 * v;
      m40 += u2 * u2;
      m31 += u2 * uv;
      m22 += u2 * v2;
      m13 += uv * v2;
      m04 += v2 * v2;
      s1 += s;
      su += s * u;
      sv += s * v;
      suv += s * uv;
      su2 += s * u2;
      sv2 += s * v2;
    }
    const double A = ia2, B = ib2, D = 2 * (A - B), ia = 1 / a, ib = 1 / b;
    const double a1 = 2 * A * st, b1 = 2 * B * ct, a2 = -2 * A * ct, b2 = 2 * B * st;
    const double ca = -2 * A * ia, cb = -2 * B * ib;
    Vec5& g = L->g;
    g << a1 * su + b1 * sv, a2 * su + b2 * sv, D * suv, ca * su2, cb * sv2;
    Mat5& H = L->gn;
    H(0, 0) = a1 * a1 * m20 + 2 * a1 * b1 * m11 + b1 * b1 * m02;
    H(0, 1) = a1 * a2 * m20 + (a1 * b2 + b1 * a2) * m11 + b1 * b2 * m02;
    H(1, 1) = a2 * a2 * m20 + 2 * a2 * b2 * m11 + b2 * b2 * m02;
    H(0, 2) = D * (a1 * m21 + b1 * m12);
    H(1, 2) = D * (a2 * m21 + b2 * m12);
    H(0, 3) = ca * (a1 * m30 + b1 * m21);
    H(1, 3) = ca * (a2 * m30 + b2 * m21);
    H(0, 4) = cb * (a1 * m12 + b1 * m03);
    H(1, 4) = cb * (a2 * m12 + b2 * m03);
    H(2, 2) = D * D * m22;
    H(2, 3) = D * ca * m31;
    H(2, 4) = D * cb * m13;
    H(3, 3) = ca * ca * m40;
    H(3, 4) = ca * cb * m22;
    H(4, 4) = cb * cb * m04;
    Mat5 S;
    S(0, 0) = 2 * (A * st * st + B * ct * ct) * s1;
    S(0, 1) = -D * st * ct * s1;
    S(1, 1) = 2 * (A * ct * ct + B * st * st) * s1;
    S(0, 2) = D * (st * sv + ct * su);
    S(1, 2) = D * (st * su - ct * sv);
    S(0, 3) = -4 * A * ia * st * su;
    S(1, 3) = 4 * A * ia * ct * su;
    S(0, 4) = -4 * B * ib * ct * sv;
    S(1, 4) = -4 * B * ib * st * sv;
    S(2, 2) = D * (sv2 - su2);
    S(2, 3) = -4 * A * ia * suv;
    S(2, 4) = 4 * B * ib * suv;
    S(3, 3) = 6 * A * A * su2;
    S(3, 4) = 0;
    S(4, 4) = 6 * B * B * sv2;
    for (int r = 0; r < 5; ++r)
      for (int c = r; c < 5; ++c) {
        H(c, r) = H(r, c);
        L->full(r, c) = L->full(c, r) = H(r, c) + S(r, c);
      }
  }
  if (P.correction) {
    // G = E·exp(r_ref − r_c): ∇G = −G n, ∇²G = G (n nᵀ − (I − n nᵀ)/r_c); the residuals' JᵀJ
    // is G/4 · n nᵀ.
    const Eigen::Vector2d w(q(kX) - P.origin.x(), q(kY) - P.origin.y());
    const double rc = w.norm();
    const double G = P.E * std::exp(P.r_ref - rc);
    cost += G;
    if (L && rc > 0) {
      const Eigen::Vector2d n = w / rc;
      const Eigen::Matrix2d nn = n * n.transpose();
      L->g.head<2>() -= 0.5 * G * n;
      L->gn.topLeftCorner<2, 2>() += 0.25 * G * nn;
      L->full.topLeftCorner<2, 2>() += 0.5 * G * (nn - (Eigen::Matrix2d::Identity() - nn) / rc);
    }
  }
  if (L) L->cost = cost;
  return cost;
}

// Solves A x = b for a symmetric 5 × 5 A by LDLᵀ; false when A is not positive definite.
bool choleskySolve(const Mat5& A, const Vec5& b, Vec5& x) {
  double L[5][5], d[5], inv[5];
  for (int j = 0; j < 5; ++j) {
    double t = A(j, j);
    for (int k = 0; k < j; ++k) t -= L[j][k] * L[j][k] * d[k];
    if (!(t > 0)) return false;
    d[j] = t;
    inv[j] = 1 / t;
    for (int i = j + 1; i < 5; ++i) {
      double e = A(i, j);
      for (int k = 0; k < j; ++k) e -= L[i][k] * L[j][k] * d[k];
      L[i][j] = e * inv[j];
    }
  }
  for (int i = 0; i < 5; ++i) {
    double t = b(i);
    for (int k = 0; k < i; ++k) t -= L[i][k] * x(k);
    x(i) = t;
  }
  for (int i = 4; i >= 0; --i) {
    double t = x(i) * inv[i];
    for (int k = i + 1; k < 5; ++k) t -= L[k][i] * x(k);
    x(i) = t;
  }
  return true;
}

Vec5 toVec(const TorsoEllipse& e) {
  Vec5 q;
  q << e.x, e.y, e.theta, e.alpha, e.beta;
  return q;
}

// Σ min(sᵢ², d_th²) over the points and the count of |sᵢ| ≤ d_th (flagged in `mask` if given).
double truncatedCost(const TorsoEllipse& e, const Points2& pts, double dth, int& inliers,
                     std::uint8_t* mask = nullptr) {
  const double st = std::sin(e.theta), ct = std::cos(e.theta);
  const double ia2 = 1 / (e.alpha * e.alpha), ib2 = 1 / (e.beta * e.beta);
  const double d2 = dth * dth;
  double W = 0;
  inliers = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double dx = pts[i].x() - e.x, dy = pts[i].y() - e.y;
    const double u = -dx * st + dy * ct, v = -dx * ct - dy * st;
    const double s = u * u * ia2 + v * v * ib2 - 1;
    const double s2 = s * s;
    const bool in = s2 <= d2;
    inliers += in;
    W += in ? s2 : d2;
    if (mask) mask[i] = in;
  }
  return W;
}

// The adaptive RANSAC count log(1 − C)/log(1 − wⁿ), capped at m.
int adaptiveIterations(double w, int n, double confidence, int m) {
  if (!(w > 0) || !(confidence < 1)) return m;
  if (!(confidence > 0)) return 1;
  const double wn = std::pow(std::min(w, 1.0), n);
  if (!(wn < 1)) return 1;
  const double k = std::ceil(std::log(1 - confidence) / std::log1p(-wn));
  return k >= m ? m : std::max(1, int(k));
}

}  // namespace

double ellipseDeviation(const TorsoEllipse& e, const Eigen::Vector2d& p) {
  const double dx = p.x() - e.x, dy = p.y() - e.y;
  const double st = std::sin(e.theta), ct = std::cos(e.theta);
  const double u = (-dx * st + dy * ct) / e.alpha, v = (-dx * ct - dy * st) / e.beta;
  return u * u + v * v - 1;
}

TorsoEllipse initialEllipse(const Points2& pts, const Eigen::Vector2d& origin, double prior_theta,
                            const EllipseRansacParams& params) {
  Eigen::Vector2d m = Eigen::Vector2d::Zero();
  for (const auto& p : pts) m += p;
  if (!pts.empty()) m /= double(pts.size());
  const Eigen::Vector2d sight = m - origin;
  const double d = sight.norm();
  TorsoEllipse e;
  const double beta = 0.5 * (params.beta_min + params.beta_max);
  if (d > 0) m += sight * (beta / d);
  e.x = m.x();
  e.y = m.y();
  e.theta = std::isfinite(prior_theta) ? wrapPi(prior_theta)
            : d > 0                    ? std::atan2(-sight.y(), -sight.x())
                                       : 0.0;
  e.alpha = 0.5 * (params.alpha_min + params.alpha_max);
  e.beta = beta;
  return e;
}

bool fitEllipseConstrained(const Points2& pts, const Eigen::Vector2d& origin, double prior_theta,
                           const EllipseRansacParams& params, TorsoEllipse start,
                           TorsoEllipse& out) {
  if (pts.size() < 3 || !validParams(params)) return false;
  const Feasible F(params, prior_theta);
  Problem P{pts, origin, params.center_correction};
  if (P.correction) {
    for (const auto& p : pts) P.r_ref = std::max(P.r_ref, (p - origin).norm());
    for (const auto& p : pts) P.E += std::exp((p - origin).norm() - P.r_ref);
  }
  Vec5 q = toVec(start);
  if (!q.allFinite()) return false;
  F.project(q);
  Local cur;
  evaluate(P, q, &cur);
  if (!std::isfinite(cur.cost)) return false;
  // Marquardt's damping λ·diag, updated by the gain ratio ρ (Nielsen's rule), kept ≥ 10⁻³ and
  // raised ×8, ×16… on failure so that a bad step recovers fast.
  double lambda = 1e-3, nu = 8;
  for (int it = 0; it < params.solver_iterations; ++it) {
    // A simple active set: components at a bound are held when the gradient or the step pushes
    // them outward; the others' step is shortened to stop at the first bound it meets.
    bool held[5] = {false, false, false, false, false};
    double lo[5], hi[5];
    bool bounded[5];
    for (int k = 0; k < 5; ++k) {
      bounded[k] = F.bounds(k, lo[k], hi[k]);
      if (bounded[k]) held[k] = (q(k) <= lo[k] && cur.g(k) > 0) || (q(k) >= hi[k] && cur.g(k) < 0);
    }
    Vec5 step;
    const Mat5* model = nullptr;
    for (int pass = 0; pass < 3; ++pass) {
      // The damped exact Hessian when positive definite, else the damped JᵀJ.
      model = nullptr;
      for (const Mat5* M : {&cur.full, &cur.gn}) {
        Mat5 A = *M;
        Vec5 rhs = -cur.g;
        const double floor = 1e-12 * (1 + M->diagonal().cwiseAbs().maxCoeff());
        for (int k = 0; k < 5; ++k) {
          A(k, k) += lambda * std::max(std::abs((*M)(k, k)), floor);
          if (held[k]) {
            A.row(k).setZero();
            A.col(k).setZero();
            A(k, k) = 1;
            rhs(k) = 0;
          }
        }
        if (choleskySolve(A, rhs, step)) {
          model = M;
          break;
        }
      }
      if (!model) break;
      bool more = false;
      for (int k = 0; k < 5; ++k) {
        if (!bounded[k] || held[k]) continue;
        if ((q(k) <= lo[k] && step(k) < 0) || (q(k) >= hi[k] && step(k) > 0)) more = held[k] = true;
      }
      if (!more) break;
    }
    if (!model) break;  // JᵀJ + λ·diag is positive definite unless λ is 0 or NaN
    double tau = 1;
    for (int k = 0; k < 5; ++k) {
      if (!bounded[k] || held[k]) continue;
      if (q(k) + step(k) > hi[k]) tau = std::min(tau, (hi[k] - q(k)) / step(k));
      if (q(k) + step(k) < lo[k]) tau = std::min(tau, (lo[k] - q(k)) / step(k));
    }
    // Converged when the step promises no decrease worth taking (10⁻⁷ of J: µm and µrad here).
    const double promised = -(2 * cur.g.dot(step) + step.dot(*model * step));
    if (!(promised > 1e-7 * cur.cost) && !(-cur.g.dot(step) > 1e-7 * cur.cost)) break;
    step *= std::max(tau, 0.0);
    Vec5 qn = q + step;
    F.project(qn);
    if (!qn.allFinite()) break;
    const Vec5 d = qn - q;
    const double predicted = -(2 * cur.g.dot(d) + d.dot(*model * d));
    const double cost = predicted > 0 ? evaluate(P, qn) : INFINITY;
    const double rho = (cur.cost - cost) / predicted;
    if (predicted > 0 && rho > 0) {
      const bool flat = cur.cost - cost <= 1e-12 * cur.cost;
      q = qn;
      evaluate(P, q, &cur);
      const double t = 2 * rho - 1;
      lambda = std::max(1e-3, lambda * std::max(1.0 / 3, 1 - t * t * t));
      nu = 8;
      if (flat) break;
    } else {  // worse, or the projection spoilt the step: a shorter one
      lambda *= nu;
      nu *= 2;
      if (!(lambda < 1e12)) break;
    }
  }
  TorsoEllipse e;
  e.x = q(kX);
  e.y = q(kY);
  e.theta = wrapPi(q(kTheta));
  e.alpha = q(kAlpha);
  e.beta = q(kBeta);
  if (!(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.theta))) return false;
  out = e;
  return true;
}

EllipseRansacResult fitEllipseRansac(const Points2& pts, const Eigen::Vector2d& origin,
                                     double prior_theta, const EllipseRansacParams& params,
                                     std::mt19937& rng) {
  EllipseRansacResult res;
  const int M = int(pts.size());
  if (M < 3 || !validParams(params)) return res;
  const int n = std::clamp(params.sample_size, 3, M);
  const int m = std::max(1, params.max_iterations);
  // With every point in each sample all samples are the same: one fit is the answer.
  int N = n == M ? 1 : m;
  std::vector<int> idx(M);
  std::iota(idx.begin(), idx.end(), 0);
  Points2 sample(n);
  double best_W = std::numeric_limits<double>::infinity(), best_w = 0;
  int k = 0;
  for (; k < N; ++k) {
    for (int i = 0; i < n; ++i) {  // partial Fisher–Yates: n distinct points
      std::uniform_int_distribution<int> pick(i, M - 1);
      std::swap(idx[i], idx[pick(rng)]);
      sample[i] = pts[idx[i]];
    }
    TorsoEllipse cand;
    if (!fitEllipseConstrained(sample, origin, prior_theta, params,
                               initialEllipse(sample, origin, prior_theta, params), cand))
      continue;
    int inliers = 0;
    const double W = truncatedCost(cand, pts, params.inlier_threshold, inliers);
    if (W < best_W) {
      best_W = W;
      res.ellipse = cand;
      res.inliers = inliers;
    }
    const double w = double(inliers) / M;
    if (w > best_w) {
      best_w = w;
      N = std::min(N, adaptiveIterations(w, n, params.confidence, m));
    }
  }
  res.iterations = k;
  if (!(best_W < std::numeric_limits<double>::infinity())) return res;
  res.ok = true;
  res.cost = best_W;
  res.inlier.resize(M);
  truncatedCost(res.ellipse, pts, params.inlier_threshold, res.inliers, res.inlier.data());
  return res;
}

}  // namespace pedtrack::fit
