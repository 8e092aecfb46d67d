#pragma once
// State errors over the CLEAR MOT matches: position, heading, torso shape, speed.
//  - position: RMSE, MAE (= MOTP) and per-axis RMSE, in the compared frame;
//  - heading: |wrap(yaw − yaw_true)| in [0, π], when both rows have yaw (velocity is not used);
//  - shape: an ellipse (α, β, yaw) is the same as (β, α, yaw + 90°), so the larger semi-axis is
//    compared with the larger one and the smaller with the smaller, when both rows have α, β;
//  - speed: | |v| − |v_true| | and the velocity-vector RMSE, when both rows have vx, vy.
#include <vector>

#include "pedtrack/eval/clear_mot.h"

namespace pedtrack::eval {

struct PairErrors {
  std::size_t pairs = 0;
  double sq_sum = 0, abs_sum = 0, sq_x = 0, sq_y = 0;
  std::size_t heading_pairs = 0;
  double heading_sum = 0;  ///< rad
  std::size_t shape_pairs = 0;
  double major_sum = 0, minor_sum = 0;
  std::size_t speed_pairs = 0;
  double speed_sum = 0, velocity_sq_sum = 0;

  double rmse() const;
  double mae() const;
  double rmseX() const;
  double rmseY() const;
  double headingMae() const;  ///< rad
  double majorMae() const;    ///< m, larger semi-axis
  double minorMae() const;    ///< m, smaller semi-axis
  double speedMae() const;    ///< m/s
  double velocityRmse() const;
  PairErrors& operator+=(const PairErrors& o);
};

PairErrors pairErrors(const std::vector<MatchedPair>& pairs);

/// An angle wrapped to (−π, π].
double wrapAngle(double a);

}  // namespace pedtrack::eval
