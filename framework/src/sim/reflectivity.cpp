#include "pedtrack/sim/reflectivity.h"

#include <algorithm>
#include <cmath>

#include "pedtrack/sim/geometry.h"

namespace pedtrack::sim {

Reflectivity::Reflectivity(unsigned long seed) : seed_(seed), noise_(seed ^ 0x5bd1e995u) {}

double Reflectivity::surface(int owner) {
  const auto it = surface_.find(owner);
  if (it != surface_.end()) return it->second;
  // One draw per surface from a stream of the surface's own: its value does not depend on which
  // surfaces the sensor happened to see first.
  std::mt19937_64 draw(seed_ * 0x9e3779b97f4a7c15ull + static_cast<unsigned long>(owner + 1000003));
  std::uniform_real_distribution<double> u01(0, 1);
  const double lo = owner == kOwnerGround ? kGroundMin : owner > 0 ? kPersonMin : kObjectMin;
  const double hi = owner == kOwnerGround ? kGroundMax : owner > 0 ? kPersonMax : kObjectMax;
  const double value = lo + (hi - lo) * u01(draw);
  surface_.emplace(owner, value);
  return value;
}

std::uint8_t Reflectivity::of(int owner) {
  std::normal_distribution<double> noise(0, kReturnSigma);
  const double v = surface(owner) + noise(noise_);
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

}  // namespace pedtrack::sim
