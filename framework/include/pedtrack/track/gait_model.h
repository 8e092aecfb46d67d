#pragma once
// P3 §2.4's gait model: the projection of the leg vector (left − right) on the sagittal axis is
// L_p(t) = L₀ cos(2π f t + φ) + b (eq. 2), fitted to the last frames by weighted least squares
// with w_j = 1/j² (j = 1 the newest) inside P3's bounds (eq. 3).
//
// Times are taken relative to the newest sample, so φ is the phase now and the fit is well
// conditioned whatever the clock's epoch.
#include <vector>

namespace pedtrack::track::gait {

struct Sample {
  double t = 0;  ///< s
  double l = 0;  ///< m, leg vector projected on the sagittal axis
};

/// P3 eq. 3's bounds.
struct Bounds {
  double l0_min = 0.1, l0_max = 0.5;  ///< m, step length (amplitude)
  double f_min = 0.5, f_max = 1.5;    ///< Hz, gait frequency
  double b_min = 0, b_max = 0.5;      ///< m, offset
};

struct Params {
  double l0 = 0, f = 0, phi = 0, b = 0;  ///< φ in [0, 2π), at t_ref
  double t_ref = 0;                      ///< s, the newest sample's time
  double cost = 0;                       ///< eq. 3's weighted sum of squares at the optimum
  bool valid = false;
  /// L_p at time t (s).
  double at(double t) const;
};

/// Eq. 3's objective at (l0, f, phi, b), times relative to t_ref.
double objective(const std::vector<Sample>& newest_first, double t_ref, double l0, double f,
                 double phi, double b);

/// Fits eq. 3 to `newest_first` (sample j = index + 1, weight 1/j²) by variable projection: for a
/// fixed f the model is linear in (L₀ cos φ, −L₀ sin φ, b), a 3 × 3 weighted least-squares
/// problem with the bounds enforced by clamping and re-solving; f is then searched on a grid over
/// [f_min, f_max] and refined by golden section. Global in f (a local method such as P3's COBYLA
/// can lock onto a harmonic), and ~50 small solves: microseconds per fit. Invalid with fewer than
/// 5 samples.
Params fitVarPro(const std::vector<Sample>& newest_first, const Bounds& bounds);

}  // namespace pedtrack::track::gait
