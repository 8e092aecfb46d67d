#pragma once
// One person's torso estimate inside ShapeTracker. The tracker does what every torso tracker
// shares — candidates from the classified clusters, Hungarian association, M-of-N confirmation,
// deletion, the tracks.csv rows — and asks each track's estimator for the rest: the IMM over
// observation models (imm_shape, kf_bb, kf_circle; shape_imm_estimator.h) or the moving-horizon
// estimator of P0 (mhe_mlesac; mhe_estimator.h).
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <random>

#include "pedtrack/frame.h"
#include "pedtrack/track/shape_observation.h"

namespace pedtrack::track {

class TorsoEstimator {
 public:
  virtual ~TorsoEstimator() = default;
  /// Moves the estimate dt seconds on; called every frame before association.
  virtual void predict(double dt) = 0;
  /// Where association looks for the person this frame (after predict).
  virtual Eigen::Vector2d position() const = 0;
  /// The person's cluster this frame: its torso-band points (fixed frame) and the sensor.
  virtual void update(const ShapeCloud& cloud, std::mt19937& rng) = 0;
  /// No cluster this frame (the track coasts).
  virtual void miss() {}
  /// The estimate as a tracks.csv row: position, velocity, facing direction, semi-axes (torso
  /// convention), position covariance, model probabilities. The tracker fills id and status.
  virtual Track row() = 0;
};

/// A new person's estimator from their first cluster; `position` is its centre of gravity moved
/// back behind the surface.
using TorsoEstimatorFactory = std::function<std::unique_ptr<TorsoEstimator>(
    const ShapeCloud& cloud, const Eigen::Vector2d& position, std::mt19937& rng)>;

}  // namespace pedtrack::track
