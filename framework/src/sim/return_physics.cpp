// What a real scanner's physics does to the ranges the ray caster found: dark surfaces fade out
// sooner (the return's power falls with reflectivity over range squared), and a beam that meets
// a depth edge with part of its footprint on each surface returns a range in between (a mixed
// pixel, floating in the air between a person and the wall behind).
#include <algorithm>
#include <cmath>

#include "pedtrack/sim/geometry.h"
#include "pedtrack/sim/sensor_model.h"

namespace pedtrack::sim {
namespace {
constexpr double kMixedMinGap = 0.3, kMixedMaxGap = 1.5;  // m
}  // namespace

void ObservationMaker::applyReturnPhysics(RangeImage& img) const {
  if (!spec_.dark_dropout && spec_.mixed_pixels <= 0) return;
  std::uniform_real_distribution<double> u01(0, 1);
  const std::size_t n = img.range.size();
  if (spec_.dark_dropout) {
    // Reach at reflectivity R: half max_range at 10 %, growing with sqrt(R) (power ∝ R / r²).
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(img.range[i])) continue;
      const double R = std::max(0.5, reflectivity_.surface(img.owner[i]));
      const double reach = 0.5 * spec_.max_range * std::sqrt(R / 10);
      const double lost = std::clamp((img.range[i] - 0.8 * reach) / (0.2 * reach), 0.0, 1.0);
      if (u01(physics_rng_) < lost) img.range[i] = kNoHit;
    }
  }
  if (spec_.mixed_pixels > 0) {
    const std::vector<double> range = img.range;  // edges of the image as cast
    const std::vector<int> owner = img.owner;
    for (int r = 0; r < img.rings; ++r)
      for (int c = 0; c < img.cols; ++c) {
        const std::size_t i = static_cast<std::size_t>(r) * img.cols + c;
        if (!std::isfinite(range[i])) continue;
        // The neighbour in the ring with the larger jump (a full circle wraps round).
        const bool wrap = spec_.is3d;
        double best = 0;
        std::size_t other = i;
        for (const int d : {-1, 1}) {
          int cc = c + d;
          if (cc < 0 || cc >= img.cols) {
            if (!wrap) continue;
            cc = (cc + img.cols) % img.cols;
          }
          const std::size_t j = static_cast<std::size_t>(r) * img.cols + cc;
          if (!std::isfinite(range[j])) continue;
          const double jump = std::abs(range[j] - range[i]);
          if (jump > best) best = jump, other = j;
        }
        // Only surfaces closer than the pulse can tell apart are averaged; farther apart they
        // give two returns and the device keeps one of them.
        if (best < kMixedMinGap || best > kMixedMaxGap || u01(physics_rng_) >= spec_.mixed_pixels)
          continue;
        const double mixed = range[i] + u01(physics_rng_) * (range[other] - range[i]);
        img.range[i] = mixed;
        // The return belongs to the surface it lies nearer.
        img.owner[i] =
            std::abs(mixed - range[i]) <= std::abs(mixed - range[other]) ? owner[i] : owner[other];
      }
  }
}

}  // namespace pedtrack::sim
