#include "renders/summary.hpp"

#include <algorithm>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "renders/frame.hpp"
#include "renders/png.hpp"
#include "renders/plot_helpers.hpp"

namespace mmv::render {
namespace {

using plot_detail::kFont;

constexpr int kPageWidth = 2400, kPageMargin = 30, kPageLeft = 1440, kPageTitleBand = 80;
constexpr double kPageLineScale = 0.75, kPageTitleScale = 1.2;

cv::Mat readImage(const std::string& path) {
  try {
    return readPng(path);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + ": cannot read the figure back for the summary");
  }
}

/// `m` scaled to at most `width` pixels wide (never enlarged).
cv::Mat toWidth(const cv::Mat& m, int width) {
  if (m.cols <= width) return m;
  cv::Mat out;
  cv::resize(m, out, cv::Size(width, std::max(1, m.rows * width / m.cols)), 0, 0, cv::INTER_AREA);
  return out;
}

/// `line` broken at spaces into pieces no wider than `width` pixels at kPageLineScale.
std::vector<std::string> wrap(const std::string& line, int width) {
  std::vector<std::string> out;
  std::string current;
  std::size_t at = 0;
  int base = 0;
  while (at <= line.size()) {
    std::size_t end = line.find(' ', at);
    if (end == std::string::npos) end = line.size();
    const std::string word = line.substr(at, end - at);
    const std::string tried = current.empty() ? word : current + " " + word;
    if (!current.empty() && cv::getTextSize(tried, kFont, kPageLineScale, 1, &base).width > width) {
      out.push_back(current);
      current = "  " + word;  // a continuation, indented
    } else {
      current = tried;
    }
    at = end + 1;
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

void paste(cv::Mat& canvas, const cv::Mat& img, int x, int y) { img.copyTo(canvas(cv::Rect(x, y, img.cols, img.rows))); }

}  // namespace

void writeSummaryPng(const std::string& path, const std::string& title, const std::vector<std::string>& images,
                     const std::vector<std::string>& lines) {
  if (images.empty()) throw std::runtime_error(path + ": a summary needs a figure");
  const int right_x = kPageMargin + kPageLeft + kPageMargin, right_w = kPageWidth - right_x - kPageMargin;
  const cv::Mat main = toWidth(readImage(images[0]), kPageLeft);
  const cv::Mat side = images.size() > 1 ? toWidth(readImage(images[1]), right_w) : cv::Mat();
  const cv::Mat under = images.size() > 2 ? toWidth(readImage(images[2]), kPageLeft) : cv::Mat();
  std::vector<std::string> wrapped;
  for (const auto& l : lines)
    for (auto& piece : wrap(l, right_w)) wrapped.push_back(std::move(piece));
  const int line_h = 34;
  const int left_h = main.rows + (under.empty() ? 0 : kPageMargin + under.rows);
  const int right_h = (side.empty() ? 0 : side.rows + kPageMargin) + static_cast<int>(wrapped.size()) * line_h;
  const int height = kPageTitleBand + std::max(left_h, right_h) + kPageMargin;
  layoutNewImage(kPageWidth, height, "summary");
  cv::Mat canvas(height, kPageWidth, CV_8UC3, plot_detail::kWhite);
  plot_detail::fittedText(canvas, title, {kPageWidth / 2, kPageTitleBand / 2 + 12}, kPageTitleScale, kPageWidth - 2 * kPageMargin);
  int y = kPageTitleBand;
  paste(canvas, main, kPageMargin, y);
  if (!under.empty()) paste(canvas, under, kPageMargin, y + main.rows + kPageMargin);
  int ry = y;
  if (!side.empty()) paste(canvas, side, right_x, ry), ry += side.rows + kPageMargin;
  for (const auto& l : wrapped) {
    ry += line_h;
    plot_detail::text(canvas, l, {right_x, ry - 10}, kPageLineScale, l.rfind("warning", 0) == 0 || l.find("FAIL") != std::string::npos
                                                                     ? cv::Scalar(0, 0, 200)
                                                                     : plot_detail::kBlack);
  }
  writePng(path, canvas);
}

}  // namespace mmv::render
