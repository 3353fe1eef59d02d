#pragma once
// Where a frame's labels go (renders/ only): clear of each other, of the title, legend,
// scale and colour bars, inside the picture, and off the drawn article where a place is.

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mmv::render {

class LabelSpace {
 public:
  /// `ink`: the frame's mask of the article's pixels (non-zero), or empty.
  LabelSpace(cv::Size frame, const cv::Mat& ink);
  /// Article pixels inside `r` (clipped to the frame).
  long inkIn(const cv::Rect& r) const;
  cv::Size frame;
  std::vector<cv::Rect> taken;  ///< boxes no label may overlap (with a gap)

 private:
  cv::Mat integral_;  ///< of the ink mask (0/1), CV_32S; empty without one
};

/// Where a label's text goes (its baseline's left end): beside its point, or the first
/// place stepping down, then up, then to the left, that keeps a gap from every box
/// taken, preferring places on a uniform background (white, or wholly on a body) near
/// the point (renders/framing.cpp says how much); failing every place, beside its
/// point, inside the frame. Takes its box.
cv::Point placeLabel(const std::string& text, const cv::Point2d& p, LabelSpace& space);

}  // namespace mmv::render
