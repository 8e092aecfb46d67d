#pragma once
// What the simulated VLP-16 reports as each return's intensity (its calibrated reflectivity,
// 0-100 for diffuse surfaces). Real scenes do not sort by reflectivity: a white wall and a light
// shirt read alike, dark trousers and asphalt too. Each surface — the ground, every object,
// every person — gets a reflectivity of its own, drawn once from its class's range (the ranges
// overlap), and every return adds noise, so no stage can read the truth from the intensity.
#include <cstdint>
#include <random>
#include <unordered_map>

namespace pedtrack::sim {

class Reflectivity {
 public:
  /// Draws from streams of their own (seeded by `seed`): the geometry's random numbers, and so
  /// every range and every truth, are as without intensities.
  explicit Reflectivity(unsigned long seed);
  /// The intensity byte of one return on `owner` (geometry.h: ground, a person, an object).
  std::uint8_t of(int owner);
  /// The surface's own reflectivity, before the return's noise.
  double surface(int owner);

  /// Class ranges of the surfaces' reflectivity and the noise of one return (VLP-16 units).
  static constexpr double kGroundMin = 4, kGroundMax = 30;   // asphalt, paving, grass
  static constexpr double kPersonMin = 3, kPersonMax = 60;   // dark to light clothing
  static constexpr double kObjectMin = 5, kObjectMax = 100;  // dark plastic to white paint
  static constexpr double kReturnSigma = 4;

 private:
  unsigned long seed_;
  std::unordered_map<int, double> surface_;
  std::mt19937_64 noise_;
};

}  // namespace pedtrack::sim
