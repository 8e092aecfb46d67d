#include "pedtrack/track/gnn.h"

#include <cmath>
#include <limits>

namespace pedtrack::track {

Assignment gnnAssociate(int tracks, int measurements, const std::function<double(int, int)>& cost,
                        double gate) {
  std::vector<double> c(std::size_t(tracks) * std::size_t(measurements));
  for (int t = 0; t < tracks; ++t)
    for (int m = 0; m < measurements; ++m) {
      const double v = cost(t, m);
      c[std::size_t(t) * measurements + m] =
          std::isfinite(v) ? v : std::numeric_limits<double>::quiet_NaN();
    }
  return solveAssignment(c, tracks, measurements, gate);
}

}  // namespace pedtrack::track
