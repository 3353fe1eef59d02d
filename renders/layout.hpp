#pragma once
/// What a figure drew where, for the figure harness (tests/figures/figure_layout.sh): each
/// text's box on the canvas and each legend entry with how many pixels of its series are
/// still in its colour when the figure is written. Off unless setLayoutLog names a file
/// (the figures plugin does when MMVLAB_FIGURE_LAYOUT is set); then every PNG written
/// appends one JSON line to it: {"file", "width", "height", "kind", "texts": [[text, x,
/// y, w, h]], "legend": [[label, b, g, r, style, pixels]]} (pixels -1: the entry was not drawn).

#include <string>

#include <opencv2/core.hpp>

namespace mmv::render {

void setLayoutLog(const std::string& path);
bool layoutLogging();

/// A new image of this size starts (a frame, a plot); `kind` names it in the log.
void layoutNewImage(int width, int height, const char* kind);
void layoutText(const std::string& text, const cv::Rect& box);
/// A legend entry: its series' colour and style ("solid", "dashed", "markers", "rings") and how many
/// pixels of that colour it shows (-1: no room for the entry).
void layoutLegend(const std::string& label, const cv::Scalar& colour, const char* style, long pixels);
/// The last `tiles` images became one contact sheet, `columns` wide (renders/frame.hpp).
void layoutArrangeSheet(std::size_t tiles, int columns);
/// The last `images` images became one, side by side left to right (a frame and its
/// trace panel).
void layoutArrangeRow(std::size_t images);
/// The image is written as `path`: its layout appended to the log, and forgotten.
void layoutFlush(const std::string& path);

/// cv::putText in Hershey simplex, its box recorded: every figure's text goes through it.
void putTextLogged(cv::Mat& img, const std::string& text, cv::Point origin, double scale, const cv::Scalar& colour,
                   int thickness = 1);
/// The box putTextLogged records for `text` at `origin` (baseline's left end).
cv::Rect textBox(const std::string& text, cv::Point origin, double scale, int thickness = 1);

}  // namespace mmv::render
