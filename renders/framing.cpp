// Framing a preset camera into the part of the picture the annotations leave free: the
// title band, the legend (top left), the colour bar (right) and the scale bar (bottom).
// A thin article in a wide frame used to sit in the middle of a sphere's worth of white
// under the legend's text (issue 36: article.png was about 70 % white).
#include <opencv2/imgproc.hpp>

#include <algorithm>

#include "renders/frame.hpp"
#include "renders/label_space.hpp"

namespace mmv::render {

cv::Rect legendArea(const DrawList& list) {
  if (list.legend.empty()) return {};
  int widest = 0;
  for (const auto& entry : list.legend) {
    int base = 0;
    widest = std::max(widest, cv::getTextSize(entry.first, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &base).width);
  }
  return {0, kTitleBand, 32 + widest + 4, kLegendFirstRow + kLegendRow * static_cast<int>(list.legend.size()) - kTitleBand};
}

Camera framedCamera(const Camera& camera, const DrawList& list, int width, int height) {
  if (camera.fit_preset.empty() || camera.fit_bounds.isEmpty() || width < 1 || height < 1) return camera;
  const int right = width - (list.has_color_bar ? kColorBarReserve : 0);
  const int top = kTitleBand, bottom = height - kScaleBarReserve;
  const cv::Rect legend = legendArea(list);
  // Pixel rectangles the drawing may fill: beside the legend, or under it.
  std::vector<cv::Rect> windows;
  if (legend.area() == 0) windows.emplace_back(0, top, right, bottom - top);
  else {
    windows.emplace_back(legend.br().x + 8, top, right - legend.br().x - 8, bottom - top);
    windows.emplace_back(0, legend.br().y + 8, right, bottom - legend.br().y - 8);
  }
  Camera best = camera;
  double nearest = -1;
  for (const cv::Rect& w : windows) {
    if (w.width < width / 5 || w.height < height / 5) continue;  // too small a corner to draw in
    ViewWindow v;
    v.aspect = static_cast<double>(width) / height;
    v.x0 = 2.0 * w.x / width - 1;
    v.x1 = 2.0 * (w.x + w.width) / width - 1;
    v.y0 = 1 - 2.0 * (w.y + w.height) / height;
    v.y1 = 1 - 2.0 * w.y / height;
    Camera c = camera;
    if (!presetCamera(camera.fit_preset, camera.fit_bounds, c, camera.fit_up, v)) return camera;
    const double distance = (c.eye - c.target).norm();
    if (nearest < 0 || distance < nearest) nearest = distance, best = c;
  }
  if (nearest < 0) {  // a frame too small for both: the whole picture
    ViewWindow v;
    v.aspect = static_cast<double>(width) / height;
    presetCamera(camera.fit_preset, camera.fit_bounds, best, camera.fit_up, v);
  }
  return best;
}

}  // namespace mmv::render

namespace mmv::render {

LabelSpace::LabelSpace(cv::Size f, const cv::Mat& ink) : frame(f) {
  if (ink.empty()) return;
  cv::Mat marked;
  cv::threshold(ink, marked, 0, 1, cv::THRESH_BINARY);
  cv::integral(marked, integral_, CV_32S);
}

long LabelSpace::inkIn(const cv::Rect& r) const {
  if (integral_.empty()) return 0;
  const cv::Rect c = r & cv::Rect(0, 0, frame.width, frame.height);
  if (c.area() == 0) return 0;
  const auto at = [&](int y, int x) { return static_cast<long>(integral_.at<int>(y, x)); };
  return at(c.y + c.height, c.x + c.width) - at(c.y, c.x + c.width) - at(c.y + c.height, c.x) + at(c.y, c.x);
}

cv::Point placeLabel(const std::string& text, const cv::Point2d& p, LabelSpace& space) {
  constexpr int kGap = 4;  // px between two labels: "gyro_link1_tip (rate_gyro)enc2" read as one
  int base = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.42, 1, &base);
  const int step = size.height + base + 2;
  auto boxAt = [&](cv::Point o) { return cv::Rect(o.x, o.y - size.height - 1, size.width, step); };
  auto clear = [&](const cv::Rect& r) {
    const cv::Rect padded(r.x - kGap, r.y - kGap, r.width + 2 * kGap, r.height + 2 * kGap);
    for (const auto& t : space.taken)
      if ((padded & t).area() > 0) return false;
    return true;
  };
  const cv::Point right(static_cast<int>(p.x) + 6, static_cast<int>(p.y) - 6), left(static_cast<int>(p.x) - 6 - size.width, right.y);
  // Nowhere free: beside its point, moved inside the frame.
  cv::Point chosen(std::clamp(right.x, 0, std::max(0, space.frame.width - size.width)),
                   std::clamp(right.y, size.height + 1, std::max(size.height + 1, space.frame.height - base)));
  // A place's cost: the pixels of its box that differ from the box's majority (text on
  // white or wholly on a body's fill reads; a link's line through it does not), and
  // some for every line it moves from its point.
  long least = -1;
  for (int k = 0; k < 24 && least != 0; ++k)
    for (const cv::Point& side : {right, left}) {
      const int shift = (k % 2 == 0 ? 1 : -1) * ((k + 1) / 2) * step;  // 0, -1, +1, -2, ... lines
      const cv::Point o(side.x, side.y + shift);
      const cv::Rect box = boxAt(o);
      if (o.y - size.height < 0 || o.y + base > space.frame.height || o.x < 0 || o.x + size.width > space.frame.width || !clear(box))
        continue;
      const long ink = space.inkIn(box);
      // At most 60 (a link's line through the box costs about 30): a label on the edge
      // of a body moves no more than five lines from its point for it.
      const long cost = std::min<long>({ink, box.area() - ink, 60L}) + 12L * ((k + 1) / 2);
      if (least < 0 || cost < least) least = cost, chosen = o;
    }
  space.taken.push_back(boxAt(chosen));
  return chosen;
}

}  // namespace mmv::render
