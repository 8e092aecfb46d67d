#pragma once
// A walker seen by a LiDAR at the origin over one MHE horizon: the visible half of the torso
// ellipse (P0's convention: α along θ) sampled every frame, with optional range noise and
// outliers (arm points off the ellipse). Shared by test_mhe and test_mhe_mlesac.
#include <cmath>
#include <random>
#include <vector>

#include "mhe_mlesac/mhe_ellipse.h"

namespace pedtrack::test {

class MheWalk {
 public:
  using State = track::mhe::State;
  MheWalk(int frames, double dt, State first, double noise = 0, double outliers = 0,
          unsigned seed = 1)
      : dt_(dt) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0, 1);
    std::uniform_real_distribution<double> u(0, 1);
    State x = first;
    for (int k = 0; k < frames; ++k) {
      if (k > 0) x.head<3>() += dt * x.segment<3>(3);
      truth_.push_back(x);
      track::mhe::HorizonFrame f;
      f.dt = dt;
      const double c = std::cos(x(2)), s = std::sin(x(2));
      for (int i = 0; i < 72; ++i) {
        const double a = 2 * M_PI * i / 72;
        // Point and outward normal of the ellipse at parameter a.
        const Eigen::Vector2d local(x(6) * std::cos(a), x(7) * std::sin(a));
        const Eigen::Vector2d nl(std::cos(a) / x(6), std::sin(a) / x(7));
        Eigen::Vector2d p(x(0) + c * local.x() - s * local.y(),
                          x(1) + s * local.x() + c * local.y());
        const Eigen::Vector2d normal(c * nl.x() - s * nl.y(), s * nl.x() + c * nl.y());
        if (normal.dot(f.origin - p) <= 0) continue;  // the far side is hidden
        p += noise * n(rng) * p.normalized();
        if (u(rng) < outliers) p += (0.15 + 0.15 * u(rng)) * normal.normalized();  // an arm
        f.points.push_back(p);
      }
      frames_.push_back(std::move(f));
    }
  }

  State truth(int k) const { return truth_[k]; }
  const std::vector<State>& truthWindow() const { return truth_; }
  std::vector<track::mhe::HorizonFrame>& frames() { return frames_; }

  /// Every point sampled; the a priori window and the arrival mean are the truth, moved by
  /// 5 cm, with zero velocity and mid-range semi-axes when `perturb`.
  track::mhe::MheProblem problem(const track::mhe::MheParams& params, bool perturb) {
    track::mhe::MheProblem pb;
    pb.frames = &frames_;
    std::size_t total = 0;
    for (const auto& f : frames_) {
      std::vector<int> all(f.points.size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
      total += all.size();
      pb.sample.push_back(std::move(all));
    }
    for (State x : truth_) {
      if (perturb) {
        x(0) += 0.05;
        x(1) -= 0.03;
        x(3) = x(4) = x(5) = 0;
        x(6) = 0.15;
        x(7) = 0.075;
      }
      pb.prior.push_back(x);
    }
    pb.arrival_mean = pb.prior[0];
    Eigen::Matrix<double, 8, 1> sd;
    sd << 0.2, 0.2, 0.3, 1, 1, 1, 0.05, 0.05;
    pb.arrival_info = sd.cwiseInverse().cwiseAbs2().asDiagonal();
    pb.data_weight = 1 / (params.r * double(total));
    return pb;
  }

 private:
  double dt_;
  std::vector<State> truth_;
  std::vector<track::mhe::HorizonFrame> frames_;
};

}  // namespace pedtrack::test
