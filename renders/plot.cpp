#include "renders/plot.hpp"
#include "renders/frame.hpp"
#include "renders/layout.hpp"
#include "renders/plot_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <tuple>

namespace mmv::render {
using namespace plot_detail;

namespace {

/// A series' line: solid (each pixel column's envelope, plot.hpp) or dashed (8 px dashes,
/// 6 px gaps along the whole polyline: a pattern restarted per segment would draw a dense
/// curve solid); markers-only series have none.
void drawSeriesLine(cv::Mat& img, const Series& s, const cv::Scalar& colour, const std::function<int(double)>& px,
                    const std::function<int(double)>& py, const std::function<bool(double, double)>& usable, int thickness,
                    int line_type) {
  if (s.markers_only) return;
  if (!s.dashed) {
    std::vector<std::optional<Pixel>> pts;
    pts.reserve(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i)
      pts.push_back(usable(s.x[i], s.y[i]) ? std::optional<Pixel>(Pixel{px(s.x[i]), py(s.y[i])}) : std::nullopt);
    const auto line = columnEnvelope(pts);
    for (std::size_t i = 1; i < line.size(); ++i)
      if (line[i - 1] && line[i]) cv::line(img, {line[i - 1]->x, line[i - 1]->y}, {line[i]->x, line[i]->y}, colour, thickness, line_type);
    return;
  }
  double phase = 0;  // the distance into the pattern
  for (std::size_t i = 1; i < s.x.size(); ++i) {
    if (!usable(s.x[i - 1], s.y[i - 1]) || !usable(s.x[i], s.y[i])) continue;
    const cv::Point2d a(px(s.x[i - 1]), py(s.y[i - 1])), b(px(s.x[i]), py(s.y[i]));
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    for (double d = 0; d < len;) {
      const double in = std::fmod(phase + d, 14.0), step = std::min(len - d, in < 8 ? 8 - in : 14 - in);
      if (in < 8) {
        const cv::Point2d p0 = a + (b - a) * (d / len), p1 = a + (b - a) * ((d + step) / len);
        cv::line(img, p0, p1, colour, thickness, line_type);
      }
      d += std::max(step, 1e-9);
    }
    phase = std::fmod(phase + len, 14.0);
  }
}

/// Markers drawn over by others' (runs of two integrators on one pixel, under the Pareto
/// front's rings): again on top as dots inside their markers, each point's dot nudged by
/// at most its marker's radius when the dots of series redrawn before would hide it or it
/// them. `shown` is the fewest pixels this series or one redrawn before it shows; the
/// first nudge that shows them all (kMinShownPixels) is kept, or else the best.
void redrawMarkers(cv::Mat& img, cv::Mat& mask, const Series& s, const cv::Scalar& colour,
                   const std::function<int(double)>& px, const std::function<int(double)>& py,
                   const std::function<bool(double, double)>& usable, const std::function<int()>& shown) {
  static const cv::Point kNudges[] = {{0, 0}, {5, 0}, {-5, 0}, {0, -5}, {0, 5}, {4, -4}, {-4, 4}, {4, 4}, {-4, -4}};
  const cv::Mat img0 = img.clone(), mask0 = mask.clone();
  auto draw = [&](const cv::Point& nudge) {
    img0.copyTo(img), mask0.copyTo(mask);
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], s.y[i])) {
        const cv::Point at = cv::Point(px(s.x[i]), py(s.y[i])) + nudge;
        cv::circle(img, at, 4, colour, cv::FILLED, cv::LINE_8);
        cv::circle(mask, at, 4, cv::Scalar(255), cv::FILLED, cv::LINE_8);
      }
    return shown();
  };
  cv::Point best = kNudges[0];
  int most = -1;
  for (const cv::Point& nudge : kNudges) {
    const int n = draw(nudge);
    if (n >= kMinShownPixels) return;
    if (n > most) most = n, best = nudge;
  }
  draw(best);
}

/// A point's label (a trade run's tolerance) beside its marker: the first of ten places
/// around it, nearest first, that stays inside the frame and clear of the labels placed
/// before (`placed`, which receives its box); none free, it is left out rather than drawn
/// over another (CI's slower machine moved two trade points together: "1e-03" over "1e-04").
void placePointLabel(cv::Mat& img, const std::string& label, const cv::Point& at, const cv::Scalar& colour,
                     const cv::Rect& area, std::vector<cv::Rect>& placed) {
  const cv::Rect size = textBox(label, {0, 0}, 0.32);
  const int w = size.width, h = size.height;
  const cv::Point offsets[] = {{7, -5},       {7, h + 5},       {-7 - w, -5},  {-7 - w, h + 5},  {-w / 2, -9},
                               {-w / 2, h + 9}, {14, -14},     {-14 - w, -14}, {14, h + 14},    {-14 - w, h + 14}};
  for (const cv::Point& o : offsets) {
    const cv::Rect box = textBox(label, at + o, 0.32);
    if ((box & area) != box) continue;
    if (std::any_of(placed.begin(), placed.end(), [&](const cv::Rect& p) { return (p & box).area() > 0; })) continue;
    text(img, label, at + o, 0.32, colour);
    placed.push_back(box);
    return;
  }
}

/// Series with the same points and style as an earlier one are drawn once: the earlier
/// one's legend entry names both ("gimbal.pitch capacity +-200 N*m = gimbal.yaw capacity
/// +-200 N*m"), so no entry stands for a line hidden under its twin.
std::vector<Series> mergeCoincident(const std::vector<Series>& given) {
  std::vector<Series> out;
  for (const auto& s : given) {
    auto same = [&](const Series& o) {
      return o.dashed == s.dashed && o.markers_only == s.markers_only && o.hollow == s.hollow && o.x == s.x && o.y == s.y;
    };
    auto it = std::find_if(out.begin(), out.end(), same);
    if (it == out.end()) {
      out.push_back(s);
      continue;
    }
    if (!s.label.empty()) it->label = it->label.empty() ? s.label : it->label + " = " + s.label;
  }
  return out;
}

/// One x-y panel inside `img` (plot area `area`, labels outside it).
void drawPanel(cv::Mat& img, const cv::Rect& area, const std::vector<Series>& given, const std::string& title,
               const std::string& x_label, const std::string& y_label, bool log_x, bool log_y, bool legend,
               const std::vector<double>& markers = {}, bool marker_labels = false, double min_y_span = 0) {
  // A series with no point to draw (a margin without a capacity: every value missing)
  // gets no legend entry; the legend's last line names it ("no data: ...").
  std::vector<Series> series;
  std::string no_data;
  for (auto& s : mergeCoincident(given)) {
    bool any = false;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size() && !any; ++i)
      any = std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!log_x || s.x[i] > 0) && (!log_y || s.y[i] > 0);
    if (any || s.label.empty()) series.push_back(std::move(s));
    else no_data += (no_data.empty() ? "no data: " : ", ") + s.label;
  }
  const int left = area.x, top = area.y, pw = area.width, ph = area.height;
  auto tx = [&](double x) { return log_x ? std::log10(x) : x; };
  auto ty = [&](double y) { return log_y ? std::log10(y) : y; };
  auto usable = [&](double x, double y) {
    return std::isfinite(x) && std::isfinite(y) && (!log_x || x > 0) && (!log_y || y > 0);
  };
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!usable(s.x[i], s.y[i])) continue;
      x0 = std::min(x0, tx(s.x[i]));
      x1 = std::max(x1, tx(s.x[i]));
      y0 = std::min(y0, ty(s.y[i]));
      y1 = std::max(y1, ty(s.y[i]));
    }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  resolvableRange(x0, x1);
  resolvableRange(y0, y1);
  if (!log_y && y1 - y0 < min_y_span) {  // a flat curve (a phase of 0 up to round-off): a readable span around it
    const double mid = 0.5 * (y0 + y1);
    y0 = mid - 0.5 * min_y_span;
    y1 = mid + 0.5 * min_y_span;
  }
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  // A log axis ends at labelled ticks (1, 2 or 5 times a power of ten) outside the data,
  // so the lowest and highest curves lie between numbers a reader can read them by.
  auto snapOut = [](double& a0, double& a1) {
    const double lo = std::pow(10.0, a0), hi = std::pow(10.0, a1);
    const double elo = std::pow(10.0, std::floor(a0)), ehi = std::pow(10.0, std::floor(a1));
    double nlo = elo, nhi = 10 * ehi;
    for (double m : {5.0, 2.0, 1.0})
      if (m * elo <= lo * (1 + 1e-12)) { nlo = m * elo; break; }
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * ehi >= hi * (1 - 1e-12)) { nhi = m * ehi; break; }
    if (nlo > 0 && nhi > nlo && std::isfinite(nlo) && std::isfinite(nhi)) a0 = std::log10(nlo), a1 = std::log10(nhi);
  };
  if (log_y) snapOut(y0, y1);
  if (log_x) snapOut(x0, x1);
  // Points drawn as markers would be cut by the frame at the ends of the x range.
  if (std::any_of(series.begin(), series.end(), [](const Series& s) { return s.markers_only || s.x.size() < 80; })) {
    const bool labelled = std::any_of(series.begin(), series.end(), [](const Series& s) { return !s.point_labels.empty(); });
    const double xpad = (labelled ? 0.08 : 0.03) * (x1 - x0);  // room for a point's label at the right end
    x0 -= xpad;
    x1 += xpad;
  }
  auto px = [&](double x) { return left + static_cast<int>((tx(x) - x0) / (x1 - x0) * pw); };
  auto py = [&](double y) { return top + ph - static_cast<int>((ty(y) - y0) / (y1 - y0) * ph); };
  fittedText(img, title, {left + pw / 2, top - 15}, 0.6, img.cols - 10);
  std::string y_axis = y_label;  // with the ticks' power of ten, if any
  auto yTick = [&](const std::string& label, int y) {  // right-aligned against the axis
    int base = 0;
    const int w = cv::getTextSize(label, kFont, 0.42, 1, &base).width;
    text(img, label, {left - 8 - w, y + 5}, 0.42);
  };
  // Ticks: decades with 2 and 5 between (log axes), "nice" steps (linear axes).
  auto logTicks = [&](double a0, double a1, const std::function<void(double, bool)>& f) {
    const bool short_range = a1 - a0 < 3;
    const std::vector<double> mult = a1 - a0 < 1 ? std::vector<double>{1, 1.5, 2, 3, 5, 7} : std::vector<double>{1, 2, 5};
    for (int e = static_cast<int>(std::floor(a0)); e <= static_cast<int>(std::ceil(a1)); ++e)
      for (double m : mult) {
        const double v = std::log10(m) + e;
        if (v >= a0 && v <= a1) f(v, m == 1.0 || short_range);
      }
  };
  if (log_x) {
    logTicks(x0, x1, [&](double v, bool label) {
      const int x = left + static_cast<int>((v - x0) / (x1 - x0) * pw);
      cv::line(img, {x, top}, {x, top + ph}, label ? kGrey : cv::Scalar(230, 230, 230));
      if (label) text(img, fmt(std::pow(10.0, v), "%g"), {x, top + ph + 20}, 0.42, kBlack, true);
    });
  } else {
    const double sx = tickStep(x1 - x0);
    for (double x : linearTicks(x0, x1)) {
      const int xx = left + static_cast<int>((x - x0) / (x1 - x0) * pw);
      cv::line(img, {xx, top}, {xx, top + ph}, kGrey);
      text(img, fmt(x, "%g", 1e-6 * sx), {xx, top + ph + 20}, 0.42, kBlack, true);
    }
  }
  if (log_y) {
    logTicks(y0, y1, [&](double v, bool label) {
      const int y = top + ph - static_cast<int>((v - y0) / (y1 - y0) * ph);
      cv::line(img, {left, y}, {left + pw, y}, label ? kGrey : cv::Scalar(230, 230, 230));
      if (label) yTick(fmt(std::pow(10.0, v), "%g"), y);
    });
  } else {
    const double sy = tickStep(y1 - y0);
    const std::vector<double> ticks = linearTicks(y0, y1);
    // Ticks far from 1 (1e-11, 2e6) are printed as multiples of a power of ten that the
    // axis label states, so a label stays short and never runs into the axis title.
    double largest = 0;
    for (double y : ticks) largest = std::max(largest, std::abs(y));
    const int exponent = largest >= 1e5 || (largest > 0 && largest < 1e-3) ? static_cast<int>(std::floor(std::log10(largest))) : 0;
    const double unit = std::pow(10.0, exponent);
    if (exponent != 0) y_axis += " x 1e" + std::to_string(exponent);
    for (double y : ticks) {
      const int yy = top + ph - static_cast<int>((y - y0) / (y1 - y0) * ph);
      cv::line(img, {left, yy}, {left + pw, yy}, kGrey);
      yTick(fmt(y / unit, "%g", 1e-6 * sy / unit), yy);
    }
  }
  // Mode markers: a thin dotted line at each frequency inside the range, numbered above.
  int last_label_x[3] = {-1000, -1000, -1000};
  for (std::size_t k = 0; k < markers.size(); ++k) {
    const double m = markers[k];
    if (!(m > 0 || !log_x) || tx(m) < x0 || tx(m) > x1) continue;
    const int x = px(m);
    for (int y = top; y < top + ph; y += 6) cv::line(img, {x, y}, {x, std::min(y + 3, top + ph)}, cv::Scalar(160, 110, 60), 1);
    if (!marker_labels) continue;
    // Three rows of numbers; a number that would touch its row's last one moves down.
    for (int row = 0; row < 3; ++row)
      if (x - last_label_x[row] >= 16) {
        text(img, std::to_string(k + 1), {x, top + 12 + 12 * row}, 0.36, cv::Scalar(160, 110, 60), true);
        last_label_x[row] = x;
        break;
      }
  }
  cv::rectangle(img, area, kBlack, 1);
  if (!x_label.empty()) text(img, x_label, {left + pw / 2, top + ph + 45}, 0.5, kBlack, true);
  {
    cv::Mat strip(30, ph, CV_8UC3, kWhite);
    cv::putText(strip, y_axis, {ph / 2 - textBox(y_axis, {0, 0}, 0.5).width / 2, 20}, kFont, 0.5, kBlack, 1, cv::LINE_AA);
    cv::Mat rotated;
    cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
    rotated.copyTo(img(cv::Rect(5, top, rotated.cols, rotated.rows)));
    layoutRotatedText(y_axis, 5, top, ph, 0.5);
  }
  std::vector<cv::Scalar> colours;
  std::vector<cv::Mat> masks;
  std::vector<cv::Rect> placed;  // the point labels drawn so far
  // Series without a colour of their own take the palette's entries the others have not
  // claimed (a mode's fixed colour, a limit's black), in order.
  std::vector<int> free_entries;
  for (int e = 0; e < kPaletteSize; ++e)
    if (std::none_of(series.begin(), series.end(), [&](const Series& s) { return s.colour_index >= 0 && s.colour_index % kPaletteSize == e; }))
      free_entries.push_back(e);
  const std::size_t automatic = std::count_if(series.begin(), series.end(), [](const Series& s) { return s.colour_index < 0; });
  std::size_t next_auto = 0;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const auto& s = series[k];
    // Up to 14 series: the qualitative palette (Okabe-Ito's colour-blind-safe colours
    // first, then Tol's), so neighbouring series stay distinguishable; more: the
    // sequential map.
    static const cv::Scalar kQualitative[kPaletteSize] = {  // BGR
        {0, 0, 0},       {0, 159, 230},  {233, 180, 86}, {115, 158, 0},  {178, 114, 0},  {0, 94, 213},  {167, 121, 204},
        {136, 34, 51},   {238, 204, 136}, {153, 170, 68}, {51, 153, 153}, {85, 34, 136},  {153, 68, 170}, {119, 119, 119}};
    // A series with a colour index keeps its colour from figure to figure (an
    // integrator is the same colour in every trade plot).
    if (s.colour_index >= 0) colours.push_back(kQualitative[s.colour_index % kPaletteSize]);
    else if (automatic <= free_entries.size()) colours.push_back(kQualitative[free_entries[next_auto++]]);
    else colours.push_back(colourFor(0.85 * double(next_auto++) / std::max<std::size_t>(1, automatic - 1)));
    const cv::Scalar& colour = colours.back();
    drawSeriesLine(img, s, colour, px, py, usable, 2, cv::LINE_AA);
    // Where this series drew (its line's core and markers), to tell later what of it shows.
    masks.emplace_back(img.size(), CV_8UC1, cv::Scalar(0));
    drawSeriesLine(masks.back(), s, cv::Scalar(255), px, py, usable, 2, cv::LINE_8);
    // A dashed line (a limit) has no markers, unless it is one point: a line of one point
    // draws nothing, and its legend entry would name an invisible series.
    std::size_t usable_points = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) usable_points += usable(s.x[i], s.y[i]) ? 1 : 0;
    if ((s.x.size() < 80 && !s.dashed) || s.markers_only || usable_points == 1)
      for (std::size_t i = 0; i < s.x.size(); ++i)
        if (usable(s.x[i], s.y[i])) {
          const cv::Point at(px(s.x[i]), py(s.y[i]));
          if (s.hollow) cv::circle(img, at, 6, colour, 2, cv::LINE_AA);
          else cv::circle(img, at, s.markers_only ? 5 : 3, colour, cv::FILLED, cv::LINE_AA);
          cv::circle(masks.back(), at, s.hollow ? 6 : s.markers_only ? 5 : 3, cv::Scalar(255), s.hollow ? 2 : cv::FILLED, cv::LINE_8);
          if (i < s.point_labels.size() && !s.point_labels[i].empty()) placePointLabel(img, s.point_labels[i], at, colour, area, placed);
        }
  }
  // A line drawn over by later ones (within a pixel of them all along) is drawn again on
  // top, one pixel wide, so that both show: the legend never names an invisible series.
  const cv::Rect inner(left + 2, top + 2, std::max(1, pw - 4), std::max(1, ph - 4));
  // Of the pixels series k drew, those still in its colour (a twin in the same colour,
  // a joint's capacity, does not count for it).
  auto shown = [&](std::size_t k) {
    cv::Mat same;
    cv::inRange(img(inner), colours[k], colours[k], same);
    return cv::countNonZero(same & masks[k](inner));
  };
  std::vector<std::size_t> redrawn;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    if (s.label.empty() || shown(k) >= kMinShownPixels) continue;
    if (!s.markers_only) drawSeriesLine(img, s, colours[k], px, py, usable, 1, cv::LINE_8);
    else redrawMarkers(img, masks[k], s, colours[k], px, py, usable, [&] {
        int fewest = shown(k);
        for (std::size_t j : redrawn) fewest = std::min(fewest, shown(j));
        return fewest;
      });
    redrawn.push_back(k);
  }
  // The legend: one entry per labelled series (a capacity's mirror line has none), its
  // line dashed or a marker as the series is drawn; rows closer together when many.
  int labelled = 0;
  for (const auto& s : series) labelled += s.label.empty() ? 0 : 1;
  const int row_h = std::clamp(labelled > 0 ? (ph - 10) / labelled : 22, 14, 22);
  int legend_row = 0;
  for (std::size_t k = 0; k < series.size() && legend; ++k) {
    const auto& s = series[k];
    const cv::Scalar& colour = colours[k];
    if (s.label.empty()) continue;
    const int ly = top + 10 + row_h * legend_row++;
    const bool room = ly < top + ph;
    if (layoutLogging())
      layoutLegend(s.label, colour, s.markers_only ? (s.hollow ? "rings" : "markers") : s.dashed ? "dashed" : "solid",
                   room ? shown(k) : -1);
    if (!room) continue;
    if (s.markers_only) cv::circle(img, {left + pw + 27, ly - 4}, s.hollow ? 5 : 4, colour, s.hollow ? 2 : cv::FILLED, cv::LINE_AA);
    else if (s.dashed)
      for (int x = left + pw + 15; x < left + pw + 40; x += 10) cv::line(img, {x, ly - 4}, {std::min(x + 6, left + pw + 40), ly - 4}, colour, 2);
    else cv::line(img, {left + pw + 15, ly - 4}, {left + pw + 40, ly - 4}, colour, 2);
    double scale = 0.42;  // a long entry (series merged by mergeCoincident) is smaller, never cut at the edge
    for (int base = 0; scale > 0.28 && cv::getTextSize(s.label, kFont, scale, 1, &base).width > img.cols - (left + pw + 46) - 4;)
      scale *= 0.93;
    text(img, s.label, {left + pw + 46, ly}, scale);
  }
  if (legend && !no_data.empty()) {
    const int ly = std::min(top + ph, top + 10 + row_h * legend_row + 6);
    double scale = 0.38;
    for (int base = 0; scale > 0.26 && cv::getTextSize(no_data, kFont, scale, 1, &base).width > img.cols - (left + pw + 15) - 4;)
      scale *= 0.93;
    text(img, no_data, {left + pw + 15, ly}, scale, cv::Scalar(90, 90, 90));
  }
}

}  // namespace

void writeLinePlotPng(const std::string& path, const std::vector<Series>& series, const std::string& title,
                      const std::string& x_label, const std::string& y_label, bool log_y, bool log_x) {
  // The legend's column is as wide as its longest label (up to 600 px); the plot keeps its size.
  int legend_w = 0;
  for (const auto& s : mergeCoincident(series)) {  // the labels the legend shows
    int base = 0;
    legend_w = std::max(legend_w, cv::getTextSize(s.label, kFont, 0.42, 1, &base).width);
  }
  const int right = std::clamp(legend_w + 70, 200, 600), width = 90 + 610 + right;
  cv::Mat img(600, width, CV_8UC3, kWhite);
  layoutNewImage(width, 600, "plot");
  drawPanel(img, cv::Rect(90, 50, 610, 600 - 50 - 70), series, title, x_label, y_label, log_x, log_y, true);
  save(path, img);
}

std::vector<double> unwrapPhaseDeg(std::vector<double> phase) {
  double shift = 0;
  for (std::size_t k = 1; k < phase.size(); ++k) {
    const double raw = phase[k] + shift, step = raw - phase[k - 1];
    shift -= 360.0 * std::round(step / 360.0);
    phase[k] += shift;
  }
  // The unwrapped curve starts in (-180, 180]: its first point as measured.
  return phase;
}

void writeBodePng(const std::string& path, const std::vector<BodeTrace>& traces, const std::string& title,
                  const std::string& x_label, const std::vector<double>& markers) {
  std::vector<Series> mag, phase;
  for (const auto& t : traces) {
    mag.push_back({t.label, t.frequency, t.magnitude_db, t.dashed});
    phase.push_back({t.label, t.frequency, unwrapPhaseDeg(t.phase_deg), t.dashed});
  }
  const int width = 1000, height = 800, left = 90, right = 260;
  cv::Mat img(height, width, CV_8UC3, kWhite);
  layoutNewImage(width, height, "bode");
  drawPanel(img, cv::Rect(left, 50, width - left - right, 400), mag, title, "", "magnitude (dB)", true, false, true,
            markers, true);
  drawPanel(img, cv::Rect(left, 490, width - left - right, 230), phase, "", x_label, "phase (deg, unwrapped)", true, false,
            false, markers, false, 10.0);
  if (!markers.empty()) text(img, "dotted: model modes 1, 2, ...", {width - right + 15, 50 + 22 * static_cast<int>(traces.size()) + 20}, 0.4);
  save(path, img);
}

// Declared in plot.hpp: each pixel column's run of points kept as its first, lowest,
// highest and last; consecutive breaks collapse into one.
std::vector<std::optional<Pixel>> columnEnvelope(const std::vector<std::optional<Pixel>>& pts) {
  std::vector<std::optional<Pixel>> out;
  std::size_t i = 0;
  while (i < pts.size()) {
    if (!pts[i]) {  // a break (several in a row are one)
      if (!out.empty() && out.back()) out.push_back(std::nullopt);
      ++i;
      continue;
    }
    std::size_t j = i, lo = i, hi = i;
    for (; j < pts.size() && pts[j] && pts[j]->x == pts[i]->x; ++j) {
      if (pts[j]->y < pts[lo]->y) lo = j;
      if (pts[j]->y > pts[hi]->y) hi = j;
    }
    for (std::size_t k : {i, std::min(lo, hi), std::max(lo, hi), j - 1})
      if (out.empty() || !out.back() || !(*out.back() == *pts[k])) out.push_back(pts[k]);
    i = j;
  }
  return out;
}

}  // namespace mmv::render
