#include "mhe_mlesac/mhe_ellipse.h"

#include <algorithm>
#include <cmath>

namespace pedtrack::track::mhe {

Deviation::Deviation(const State& x)
    : x_(x(0)),
      y_(x(1)),
      c_(std::cos(x(2))),
      s_(std::sin(x(2))),
      a_(1 / (x(6) * x(6))),
      b_(1 / (x(7) * x(7))) {}

double Deviation::operator()(const Point& p) const {
  const double dx = p.x() - x_, dy = p.y() - y_;
  const double u = dx * c_ + dy * s_, w = -dx * s_ + dy * c_;
  return a_ * u * u + b_ * w * w - 1;
}

double deviation(const State& x, const Point& p) {
  return Deviation(x)(p);
}

// Variables q = (x, y, θ, α, β). With a = α⁻², b = β⁻²: s = a u² + b w² − 1, where
// u_x = −c, u_y = −s, u_θ = w and w_x = s, w_y = −c, w_θ = −u; the only non-zero second
// derivatives of u and w are u_xθ = s, u_yθ = −c, u_θθ = −u, w_xθ = c, w_yθ = s, w_θθ = −w.
double deviation(const State& x, const Point& p, Eigen::Matrix<double, 5, 1>& grad,
                 Eigen::Matrix<double, 5, 5>* hess) {
  const double dx = p.x() - x(0), dy = p.y() - x(1);
  const double c = std::cos(x(2)), sn = std::sin(x(2));
  const double u = dx * c + dy * sn, w = -dx * sn + dy * c;
  const double al = x(6), be = x(7);
  const double a = 1 / (al * al), b = 1 / (be * be);
  const Eigen::Vector3d du(-c, -sn, w), dw(sn, -c, -u);
  grad.head<3>() = 2 * a * u * du + 2 * b * w * dw;
  grad(3) = -2 * u * u / (al * al * al);
  grad(4) = -2 * w * w / (be * be * be);
  if (hess) {
    Eigen::Matrix3d uu = du * du.transpose(), ww = dw * dw.transpose();
    Eigen::Matrix3d d2u = Eigen::Matrix3d::Zero(), d2w = Eigen::Matrix3d::Zero();
    d2u(0, 2) = d2u(2, 0) = sn;
    d2u(1, 2) = d2u(2, 1) = -c;
    d2u(2, 2) = -u;
    d2w(0, 2) = d2w(2, 0) = c;
    d2w(1, 2) = d2w(2, 1) = sn;
    d2w(2, 2) = -w;
    Eigen::Matrix<double, 5, 5>& H = *hess;
    H.setZero();
    H.topLeftCorner<3, 3>() = 2 * a * (uu + u * d2u) + 2 * b * (ww + w * d2w);
    const double al3 = al * al * al, be3 = be * be * be;
    H.block<3, 1>(0, 3) = -4 * u * du / al3;
    H.block<1, 3>(3, 0) = H.block<3, 1>(0, 3).transpose();
    H.block<3, 1>(0, 4) = -4 * w * dw / be3;
    H.block<1, 3>(4, 0) = H.block<3, 1>(0, 4).transpose();
    H(3, 3) = 6 * u * u / (al3 * al);
    H(4, 4) = 6 * w * w / (be3 * be);
  }
  return a * u * u + b * w * w - 1;
}

Eigen::Matrix<double, 5, 1> systemNoise(const State& prev, const State& next, double dt) {
  return (next.tail<5>() - prev.tail<5>()) / dt;
}

namespace {

double motionCost(const MheProblem& pb, const MheParams& params, const std::vector<State>& xs) {
  double J = 0;
  for (int k = 1; k < pb.size(); ++k) {
    const auto n = systemNoise(xs[k - 1], xs[k], (*pb.frames)[k].dt);
    J += (n.array().square() / params.q.array()).sum();
  }
  return J / params.horizon;
}

double arrivalCost(const MheProblem& pb, const std::vector<State>& xs) {
  const State d = xs[0] - pb.arrival_mean;
  return d.dot(pb.arrival_info * d);
}

}  // namespace

MheCost mheCost(const MheProblem& pb, const MheParams& params, const std::vector<State>& xs) {
  MheCost c;
  c.motion = motionCost(pb, params, xs);
  c.arrival = arrivalCost(pb, xs);
  for (int k = 0; k < pb.size(); ++k)
    for (int i : pb.sample[k]) c.data += std::pow(deviation(xs[k], (*pb.frames)[k].points[i]), 2);
  c.data *= pb.data_weight;
  return c;
}

Selected selectionCost(const MheProblem& pb, const MheParams& params, Selection selection,
                       const std::vector<State>& xs) {
  Selected out;
  double sum = 0;
  const double d2 = params.d_th * params.d_th;
  for (int k = 0; k < pb.size(); ++k) {
    const Deviation s(xs[k]);  // every horizon point of every candidate: a hot path
    for (const Point& p : (*pb.frames)[k].points) {
      const double s2 = std::pow(s(p), 2);
      ++out.points;
      if (s2 < d2) {
        ++out.inliers;
        sum += s2;
      } else if (selection == Selection::Truncated) {
        sum += d2;
      }
    }
  }
  const int n = selection == Selection::Truncated ? out.points : out.inliers;
  // No inlier at all: the candidate explains nothing; it loses to any that explains something.
  const double data = n > 0 ? sum / n / params.r : std::numeric_limits<double>::infinity();
  out.cost = motionCost(pb, params, xs) + arrivalCost(pb, xs) + data;
  return out;
}

double meanSampleRange(const MheProblem& pb, int k) {
  const HorizonFrame& f = (*pb.frames)[k];
  if (pb.sample[k].empty()) return 0;
  double sum = 0;
  for (int i : pb.sample[k]) sum += (f.points[i] - f.origin).norm();
  return sum / double(pb.sample[k].size());
}

double constraintViolation(const MheProblem& pb, const MheParams& params,
                           const std::vector<State>& xs) {
  double v = 0;
  auto over = [&v](double amount) { v = std::max(v, amount); };
  for (int k = 0; k < pb.size(); ++k) {
    const State& x = xs[k];
    over(x(7) - x(6));                                             // (6)
    over(params.alpha_min - x(6)), over(x(6) - params.alpha_max);  // (7)
    over(params.beta_min - x(7)), over(x(7) - params.beta_max);    // (8)
    over(std::abs(x(2) - pb.prior[k](2)) - params.theta_th);       // (9)
    if (!pb.sample[k].empty())                                     // (10)
      over(meanSampleRange(pb, k) - (x.head<2>() - (*pb.frames)[k].origin).norm());
    if (k > 0) {
      const double dt = (*pb.frames)[k].dt;
      const Eigen::Vector3d e = x.head<3>() - xs[k - 1].head<3>() - dt * xs[k - 1].segment<3>(3);
      over(e.cwiseAbs().maxCoeff());
    }
  }
  return v;
}

}  // namespace pedtrack::track::mhe
