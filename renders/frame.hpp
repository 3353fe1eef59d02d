#pragma once
/// Off-screen 3-D frames: a drawing list (sim/core/drawing.hpp) drawn with OpenGL in an
/// OSMesa context (software, no display, no window), shaded by two directional lights
/// with a depth buffer, anti-aliased by supersampling (rendered at k times the size
/// and reduced by area averaging), then annotated in 2-D with OpenCV: the title, the
/// labels at their projected points, the legend, a scale bar and the colour bar.
/// Deterministic: the same list, camera and size give the same pixels.

#include <opencv2/core.hpp>

#include <string>
#include <vector>

#include "sim/core/drawing.hpp"

namespace mmv::render {

struct FrameOptions {
  int width = 1280, height = 720;  ///< pixels.
  int supersample = 3;             ///< render at this multiple of the size (anti-aliasing).
};

/// Draws `list` as `camera` sees it; returns a BGR image (CV_8UC3). Throws
/// std::runtime_error if OSMesa cannot create a context.
cv::Mat renderFrame(const DrawList& list, const Camera& camera, const FrameOptions& options);

/// The pixel (x right, y down, from the top-left corner) where world point `p` lands in
/// a frame of width x height from `camera`; false when it is behind the camera.
bool projectPoint(const Camera& camera, int width, int height, const Eigen::Vector3d& p, cv::Point2d& pixel);

/// Tiles images (all of one size) `columns` wide, white where a row is short.
cv::Mat contactSheet(const std::vector<cv::Mat>& tiles, int columns);

/// Writes a PNG; throws std::runtime_error when it cannot.
void writePng(const std::string& path, const cv::Mat& image);

/// Writes frames as a video: .mp4 (MPEG-4 part 2) or .avi (Motion JPEG), at `fps`.
/// Throws std::runtime_error for another extension or when the encoder cannot open.
void writeVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps);

}  // namespace mmv::render
