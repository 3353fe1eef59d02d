#pragma once
// The plots' shared drawing helpers (renders/plot.cpp, renders/heatmap.cpp): text,
// colours, number formats and axis ticks. Internal to the renders layer.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "renders/frame.hpp"
#include "renders/layout.hpp"

namespace mmv::render::plot_detail {


inline const cv::Scalar kBlack(0, 0, 0), kGrey(200, 200, 200), kWhite(255, 255, 255);
/// The qualitative palette: black, Okabe-Ito's colour-blind-safe colours (less the yellow,
/// unreadable on white), then Tol's muted ones and a grey.
constexpr int kPaletteSize = 14;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
/// A legend entry's series shows at least this many pixels in its own colour.
constexpr int kMinShownPixels = 30;

inline void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.45, cv::Scalar colour = kBlack,
          bool centred = false, int thickness = 1) {
  int base = 0;
  const cv::Size sz = cv::getTextSize(s, kFont, scale, thickness, &base);
  if (centred) at.x -= sz.width / 2;
  putTextLogged(img, s, at, scale, colour, thickness);
}

/// Centred text, its scale reduced until it fits `max_width` pixels (a long title is
/// smaller, never cut at the image's edge), and kept inside the image.
inline void fittedText(cv::Mat& img, const std::string& s, cv::Point at, double scale, int max_width) {
  int base = 0;
  while (scale > 0.3 && cv::getTextSize(s, kFont, scale, 1, &base).width > max_width) scale *= 0.93;
  const int w = cv::getTextSize(s, kFont, scale, 1, &base).width;
  at.x = std::clamp(at.x, 5 + w / 2, std::max(5 + w / 2, img.cols - 5 - w / 2));
  text(img, s, at, scale, kBlack, true);
}

/// A label written along a strip of `length` px turned upright at (x, top): its box on the
/// canvas, for the layout log (the text runs bottom to top, centred on the strip).
inline void layoutRotatedText(const std::string& s, int x, int top, int length, double scale) {
  if (s.empty()) return;
  const cv::Rect b = textBox(s, {0, 20}, scale);
  // In the strip (30 px high, `length` wide) the text spans [length/2 - w/2, length/2 + w/2]
  // across and [b.y, b.y + b.height] down; turned counterclockwise, across becomes up.
  layoutText(s, cv::Rect(x + b.y, top + length / 2 - b.width / 2, b.height, b.width));
}

/// Viridis-like colour for t in [0, 1] (BGR), from five anchors.
inline cv::Scalar colourFor(double t) {
  static const double anchors[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) * 4.0 : 0.0;  // a NaN would index past the table
  const int i = std::min(3, static_cast<int>(t));
  const double f = t - i;
  double rgb[3];
  for (int c = 0; c < 3; ++c) rgb[c] = anchors[i][c] + f * (anchors[i + 1][c] - anchors[i][c]);
  return cv::Scalar(rgb[2], rgb[1], rgb[0]);
}

inline void save(const std::string& path, const cv::Mat& img) { writePng(path, img); }

/// `v` formatted; |v| below `zero_below` prints as 0 (a linear axis' tick that is zero
/// up to round-off, never "-0" or "1e-17"; pass a fraction of the tick step).
inline std::string fmt(double v, const char* f = "%.3g", double zero_below = 0.0) {
  if (std::abs(v) < zero_below || v == 0.0) v = 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

/// "Nice" tick step for a range.
inline double tickStep(double range, int target = 6) {
  const double raw = range / target, mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (raw <= m * mag) return m * mag;
  return 10 * mag;
}

/// The ticks of a linear axis over [a0, a1]: multiples of a "nice" step, counted by an
/// integer index so a range of a few ulps (where x + step == x) still ends; at most 50.
inline std::vector<double> linearTicks(double a0, double a1) {
  std::vector<double> out;
  const double step = tickStep(a1 - a0);
  if (!(step > 0) || !std::isfinite(step)) return out;
  const double k0 = std::ceil(a0 / step), k1 = std::floor(a1 / step + 1e-9);
  for (double k = k0; k <= k1 && out.size() < 50; k += 1.0) out.push_back(k * step);
  return out;
}

/// Widens [lo, hi] to a range a plot can resolve: a point (or a span of a few ulps,
/// where pixel positions and tick steps underflow) becomes a span around its centre.
inline void resolvableRange(double& lo, double& hi) {
  const double scale = std::max({std::abs(lo), std::abs(hi), 1e-300});
  if (hi - lo > 1e-9 * scale) return;
  const double mid = 0.5 * (lo + hi), half = lo == hi && lo == 0 ? 1.0 : std::max(1e-6 * scale, 1e-300);
  lo = mid - half;
  hi = mid + half;
}


}  // namespace mmv::render::plot_detail
