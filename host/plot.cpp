#include "plot.h"

#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace pedtrack::cli::plot {
namespace {

const auto kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kGrid(225, 225, 225), kWhite(255, 255, 255);
constexpr double kTickFont = 0.4, kLabelFont = 0.5;
constexpr int kDashOn = 8, kDashOff = 6;  // px

/// 1, 2 or 5 × 10^k nearest above `raw`.
double niceStep(double raw) {
  if (!(raw > 0) || !std::isfinite(raw)) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p * (1 + 1e-9)) return m * p;
  return 10 * p;
}

int decimalsFor(double step) {
  return std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
}

struct Tick {
  double value;
  std::string text;
};

std::vector<Tick> ticks(const Axis& a) {
  std::vector<Tick> out;
  if (a.log) {
    const int k0 = int(std::floor(std::log10(a.min) + 1e-9));
    const int k1 = int(std::ceil(std::log10(a.max) - 1e-9));
    const bool fine = std::log10(a.max / a.min) < 2.5;  // a few decades: 1, 2, 5 each
    for (int k = k0; k <= k1; ++k)
      for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
        const double v = m * std::pow(10.0, k);
        if (v >= a.min * (1 - 1e-9) && v <= a.max * (1 + 1e-9))
          out.push_back({v, mrpt::format("%g", v)});
      }
    return out;
  }
  const double step = a.step > 0 ? a.step : niceStep((a.max - a.min) / 6);
  const int dec = decimalsFor(step);
  for (double v = std::ceil(a.min / step - 1e-9) * step; v <= a.max + step * 1e-9; v += step) {
    const double r = std::abs(v) < step * 1e-9 ? 0.0 : v;  // no "-0.0"
    out.push_back({r, mrpt::format("%.*f", dec, r)});
  }
  return out;
}

int clampPx(double v) {
  return int(std::lround(std::clamp(v, -1e5, 1e5)));
}

/// A dashed polyline whose pattern runs on across the vertices.
void dashedPolyline(cv::Mat& img, const std::vector<cv::Point>& pts, const cv::Scalar& colour,
                    int thickness) {
  double phase = 0;  // distance into the current on+off period
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const cv::Point2d a = pts[i - 1], b = pts[i];
    const double len = cv::norm(b - a);
    double s = 0;
    while (s < len) {
      const bool on = phase < kDashOn;
      const double piece = std::min(len - s, on ? kDashOn - phase : kDashOn + kDashOff - phase);
      if (on) {
        const cv::Point2d p = a + (b - a) * (s / len), q = a + (b - a) * ((s + piece) / len);
        cv::line(img, cv::Point(clampPx(p.x), clampPx(p.y)), cv::Point(clampPx(q.x), clampPx(q.y)),
                 colour, thickness, cv::LINE_AA);
      }
      s += piece;
      phase = std::fmod(phase + piece, double(kDashOn + kDashOff));
    }
  }
}

void text(cv::Mat& img, const std::string& t, cv::Point at, double scale,
          const cv::Scalar& colour = kBlack) {
  cv::putText(img, t, at, kFont, scale, colour, 1, cv::LINE_AA);
}

cv::Size textSize(const std::string& t, double scale) {
  int base = 0;
  return cv::getTextSize(t, kFont, scale, 1, &base);
}

}  // namespace

cv::Scalar colour(std::size_t i) {
  static const cv::Scalar colours[] = {{200, 90, 20},  {30, 30, 210},  {40, 150, 40},
                                       {150, 40, 150}, {20, 140, 200}, {140, 140, 20},
                                       {90, 60, 30},   {180, 105, 255}};
  return colours[i % (sizeof(colours) / sizeof(colours[0]))];
}

Axis fitAxis(const std::string& label, const std::vector<double>& values, bool log,
             bool from_zero) {
  Axis a;
  a.label = label;
  a.log = log;
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (std::isfinite(v) && (!log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!std::isfinite(lo)) {
    a.min = log ? 0.1 : 0, a.max = log ? 10 : 1;
    return a;
  }
  if (log) {
    if (hi <= lo * 1.01) lo /= 2, hi *= 2;
    const double pad = std::pow(hi / lo, 0.04);
    a.min = lo / pad, a.max = hi * pad;
    return a;
  }
  if (from_zero && lo >= 0) lo = 0;
  if (hi - lo < 1e-12) hi = lo + (lo == 0 ? 1 : std::abs(lo) * 0.1);
  const double pad = 0.04 * (hi - lo);
  a.min = from_zero && lo == 0 ? 0 : lo - pad;
  a.max = hi + pad;
  return a;
}

Plot::Plot(int width, int height, const Axis& x, const Axis& y, const std::string& title)
    : img_(height, width, CV_8UC3, kWhite), x_(x), y_(y) {
  const int left = 80, right = 25, top = title.empty() ? 22 : 40, bottom = 55;
  area_ = cv::Rect(left, top, width - left - right, height - top - bottom);
  drawAxes(title);
}

double Plot::fx(double x) const {
  return x_.log ? std::log10(x / x_.min) / std::log10(x_.max / x_.min)
                : (x - x_.min) / (x_.max - x_.min);
}

double Plot::fy(double y) const {
  return y_.log ? std::log10(y / y_.min) / std::log10(y_.max / y_.min)
                : (y - y_.min) / (y_.max - y_.min);
}

cv::Point Plot::pixel(double x, double y) const {
  return {clampPx(area_.x + fx(x) * area_.width), clampPx(area_.y + (1 - fy(y)) * area_.height)};
}

void Plot::drawAxes(const std::string& title) {
  const int bottom = area_.y + area_.height;
  for (const Tick& t : ticks(x_)) {
    const int px = pixel(t.value, y_.min).x;
    cv::line(img_, {px, area_.y}, {px, bottom}, kGrid, 1);
    cv::line(img_, {px, bottom}, {px, bottom + 4}, kBlack, 1);
    const cv::Size s = textSize(t.text, kTickFont);
    text(img_, t.text, {px - s.width / 2, bottom + 18}, kTickFont);
  }
  for (const Tick& t : ticks(y_)) {
    const int py = pixel(x_.min, t.value).y;
    cv::line(img_, {area_.x, py}, {area_.x + area_.width, py}, kGrid, 1);
    cv::line(img_, {area_.x - 4, py}, {area_.x, py}, kBlack, 1);
    const cv::Size s = textSize(t.text, kTickFont);
    text(img_, t.text, {area_.x - 8 - s.width, py + s.height / 2}, kTickFont);
  }
  cv::rectangle(img_, area_, kBlack, 1);
  const cv::Size xs = textSize(x_.label, kLabelFont);
  text(img_, x_.label, {area_.x + (area_.width - xs.width) / 2, img_.rows - 14}, kLabelFont);
  if (!y_.label.empty()) {
    // The y label is drawn horizontally into a strip that is then turned on its side.
    const cv::Size ys = textSize(y_.label, kLabelFont);
    const int w = std::min(ys.width + 8, area_.height), h = ys.height + 10;
    cv::Mat strip(h, w, CV_8UC3, kWhite);
    text(strip, y_.label, {(w - ys.width) / 2, h - 6}, kLabelFont);
    cv::rotate(strip, strip, cv::ROTATE_90_COUNTERCLOCKWISE);
    strip.copyTo(img_(cv::Rect(6, area_.y + (area_.height - w) / 2, h, w)));
  }
  if (!title.empty()) {
    double scale = kLabelFont;
    while (scale > 0.3 && textSize(title, scale).width > img_.cols - 20) scale -= 0.05;
    const cv::Size ts = textSize(title, scale);
    text(img_, title, {std::max(10, (img_.cols - ts.width) / 2), area_.y - 14}, scale);
  }
}

void Plot::line(const std::vector<double>& x, const std::vector<double>& y,
                const cv::Scalar& colour, int thickness, bool dashed, const std::string& label) {
  // Drawn into the plot area (a few pixels of slack for the line width), which clips it.
  const cv::Rect clip = (area_ + cv::Size(6, 6) - cv::Point(3, 3)) & cv::Rect({}, img_.size());
  cv::Mat roi = img_(clip);
  std::vector<cv::Point> run;
  auto flush = [&] {
    if (run.size() == 1) cv::circle(roi, run[0], std::max(1, thickness), colour, -1, cv::LINE_AA);
    if (run.size() > 1) {
      if (dashed)
        dashedPolyline(roi, run, colour, thickness);
      else
        cv::polylines(roi, run, false, colour, thickness, cv::LINE_AA);
    }
    run.clear();
  };
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    const bool ok = std::isfinite(x[i]) && std::isfinite(y[i]) && (!x_.log || x[i] > 0) &&
                    (!y_.log || y[i] > 0);
    if (!ok) {
      flush();
      continue;
    }
    run.push_back(pixel(x[i], y[i]) - clip.tl());
  }
  flush();
  if (!label.empty()) entries_.push_back({label, colour, thickness, dashed});
}

void Plot::hline(double y, const cv::Scalar& colour, int thickness, bool dashed,
                 const std::string& label) {
  line({x_.min, x_.max}, {y, y}, colour, thickness, dashed, label);
}

void Plot::marker(double x, double y, const cv::Scalar& colour, int radius) {
  cv::circle(img_, pixel(x, y), radius, colour, 2, cv::LINE_AA);
}

void Plot::scatter(const std::vector<double>& x, const std::vector<double>& y,
                   const cv::Scalar& colour, int radius, const std::string& label) {
  const cv::Rect clip = area_ & cv::Rect({}, img_.size());
  cv::Mat roi = img_(clip);
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    const bool ok = std::isfinite(x[i]) && std::isfinite(y[i]) && (!x_.log || x[i] > 0) &&
                    (!y_.log || y[i] > 0);
    if (ok) cv::circle(roi, pixel(x[i], y[i]) - clip.tl(), radius, colour, -1, cv::LINE_AA);
  }
  if (!label.empty()) entries_.push_back({label, colour, 0, false, std::max(1, radius)});
}

void Plot::note(const std::string& label, const cv::Scalar& colour) {
  entries_.push_back({label, colour, 0, false});
}

void Plot::legend(Corner corner, double font_scale) {
  if (entries_.empty()) return;
  const int swatch = 26, pad = 6, row = int(std::lround(40 * font_scale)) + 2;
  int w = 0;
  for (const auto& e : entries_) w = std::max(w, textSize(e.label, font_scale).width);
  w += swatch + 3 * pad;
  const int h = int(entries_.size()) * row + pad;
  auto boxAt = [&](Corner c) {
    const bool left = c == Corner::TopLeft || c == Corner::BottomLeft;
    const bool top = c == Corner::TopLeft || c == Corner::TopRight;
    return cv::Rect(left ? area_.x + 8 : area_.x + area_.width - 8 - w,
                    top ? area_.y + 8 : area_.y + area_.height - 8 - h, w, h) &
           cv::Rect({}, img_.size());
  };
  cv::Rect box = boxAt(corner == Corner::Best ? Corner::TopRight : corner);
  if (corner == Corner::Best) {
    std::size_t least = SIZE_MAX;
    for (Corner c : {Corner::TopRight, Corner::TopLeft, Corner::BottomRight, Corner::BottomLeft}) {
      // Drawn pixels: darker than the grid in some channel.
      cv::Mat dark;
      cv::inRange(img_(boxAt(c)), cv::Scalar(200, 200, 200), cv::Scalar(255, 255, 255), dark);
      const std::size_t n = dark.total() - std::size_t(cv::countNonZero(dark));
      if (n < least) least = n, box = boxAt(c);
    }
  }
  cv::rectangle(img_, box, kWhite, -1);
  cv::rectangle(img_, box, kGrey, 1);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const auto& e = entries_[i];
    const int y = box.y + pad + int(i) * row + row / 2;
    const cv::Point a(box.x + pad, y), b(box.x + pad + swatch, y);
    if (e.dot > 0)
      cv::circle(img_, (a + b) / 2, std::max(3, e.dot), e.colour, -1, cv::LINE_AA);
    else if (e.thickness > 0 && e.dashed)
      dashedPolyline(img_, {a, b}, e.colour, e.thickness);
    else if (e.thickness > 0)
      cv::line(img_, a, b, e.colour, e.thickness, cv::LINE_AA);
    const cv::Size s = textSize(e.label, font_scale);
    text(img_, e.label, {b.x + pad, y + s.height / 2}, font_scale,
         e.thickness > 0 || e.dot > 0 ? kBlack : e.colour);
  }
}

bool Plot::write(const std::string& path) const {
  try {
    return cv::imwrite(path, img_);
  } catch (const cv::Exception&) {
    return false;
  }
}

bool writeStacked(const std::vector<const Plot*>& plots, const std::string& path) {
  int width = 0;
  for (const Plot* p : plots) width = std::max(width, p->image().cols);
  std::vector<cv::Mat> rows;
  for (const Plot* p : plots) {
    cv::Mat m = p->image();
    if (m.cols < width)
      cv::copyMakeBorder(m, m, 0, 0, 0, width - m.cols, cv::BORDER_CONSTANT, kWhite);
    rows.push_back(m);
  }
  if (rows.empty()) return false;
  cv::Mat all;
  cv::vconcat(rows, all);
  try {
    return cv::imwrite(path, all);
  } catch (const cv::Exception&) {
    return false;
  }
}

}  // namespace pedtrack::cli::plot
