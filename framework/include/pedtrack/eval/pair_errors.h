#pragma once
// State errors over the CLEAR MOT matches: position, heading, torso shape, speed.
//  - position: RMSE, MAE (= MOTP) and per-axis RMSE, in the compared frame; MAE along the
//    person's own axes (P3 Table 1), when the truth row has yaw: sagittal = the error's component
//    along the truth heading (cos yaw, sin yaw), frontal = the component across it, both from the
//    rows' fixed-frame x, y (the frame yaw is given in, also with --frame sensor);
//  - heading: |wrap(yaw − yaw_true)| in [0, π], when both rows have yaw (velocity is not used);
//    the axis error is that difference modulo π, in [−π/2, π/2] (front/back ignored: P0 Table I's
//    "Abs. angular error" of ellipse / bounding-box orientations);
//  - shape: an ellipse (α, β, yaw) is the same as (β, α, yaw + 90°), so the larger semi-axis is
//    compared with the larger one and the smaller with the smaller, when both rows have α, β;
//  - speed: | |v| − |v_true| | and the velocity-vector RMSE, when both rows have vx, vy.
#include <cmath>
#include <functional>
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
  double heading_sq_sum = 0;   ///< rad², of the heading pairs
  double axis_sq_sum = 0;      ///< rad², of the heading pairs' errors modulo π
  std::size_t body_pairs = 0;  ///< pairs whose truth row has yaw
  double sagittal_sum = 0;     ///< m, |error along the truth heading| of the body pairs
  double frontal_sum = 0;      ///< m, |error across the truth heading| of the body pairs

  double rmse() const;
  double mae() const;
  double rmseX() const;
  double rmseY() const;
  double headingMae() const;  ///< rad
  double majorMae() const;    ///< m, larger semi-axis
  double minorMae() const;    ///< m, smaller semi-axis
  double speedMae() const;    ///< m/s
  double velocityRmse() const;
  double headingRmse() const;  ///< rad, √ of the mean squared wrapped heading error
  /// rad, √ of the mean squared axis error d − π·round(d / π), d = wrap(yaw − yaw_true); NaN
  /// without heading pairs.
  double axisRmse() const;
  double sagittalMae() const;  ///< m, mean |error along the truth heading|; NaN without body pairs
  double frontalMae() const;   ///< m, mean |error across the truth heading|; NaN without body pairs
  PairErrors& operator+=(const PairErrors& o);
};

PairErrors pairErrors(const std::vector<MatchedPair>& pairs);

/// An angle wrapped to (−π, π].
double wrapAngle(double a);

/// The matches of one distance band from the sensor, measured at the estimate (its row's
/// sensor_x, sensor_y): [from, to) m.
struct RangeBand {
  double from = 0, to = INFINITY;
  PairErrors errors;  ///< position, heading, shape, speed errors of the band's pairs
  /// Semi-axes of the band's estimate rows that have alpha, beta (m).
  std::size_t shape_rows = 0;
  double alpha_sum = 0, alpha_min = INFINITY, alpha_max = -INFINITY;
  double beta_sum = 0, beta_min = INFINITY, beta_max = -INFINITY;
  /// Model probabilities of the estimate rows that have them: per model index, the sum and the
  /// number of rows with that model.
  std::vector<double> prob_sum;
  std::vector<std::size_t> prob_rows;

  double alphaMean() const;                  ///< m, NaN without shape rows
  double betaMean() const;                   ///< m
  double probMean(std::size_t model) const;  ///< NaN when no row has that model
};

struct RangeBandReport {
  std::vector<RangeBand> bands;  ///< one per edge: [edge i, edge i+1), the last to ∞
  std::size_t unbanded = 0;      ///< pairs whose estimate has no range or is nearer than edge 0
  std::size_t models = 0;        ///< the most model probabilities of any banded row
};

/// An estimate row's model probabilities (tracks.csv `model_probs`), null when it has none.
using ModelProbsOf = std::function<const std::vector<double>*(const ObjectRow&)>;

/// Sorts `pairs` into the bands of increasing `edges` (m) by the distance of the estimate row's
/// (sensor_x, sensor_y) from the sensor. `probs` may be empty (no model probabilities).
RangeBandReport rangeBands(const std::vector<MatchedPair>& pairs, const std::vector<double>& edges,
                           const ModelProbsOf& probs = {});

}  // namespace pedtrack::eval
