#pragma once
// Line plots drawn with OpenCV into a PNG: axes with ticks and labels (linear or base-10 log),
// lines (solid or dashed, broken at NaN), horizontal reference lines, markers, a legend and a
// title; scatter dots; panels stacked into one image. `pedtrack eval --roc`, `--shape-plot` and
// `pedtrack montecarlo` draw with it.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace pedtrack::cli::plot {

/// Distinct line colours (BGR), cycled by index.
cv::Scalar colour(std::size_t i);
const cv::Scalar kBlack(0, 0, 0), kGrey(150, 150, 150), kRed(40, 40, 210), kGreen(40, 150, 40),
    kBlue(200, 90, 20);

struct Axis {
  std::string label;
  double min = 0, max = 1;
  bool log = false;  ///< base-10 scale (min > 0)
  double step = 0;   ///< linear tick spacing; 0: a 1-2-5 step giving about 6 ticks
};

/// An axis spanning the finite `values` (only the positive ones when `log`), with a little room
/// on each side; from 0 when `from_zero` and every value is ≥ 0. [0, 1] (log: [0.1, 10]) when
/// there are none.
Axis fitAxis(const std::string& label, const std::vector<double>& values, bool log = false,
             bool from_zero = false);

/// Where the legend goes; Best: the corner covering the fewest drawn pixels.
enum class Corner { Best, TopLeft, TopRight, BottomLeft, BottomRight };

class Plot {
 public:
  /// A white `width` × `height` image with the axes, grid, tick labels and title drawn.
  Plot(int width, int height, const Axis& x, const Axis& y, const std::string& title = "");

  /// A polyline through (x[i], y[i]); a NaN (or, on a log axis, a non-positive) value breaks it.
  /// Drawn clipped to the plot area. A non-empty `label` adds a legend entry.
  void line(const std::vector<double>& x, const std::vector<double>& y, const cv::Scalar& colour,
            int thickness = 2, bool dashed = false, const std::string& label = "");
  /// A horizontal line across the plot at `y`.
  void hline(double y, const cv::Scalar& colour, int thickness = 1, bool dashed = true,
             const std::string& label = "");
  /// A circle marker at (x, y).
  void marker(double x, double y, const cv::Scalar& colour, int radius = 5);
  /// A filled dot at each finite (x[i], y[i]) inside the plot area (a scatter plot). A non-empty
  /// `label` adds a legend entry drawn as a dot.
  void scatter(const std::vector<double>& x, const std::vector<double>& y, const cv::Scalar& colour,
               int radius = 2, const std::string& label = "");
  /// A legend entry drawn by nothing else (e.g. "+ 3 more").
  void note(const std::string& label, const cv::Scalar& colour);
  /// Draws the legend entries collected so far in a box at `corner` of the plot area.
  void legend(Corner corner = Corner::Best, double font_scale = 0.45);
  /// Writes the image (PNG by the extension); false when it cannot.
  bool write(const std::string& path) const;

  cv::Point pixel(double x, double y) const;
  const cv::Mat& image() const { return img_; }

 private:
  double fx(double x) const;  ///< fraction of the plot width, 0 at x.min
  double fy(double y) const;  ///< fraction of the plot height, 0 at y.min
  void drawAxes(const std::string& title);

  struct Entry {
    std::string label;
    cv::Scalar colour;
    int thickness;
    bool dashed;
    int dot = 0;  ///< > 0: a scatter entry, a dot of this radius
  };
  cv::Mat img_;
  cv::Rect area_;  ///< the plot area in the image
  Axis x_, y_;
  std::vector<Entry> entries_;
};

/// The plots' images one above the other (the widest sets the width; narrower ones padded with
/// white), written to `path` (PNG by the extension); false when it cannot.
bool writeStacked(const std::vector<const Plot*>& plots, const std::string& path);

}  // namespace pedtrack::cli::plot
