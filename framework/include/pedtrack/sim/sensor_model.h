#pragma once
// Sensor models of the simulator: which rays a scan fires (directions in the sensor frame) and
// how a cast range image becomes the MRPT observation the real device produces.
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pedtrack/sim/reflectivity.h"

namespace pedtrack::sim {

struct SensorSpec {
  std::string model;                    ///< utm30lx | urg04lx | vlp16 | custom2d
  bool is3d = false;                    ///< vlp16
  double fov = 0;                       ///< rad (2D)
  double resolution = 0;                ///< rad between beams (2D) or columns (VLP-16)
  double max_range = 0, min_range = 0;  ///< m
  double rate = 0;                      ///< Hz
  double range_noise = 0;               ///< m, 1σ
  double dropout = 0;                   ///< probability that a return is lost
  bool dark_dropout = false;            ///< dark surfaces return less far (ReturnPhysics)
  double mixed_pixels = 0;              ///< probability of a mixed return at a depth edge
  std::string label;                    ///< MRPT sensorLabel
  bool sweep_motion = false;            ///< pose people when the beam passes, not at the stamp
  mrpt::poses::CPose3D mount;           ///< sensor on the robot
};

/// Seconds after the scan's stamp at which the beam points at sensor-frame azimuth `azimuth`
/// (rad, counter-clockwise): a VLP-16 turns clockwise from its forward axis once per scan; a 2D
/// scanner sweeps counter-clockwise from -fov/2 and its mirror turns once per scan period.
double sweepTime(const SensorSpec& spec, double azimuth);

/// Datasheet defaults of a model (fov, resolution, ranges, rate, noise, label); throws
/// ConfigError for an unknown model name.
SensorSpec sensorDefaults(const std::string& model);

/// What one scan saw: per ray (ring-major) the range along the ray and who was hit.
struct RangeImage {
  int rings = 0, cols = 0;
  std::vector<double> range;  ///< m, +inf for no return
  std::vector<int> owner;     ///< who each ray hit (geometry.h: ground, person or object)
  void reset(int r, int c);
};

/// Ray directions of one scan in the sensor frame, and the mapping from azimuth to columns used
/// to cull primitives.
class RayTable {
 public:
  explicit RayTable(const SensorSpec& spec);
  int rings() const { return rings_; }
  int cols() const { return cols_; }
  const Eigen::Vector3d& dir(int ring, int col) const { return dir_[ring * cols_ + col]; }
  double ringElevation(int ring) const { return elev_[ring]; }
  /// Columns whose azimuth lies within `half_width` of `azimuth` (sensor frame, rad), as up to
  /// two inclusive ranges (a wrap around 360° splits it). Returns the number of ranges.
  int columnRanges(double azimuth, double half_width, int out[4]) const;

 private:
  int rings_ = 0, cols_ = 0;
  bool full_circle_ = false;
  double az0_ = 0, daz_ = 0;  ///< column c nominally at az0_ + c·daz_ (rad)
  std::vector<Eigen::Vector3d> dir_;
  std::vector<double> elev_;
};

/// What one made observation contains besides itself.
struct ReturnTruth {
  bool record_owners = true;    ///< fill `owners` (per-point truth)
  std::vector<int> per_person;  ///< returns produced on each person, indexed by person id
  /// The owner of every return, in the order Frame::cloud() lists the observation's points (2D:
  /// valid beams in beam order; VLP-16: packet, block, firing, laser, as the decoder reads them).
  std::vector<std::int32_t> owners;
};

/// Turns a cast range image into the device's MRPT observation, adding range noise, dropout and
/// the device's range quantisation, and records who each return it produced belongs to.
class ObservationMaker {
 public:
  /// `seed` seeds the intensities' own streams (reflectivity.h).
  ObservationMaker(const SensorSpec& spec, unsigned long seed);
  /// `truth.per_person` must be sized to the largest person id + 1; `owners` is filled.
  mrpt::obs::CObservation::Ptr make(const RangeImage& img, double t, std::mt19937_64& rng,
                                    ReturnTruth& truth) const;
  /// What a real scanner's physics does to the cast ranges before the device encodes them
  /// (dark_dropout, mixed_pixels; return_physics.cpp), from a stream of its own: off, the
  /// image is untouched and every other draw is as without it.
  void applyReturnPhysics(RangeImage& img) const;

 private:
  mrpt::obs::CObservation::Ptr make2D(const RangeImage& img, double t, std::mt19937_64& rng,
                                      ReturnTruth& truth) const;
  mrpt::obs::CObservation::Ptr makeVelodyne(const RangeImage& img, double t, std::mt19937_64& rng,
                                            ReturnTruth& truth) const;
  SensorSpec spec_;
  mutable Reflectivity reflectivity_;  // the VLP-16's intensity byte
  mutable std::mt19937_64 physics_rng_;
};

}  // namespace pedtrack::sim
