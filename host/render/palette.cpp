#include "palette.h"

#include <array>

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

}  // namespace pedtrack::render
