// Direct least-squares ellipse fit: Fitzgibbon, Pilu & Fisher (1999) in the numerically stable
// form of Halíř & Flusser (1998). Written here rather than calling cv::fitEllipseDirect (which
// implements the same method; tests/test_fit.cpp checks the two agree) because OpenCV's version
// allocates several cv::Mat and solves a general eigenproblem per call: on the leg_tracker scans
// it was 70 % of scan_segments' time (~100k instructions a segment), this fixed-size version
// with a closed-form 3 × 3 eigenproblem takes a few thousand.
#include "pedtrack/fit/ellipse.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

namespace pedtrack::fit {
namespace {

// Real roots of det(R − λI) = −λ³ + tr·λ² − m·λ + det (trigonometric form for three real roots,
// Cardano's for one).
std::vector<double> realEigenvalues(const Eigen::Matrix3d& R) {
  const double tr = R.trace();
  const double m = R(0, 0) * R(1, 1) - R(0, 1) * R(1, 0) + R(0, 0) * R(2, 2) - R(0, 2) * R(2, 0) +
                   R(1, 1) * R(2, 2) - R(1, 2) * R(2, 1);
  const double det = R.determinant();
  // λ³ + a λ² + b λ + c = 0 with a = −tr, b = m, c = −det; depressed with λ = t − a/3.
  const double a = -tr, b = m, c = -det;
  const double p = b - a * a / 3, q = 2 * a * a * a / 27 - a * b / 3 + c;
  const double shift = -a / 3;
  const double disc = q * q / 4 + p * p * p / 27;
  if (disc > 0) {
    const double u = std::cbrt(-q / 2 + std::sqrt(disc)), v = std::cbrt(-q / 2 - std::sqrt(disc));
    return {u + v + shift};
  }
  if (p == 0) return {shift};
  const double r = 2 * std::sqrt(-p / 3);
  const double phi = std::acos(std::clamp(3 * q / (p * r), -1.0, 1.0)) / 3;
  return {r * std::cos(phi) + shift, r * std::cos(phi - 2 * M_PI / 3) + shift,
          r * std::cos(phi - 4 * M_PI / 3) + shift};
}

}  // namespace

bool fitEllipseDirect(const Points2& pts, Ellipse& out) {
  const std::size_t n = pts.size();
  if (n < 5) return false;
  // Centre and scale the points so the scatter matrices are well conditioned.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(n);
  double s2 = 0;
  for (const auto& p : pts) s2 += (p - mean).squaredNorm();
  const double scale = std::sqrt(s2 / double(n));
  if (!(scale > 0)) return false;
  const double inv = 1.0 / scale;
  // Scatter of D1 = [x², xy, y²] and D2 = [x, y, 1].
  Eigen::Matrix3d S1 = Eigen::Matrix3d::Zero(), S2 = Eigen::Matrix3d::Zero(),
                  S3 = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) {
    const double x = (p.x() - mean.x()) * inv, y = (p.y() - mean.y()) * inv;
    const Eigen::Vector3d d1(x * x, x * y, y * y), d2(x, y, 1);
    S1 += d1 * d1.transpose();
    S2 += d1 * d2.transpose();
    S3 += d2 * d2.transpose();
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(S3);
  if (!lu.isInvertible()) return false;
  const Eigen::Matrix3d T = -lu.solve(S2.transpose());
  const Eigen::Matrix3d M = S1 + S2 * T;
  Eigen::Matrix3d R;  // C1⁻¹ · M with C1 = [[0, 0, 2], [0, -1, 0], [2, 0, 0]]
  R.row(0) = 0.5 * M.row(2);
  R.row(1) = -M.row(1);
  R.row(2) = 0.5 * M.row(0);
  // R has real eigenvalues, one of them positive (Fitzgibbon et al.); its eigenvector is the
  // one meeting the ellipse constraint 4AC − B² > 0. Roots of the characteristic cubic in closed
  // form, eigenvectors as the cross product of two rows of R − λI: no iterative eigensolver.
  Eigen::Vector3d a1 = Eigen::Vector3d::Zero();
  double best_cond = 0;
  for (double lambda : realEigenvalues(R)) {
    const Eigen::Matrix3d K = R - lambda * Eigen::Matrix3d::Identity();
    Eigen::Vector3d v = K.row(0).cross(K.row(1));
    for (const Eigen::Vector3d& w :
         {Eigen::Vector3d(K.row(0).cross(K.row(2))), Eigen::Vector3d(K.row(1).cross(K.row(2)))})
      if (w.squaredNorm() > v.squaredNorm()) v = w;
    if (!(v.squaredNorm() > 0)) continue;
    v.normalize();
    const double cond = 4 * v(0) * v(2) - v(1) * v(1);
    if (cond > best_cond) {
      best_cond = cond;
      a1 = v;
    }
  }
  if (!(best_cond > 0)) return false;
  // An eigenvector's sign is arbitrary: take A + C > 0, so the quadratic form Q below is
  // positive definite and its smaller eigenvalue belongs to the longer axis.
  if (a1(0) + a1(2) < 0) a1 = -a1;
  const Eigen::Vector3d a2 = T * a1;
  const double A = a1(0), B = a1(1), C = a1(2), D = a2(0), E = a2(1), F = a2(2);
  // Centre, then the quadratic form at the centre: (p − c)ᵀ Q (p − c) = −F_c.
  Eigen::Matrix2d Q;
  Q << A, B / 2, B / 2, C;
  const Eigen::Vector2d c = -0.5 * Q.inverse() * Eigen::Vector2d(D, E);
  const double Fc =
      A * c.x() * c.x() + B * c.x() * c.y() + C * c.y() * c.y() + D * c.x() + E * c.y() + F;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> q(Q);
  const double l0 = q.eigenvalues()(0), l1 = q.eigenvalues()(1);
  if (!(-Fc / l0 > 0 && -Fc / l1 > 0)) return false;
  // The smaller eigenvalue belongs to the longer axis.
  const double a = std::sqrt(-Fc / l0), b = std::sqrt(-Fc / l1);
  const Eigen::Vector2d major = q.eigenvectors().col(0);
  double ang = std::atan2(major.y(), major.x());
  ang = std::remainder(ang, M_PI);
  if (ang <= -M_PI / 2) ang += M_PI;
  out = {mean.x() + scale * c.x(), mean.y() + scale * c.y(), scale * std::max(a, b),
         scale * std::min(a, b), ang};
  if (b > a) {  // only by rounding, for a circle (equal eigenvalues): keep a ≥ b
    out.angle = std::remainder(ang + M_PI / 2, M_PI);
    if (out.angle <= -M_PI / 2) out.angle += M_PI;
  }
  return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.a) &&
         std::isfinite(out.b);
}

double ellipseResidual(const Points2& pts, const Ellipse& e) {
  if (pts.empty() || !(e.a > 0 && e.b > 0)) return 0;
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  double sum = 0;
  for (const auto& p : pts) {
    const double dx = p.x() - e.x, dy = p.y() - e.y;
    const double u = c * dx + s * dy, v = -s * dx + c * dy;
    const double k = std::sqrt(u * u / (e.a * e.a) + v * v / (e.b * e.b));
    const double d = k > 0 ? std::abs(1 - 1 / k) * std::sqrt(dx * dx + dy * dy) : e.b;
    sum += d * d;
  }
  return std::sqrt(sum / double(pts.size()));
}

}  // namespace pedtrack::fit
