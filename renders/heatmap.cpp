// The heatmap figures (AutoMAC, orthogonality): a labelled matrix of colours
// (renders/plot.hpp, writeHeatmapPng).
#include "renders/plot.hpp"
#include "renders/plot_helpers.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace mmv::render {

using namespace plot_detail;

void writeHeatmapPng(const std::string& path, const Eigen::MatrixXd& values, const std::vector<std::string>& row_labels,
                     const std::vector<std::string>& col_labels, const std::string& title, const std::string& row_axis,
                     const std::string& col_axis, double vmin, double vmax) {
  const int rows = static_cast<int>(values.rows()), cols = static_cast<int>(values.cols());
  int label_w = 0;
  for (const auto& l : row_labels) {
    int base = 0;
    label_w = std::max(label_w, cv::getTextSize(l, kFont, 0.42, 1, &base).width);
  }
  const int cell = 56, left = 50 + label_w, top = 70, bar = 90;
  const int width = left + cols * cell + bar + 30, height = top + rows * cell + 95;
  cv::Mat img(height, width, CV_8UC3, kWhite);
  layoutNewImage(width, height, "heatmap");
  fittedText(img, title, {width / 2, 30}, 0.6, width - 10);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double v = values(i, j), t = (v - vmin) / (vmax - vmin);
      const cv::Rect r(left + j * cell, top + i * cell, cell, cell);
      if (!std::isfinite(v)) {  // undefined (a MAC with a zero shape): grey, labelled so
        cv::rectangle(img, r, cv::Scalar(200, 200, 200), cv::FILLED);
        cv::rectangle(img, r, kWhite, 1);
        text(img, "n/a", {r.x + cell / 2, r.y + cell / 2 + 5}, 0.38, kBlack, true);
        continue;
      }
      cv::rectangle(img, r, colourFor(t), cv::FILLED);
      cv::rectangle(img, r, kWhite, 1);
      // Three significant figures at most, the text shrunk to fit its cell (-123.4 dB fits).
      const std::string label = std::abs(v) >= 100 ? fmt(v, "%.0f") : std::abs(v) >= 10 ? fmt(v, "%.1f") : fmt(v, "%.2f");
      double scale = 0.42;
      for (int base = 0; scale > 0.25 && cv::getTextSize(label, kFont, scale, 1, &base).width > cell - 6;) scale *= 0.9;
      text(img, label, {r.x + cell / 2, r.y + cell / 2 + 5}, scale, t > 0.6 ? kBlack : kWhite, true);
    }
  for (int i = 0; i < rows && i < static_cast<int>(row_labels.size()); ++i) {
    int base = 0;
    const int w = cv::getTextSize(row_labels[i], kFont, 0.42, 1, &base).width;
    text(img, row_labels[i], {left - 8 - w, top + i * cell + cell / 2 + 5}, 0.42);
  }
  // A column label "M3 4.12 Hz" on two lines ("M3" over "4.12 Hz") to fit its cell.
  for (int j = 0; j < cols && j < static_cast<int>(col_labels.size()); ++j) {
    const std::string& l = col_labels[j];
    const auto sp = l.find(' ');
    // Each line shrunk to its cell's width, so neighbouring columns' labels never touch.
    auto fitted = [&](const std::string& t, double scale) {
      for (int base = 0; scale > 0.25 && cv::getTextSize(t, kFont, scale, 1, &base).width > cell - 4;) scale *= 0.92;
      return scale;
    };
    const std::string first = l.substr(0, sp);
    text(img, first, {left + j * cell + cell / 2, top + rows * cell + 20}, fitted(first, 0.42), kBlack, true);
    if (sp != std::string::npos) {
      const std::string second = l.substr(sp + 1);
      text(img, second, {left + j * cell + cell / 2, top + rows * cell + 38}, fitted(second, 0.36), kBlack, true);
    }
  }
  text(img, col_axis, {left + cols * cell / 2, top + rows * cell + 62}, 0.5, kBlack, true);
  // The row axis label, written vertically by rotating a strip.
  {
    cv::Mat strip(30, std::max(rows * cell, 40), CV_8UC3, kWhite);
    cv::putText(strip, row_axis, {strip.cols / 2 - textBox(row_axis, {0, 0}, 0.5).width / 2, 20}, kFont, 0.5, kBlack, 1, cv::LINE_AA);
    cv::Mat rotated;
    cv::rotate(strip, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
    const int h = std::min(rotated.rows, height - top);
    rotated(cv::Rect(0, 0, rotated.cols, h)).copyTo(img(cv::Rect(8, top, rotated.cols, h)));
    layoutRotatedText(row_axis, 8, top, strip.cols, 0.5);
  }
  // Colour bar.
  const int bx = left + cols * cell + 30, bh = std::max(rows * cell, 100);
  for (int y = 0; y < bh; ++y) cv::line(img, {bx, top + y}, {bx + 20, top + y}, colourFor(1.0 - double(y) / bh));
  cv::rectangle(img, cv::Rect(bx, top, 20, bh), kBlack, 1);
  text(img, fmt(vmax, "%.3g"), {bx + 26, top + 10}, 0.42);
  text(img, fmt(vmin, "%.3g"), {bx + 26, top + bh}, 0.42);
  save(path, img);
}

}  // namespace mmv::render
