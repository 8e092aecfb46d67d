#include "palette.h"

#include <array>
#include <cmath>

namespace pedtrack::render {
namespace {

// Bright, mutually distinct hues that read well on the dark background (BGR).
// Neighbouring ids get far-apart hues (ids are usually consecutive).
const std::array<cv::Scalar, 9> kTrackPalette = {
    cv::Scalar(75, 25, 230),    // red
    cv::Scalar(255, 120, 40),   // blue
    cv::Scalar(48, 130, 245),   // orange
    cv::Scalar(230, 50, 240),   // magenta
    cv::Scalar(230, 210, 0),    // cyan
    cv::Scalar(40, 110, 170),   // brown
    cv::Scalar(255, 90, 150),   // violet
    cv::Scalar(190, 160, 255),  // pink
    cv::Scalar(130, 150, 0),    // teal
};

}  // namespace

cv::Scalar trackColor(long id) {
  // Unsigned wrap-around keeps negative ids (and LONG_MIN) well defined and stable.
  return kTrackPalette[static_cast<unsigned long>(id) % kTrackPalette.size()];
}

int trackPaletteSize() {
  return static_cast<int>(kTrackPalette.size());
}

cv::Scalar clusterColor(long id) {
  // Golden-angle steps over the 260° of hue outside [50°, 150°) (yellow to green).
  const double u =
      std::fmod(static_cast<double>(static_cast<unsigned long>(id) % 100003) * 0.6180339887, 1.0);
  double hue = u * 260.0;
  if (hue >= 50) hue += 100;
  // HSV (S 0.6, V 1) to BGR, in whole units: the colour drawn is exactly the colour returned.
  const double s = 0.6, h6 = hue / 60.0, f = h6 - std::floor(h6);
  const double p = std::round(255 * (1 - s)), q = std::round(255 * (1 - s * f)),
               t = std::round(255 * (1 - s * (1 - f)));
  switch (static_cast<int>(h6) % 6) {
    case 0:
      return {p, t, 255};
    case 1:
      return {p, 255, q};
    case 2:
      return {t, 255, p};
    case 3:
      return {255, q, p};
    case 4:
      return {255, p, t};
    default:
      return {q, p, 255};
  }
}

}  // namespace pedtrack::render
