// The trace panel under a history video: each recorded column against time, the
// current moment marked (renders/frame.hpp, tracePanel).
#include "renders/frame.hpp"
#include "renders/layout.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mmv::render {

namespace {

/// "Nice" ticks over [a, b] (1, 2 or 5 times a power of ten apart, about `target` of them).
std::vector<double> niceTicks(double a, double b, int target) {
  std::vector<double> out;
  if (!(b > a)) return out;
  const double raw = (b - a) / target, mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (double m : {1.0, 2.0, 5.0})
    if (raw <= m * mag) { step = m * mag; break; }
  for (double k = std::ceil(a / step); k * step <= b + 1e-9 * step && out.size() < 50; k += 1) out.push_back(k * step);
  return out;
}

/// One strip of the trace panel: the trace within 4 px of its border, the time grid, its
/// limit (a sensor's range, a torquer's capacity) dashed when it is on the strip's scale,
/// the name and the value at `now` on top, the strip's extremes at its right edge.
void drawStrip(cv::Mat& img, const cv::Rect& r, const Trace& tr, double t0, double t1, double now,
               const std::vector<double>& time_ticks) {
  double lo = *std::min_element(tr.v.begin(), tr.v.end()), hi = *std::max_element(tr.v.begin(), tr.v.end());
  // A limit within 3x the trace's reach is drawn on its scale; farther, only named.
  const bool limit_shown = tr.limit > 0 && tr.limit <= 3 * std::max(std::abs(lo), std::abs(hi));
  if (limit_shown) lo = std::min(lo, -tr.limit), hi = std::max(hi, tr.limit);
  if (!(hi > lo)) lo -= 1, hi += 1;
  const int inner = std::max(2, r.height - 9);
  auto y = [&](double v) { return r.y + 4 + inner - static_cast<int>(std::lround((v - lo) / (hi - lo) * inner)); };
  auto x = [&](double t) { return r.x + static_cast<int>(std::lround((t - t0) / (t1 - t0) * (r.width - 1))); };
  cv::rectangle(img, r, cv::Scalar(200, 200, 200), 1);
  for (double t : time_ticks) cv::line(img, {x(t), r.y + 1}, {x(t), r.y + r.height - 2}, cv::Scalar(235, 235, 235), 1);
  if (lo < 0 && hi > 0) cv::line(img, {r.x + 1, y(0)}, {r.x + r.width - 2, y(0)}, cv::Scalar(215, 215, 215), 1);
  if (limit_shown)
    for (const double v : {-tr.limit, tr.limit})
      for (int px = r.x + 2; px < r.x + r.width - 2; px += 9) cv::line(img, {px, y(v)}, {std::min(px + 5, r.x + r.width - 2), y(v)}, cv::Scalar(40, 40, 200), 1);
  // Per pixel column: the least and greatest sample in it, joined to the next column.
  std::vector<double> mn(r.width, 1e300), mx(r.width, -1e300);
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    const int c = std::clamp(x(tr.t[i]) - r.x, 0, r.width - 1);
    mn[c] = std::min(mn[c], tr.v[i]);
    mx[c] = std::max(mx[c], tr.v[i]);
  }
  int last = -1;
  for (int c = 0; c < r.width; ++c) {
    if (mn[c] > mx[c]) continue;
    const bool past = t0 + (t1 - t0) * c / std::max(1, r.width - 1) <= now;
    const cv::Scalar colour = past ? cv::Scalar(180, 90, 20) : cv::Scalar(190, 190, 190);
    cv::line(img, {r.x + c, y(mn[c])}, {r.x + c, y(mx[c])}, colour, 1);
    if (last >= 0) cv::line(img, {r.x + last, y(0.5 * (mn[last] + mx[last]))}, {r.x + c, y(0.5 * (mn[c] + mx[c]))}, colour, 1);
    last = c;
  }
  const int cx = x(std::clamp(now, t0, t1));
  cv::line(img, {cx, r.y}, {cx, r.y + r.height - 1}, cv::Scalar(40, 40, 200), 1);
  const auto it = std::upper_bound(tr.t.begin(), tr.t.end(), now);
  const std::size_t k = it == tr.t.begin() ? 0 : static_cast<std::size_t>(it - tr.t.begin()) - 1;
  char text[200], top[32], bottom[32];
  if (tr.limit > 0)
    std::snprintf(text, sizeof text, "%s: %.4g  (%s +-%.3g%s)", tr.name.c_str(), tr.v[k], tr.limit_label.c_str(), tr.limit,
                  limit_shown ? "" : ", off scale");
  else
    std::snprintf(text, sizeof text, "%s: %.4g", tr.name.c_str(), tr.v[k]);
  std::snprintf(top, sizeof top, "%.3g", hi);
  std::snprintf(bottom, sizeof bottom, "%.3g", lo);
  const int right = r.x + r.width - 4;
  const cv::Rect top_box = textBox(top, {0, 0}, 0.35), bottom_box = textBox(bottom, {0, 0}, 0.35);
  // The name is set smaller rather than run into the extremes' labels or past the strip.
  double scale = 0.4;
  for (int base = 0; scale > 0.28 && cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base).width > r.width - 16 - top_box.width;)
    scale *= 0.93;
  putTextLogged(img, text, {r.x + 4, r.y + 13}, scale, cv::Scalar(0, 0, 0));
  putTextLogged(img, top, {right - top_box.width, r.y + 13}, 0.35, cv::Scalar(90, 90, 90));
  if (r.height >= 34) putTextLogged(img, bottom, {right - bottom_box.width, r.y + r.height - 5}, 0.35, cv::Scalar(90, 90, 90));
}

}  // namespace

cv::Mat tracePanel(const std::vector<Trace>& traces, double now, cv::Size size) {
  cv::Mat img(size, CV_8UC3, cv::Scalar(255, 255, 255));
  layoutNewImage(size.width, size.height, "traces");
  double t0 = 1e300, t1 = -1e300;
  for (const auto& tr : traces)
    if (!tr.t.empty()) t0 = std::min(t0, tr.t.front()), t1 = std::max(t1, tr.t.back());
  if (traces.empty() || !(t1 > t0)) return img;
  const int n = static_cast<int>(traces.size()), top = 40, bottom = 46;
  const int strip = std::max(24, (size.height - top - bottom) / n);
  const std::vector<double> ticks = niceTicks(t0, t1, std::max(2, (size.width - 16) / 90));
  for (int i = 0; i < n; ++i)
    if (!traces[i].t.empty())
      drawStrip(img, cv::Rect(8, top + i * strip, size.width - 16, strip - 8), traces[i], t0, t1, now, ticks);
  // The time axis under the strips: its ticks' values, then where the run is.
  const int axis_y = top + n * strip + 6;
  for (double t : ticks) {
    char label[32];
    std::snprintf(label, sizeof label, "%g", std::abs(t) < 1e-12 ? 0.0 : t);
    const int x = 8 + static_cast<int>(std::lround((t - t0) / (t1 - t0) * (size.width - 17)));
    const int w = textBox(label, {0, 0}, 0.38).width;
    putTextLogged(img, label, {std::clamp(x - w / 2, 2, size.width - w - 2), axis_y}, 0.38, cv::Scalar(0, 0, 0));
  }
  char text[64];
  std::snprintf(text, sizeof text, "time (s): t = %.3f s of %.3g s", now, t1);
  putTextLogged(img, text, {8, std::min(size.height - 8, axis_y + 20)}, 0.42, cv::Scalar(0, 0, 0));
  return img;
}

}  // namespace mmv::render
