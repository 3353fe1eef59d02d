#include "renders/layout.hpp"

#include <algorithm>
#include <fstream>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <nlohmann/json.hpp>

namespace mmv::render {
namespace {

struct Image {
  int width = 0, height = 0;
  std::string kind;
  nlohmann::json texts = nlohmann::json::array(), legend = nlohmann::json::array();
};

std::string& logPath() {
  static std::string path;
  return path;
}

/// The images drawn on this thread since the last one was written.
thread_local std::vector<Image> t_images;

}  // namespace

void setLayoutLog(const std::string& path) { logPath() = path; }
bool layoutLogging() { return !logPath().empty(); }

void layoutNewImage(int width, int height, const char* kind) {
  if (!layoutLogging()) return;
  t_images.push_back({width, height, kind, nlohmann::json::array(), nlohmann::json::array()});
}

void layoutText(const std::string& text, const cv::Rect& box) {
  if (!layoutLogging() || t_images.empty()) return;
  t_images.back().texts.push_back({text, box.x, box.y, box.width, box.height});
}

void layoutLegend(const std::string& label, const cv::Scalar& colour, const char* style, long pixels) {
  if (!layoutLogging() || t_images.empty()) return;
  t_images.back().legend.push_back({label, static_cast<int>(colour[0]), static_cast<int>(colour[1]),
                                    static_cast<int>(colour[2]), style, pixels});
}

void layoutArrangeSheet(std::size_t tiles, int columns) {
  if (!layoutLogging() || tiles == 0 || t_images.size() < tiles || columns < 1) return;
  Image sheet;
  const std::size_t first = t_images.size() - tiles;
  const int w = t_images[first].width, h = t_images[first].height;
  sheet.kind = "sheet";
  sheet.width = columns * w;
  sheet.height = static_cast<int>((tiles + columns - 1) / columns) * h;
  for (std::size_t i = 0; i < tiles; ++i) {
    const int dx = static_cast<int>(i) % columns * w, dy = static_cast<int>(i) / columns * h;
    for (auto t : t_images[first + i].texts) {
      t[1] = t[1].get<int>() + dx;
      t[2] = t[2].get<int>() + dy;
      sheet.texts.push_back(t);
    }
  }
  t_images.resize(first);
  t_images.push_back(std::move(sheet));
}

void layoutArrangeRow(std::size_t images) {
  if (!layoutLogging() || images == 0 || t_images.size() < images) return;
  Image row;
  row.kind = "row";
  const std::size_t first = t_images.size() - images;
  for (std::size_t i = first; i < t_images.size(); ++i) {
    for (auto t : t_images[i].texts) {
      t[1] = t[1].get<int>() + row.width;
      row.texts.push_back(t);
    }
    row.width += t_images[i].width;
    row.height = std::max(row.height, t_images[i].height);
  }
  t_images.resize(first);
  t_images.push_back(std::move(row));
}

void layoutFlush(const std::string& path) {
  if (!layoutLogging()) return;
  if (!t_images.empty()) {
    const Image& im = t_images.back();
    const auto slash = path.find_last_of('/');
    std::ofstream(logPath(), std::ios::app)
        << nlohmann::json{{"file", slash == std::string::npos ? path : path.substr(slash + 1)},
                          {"width", im.width}, {"height", im.height}, {"kind", im.kind},
                          {"texts", im.texts}, {"legend", im.legend}}.dump()
        << '\n';
  }
  t_images.clear();
}

cv::Rect textBox(const std::string& text, cv::Point origin, double scale, int thickness) {
  int base = 0;
  const cv::Size s = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &base);
  return {origin.x, origin.y - s.height, s.width, s.height + base};
}

void putTextLogged(cv::Mat& img, const std::string& text, cv::Point origin, double scale, const cv::Scalar& colour,
                   int thickness) {
  cv::putText(img, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness, cv::LINE_AA);
  if (!text.empty()) layoutText(text, textBox(text, origin, scale, thickness));
}

}  // namespace mmv::render
