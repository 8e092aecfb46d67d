#pragma once
// The IRLS ground-plane tracker of P2 §3.2 (eq. 1–4): each frame, the lowest point of every
// 10 cm × 10 cm cell within 5 m, plus a 5 × 7 mesh of seed points on the default plane, are fitted
// by iteratively re-weighted least squares, the weight of a point a logistic function of its
// distance to the previous estimate (the previous frame's plane at the first iteration).
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <vector>

#include "pedtrack/frame.h"

namespace pedtrack::seg {

struct IrlsParams {
  double max_range = 5.0;  ///< m, horizontal distance from the sensor of the fitted points
  double bin = 0.10;       ///< m, cell side; the lowest point of each cell is fitted
  double A = 0.9, B = 15.0, C = 0.1, D = 0.02;  ///< W(x) = 1/(1 + A·e^{B(x−C)}) + D, x in m
  int seed_rows = 5, seed_cols = 7;             ///< seed mesh on the default plane
  double seed_extent = 5.0;   ///< m, the mesh spans ±seed_extent around the sensor
  double default_height = 0;  ///< m, robot frame z of the default (level) plane
  /// Take the default plane's height from the first frame (the lowest well-populated level of
  /// the cells' lowest points) instead of default_height.
  bool auto_height = true;
  int iterations = 10;      ///< IRLS iterations per frame at most
  double tolerance = 1e-3;  ///< stop when the plane moves less (normal and offset), m
  /// rad: estimates tilted more from the default plane are refused (about 0.35 rad, the key's
  /// 20.0535°).
  double max_tilt = 20.0535 * (M_PI / 180);
  /// > 0: after IRLS, refit by plain least squares to the data within this distance of the
  /// IRLS plane (m). Removes the pull of the weight floor D on off-plane points, which tilts
  /// P2's estimate toward obstacles; 0: P2 as published.
  double refine_band = 0;
};

/// P2 eq. 4: W(x) = 1 / (1 + A·e^{B(x − C)}) + D for a point at distance x (m) from the plane.
double irlsWeight(double distance, const IrlsParams& p);

/// One IRLS iteration: weights W(|distance to `prior`|), then the weighted plane fit (P2 eq. 3
/// with a unit normal). `weights`, when given, receives the weights used.
GroundPlane irlsIteration(const std::vector<Eigen::Vector3d>& pts, const GroundPlane& prior,
                          const IrlsParams& p, std::vector<double>* weights = nullptr);

/// A level plane at robot-frame height z.
GroundPlane levelPlane(double z);

class IrlsGround {
 public:
  explicit IrlsGround(const IrlsParams& p) : p_(p) {}

  /// Estimates this frame's plane from the points (robot frame; with `labels`, only points still
  /// Kept) seen from a sensor at (sx, sy), and keeps it as the next frame's prior.
  GroundPlane update(const float* xs, const float* ys, const float* zs, std::size_t n,
                     const std::vector<PointLabel>* labels, double sx, double sy);

  /// The lowest point of every cell of the last update (the fitted data without the seeds).
  const std::vector<Eigen::Vector3d>& binnedPoints() const { return binned_; }
  const GroundPlane& defaultPlane() const { return default_; }
  /// Frames whose estimate was refused (tilted beyond max_tilt or degenerate); the prior stayed.
  std::size_t refused() const { return refused_; }

 private:
  void binLowest(const float* xs, const float* ys, const float* zs, std::size_t n,
                 const std::vector<PointLabel>* labels, double sx, double sy);
  double findDefaultHeight() const;

  IrlsParams p_;
  GroundPlane default_, prior_;
  bool started_ = false;
  std::size_t refused_ = 0;
  std::vector<float> cell_z_;  // lowest z per cell, +inf when empty (reused)
  std::vector<int> cell_i_;    // point index of that lowest z
  std::vector<Eigen::Vector3d> binned_, data_;
};

}  // namespace pedtrack::seg
