#pragma once
/// Off-screen 3-D frames: a drawing list (sim/core/drawing.hpp) drawn with OpenGL in an
/// OSMesa context (software, no display, no window), shaded by two directional lights
/// with a depth buffer, anti-aliased by supersampling (rendered at k times the size
/// and reduced by area averaging), then annotated in 2-D with OpenCV: the title, the
/// labels at their projected points, the legend, a scale bar and the colour bar.
/// Deterministic: the same list, camera and size give the same pixels.

#include <opencv2/core.hpp>

#include <memory>

#include <string>
#include <vector>

#include "sim/core/drawing.hpp"

namespace mmv::render {

struct VideoApi;

struct FrameOptions {
  int width = 1280, height = 720;  ///< pixels.
  int supersample = 3;             ///< render at this multiple of the size (anti-aliasing).
};

/// The largest side of the buffer OSMesa draws into (the frame times its supersampling):
/// a larger frame is supersampled less (8192 x 8192 not at all), so every size up to
/// the documented 8192 draws into at most 8192 x 8192 samples (docs/reliability.md).
constexpr int kMaxBufferSide = 8192;
/// The supersampling a frame gets: `options.supersample`, lowered to fit kMaxBufferSide.
int effectiveSupersample(const FrameOptions& options);
/// Throws std::runtime_error naming the GB needed and available when a frame drawn at
/// w x h samples (width x height pixels) would not fit in MemAvailable (frame_memory.cpp).
void checkFrameMemory(int w, int h, int width, int height);

/// Draws `list` as `camera` sees it; returns a BGR image (CV_8UC3). Throws
/// std::runtime_error if OSMesa cannot create a context, or before allocating anything
/// when the machine has less memory available than the frame needs (named).
cv::Mat renderFrame(const DrawList& list, const Camera& camera, const FrameOptions& options);

/// The frame's annotation layout (pixels): the title's band at the top, the legend's
/// rows (a swatch and a name each) from its first baseline, what the colour bar takes
/// at the right and the scale bar at the bottom.
constexpr int kTitleBand = 34, kLegendFirstRow = 50, kLegendRow = 18, kColorBarReserve = 84, kScaleBarReserve = 48;
/// The box the legend of `list` takes (empty without a legend).
cv::Rect legendArea(const DrawList& list);
/// The camera renderFrame draws with: a preset camera (Camera::fit_preset) framed again
/// so that what it frames fills the part of a width x height picture the legend, the
/// title, the colour bar and the scale bar leave free (beside the legend or under it,
/// whichever draws it larger); any other camera as it is. Project points with this one.
Camera framedCamera(const Camera& camera, const DrawList& list, int width, int height);

/// The pixel (x right, y down, from the top-left corner) where world point `p` lands in
/// a frame of width x height from `camera`; false when it is behind the camera.
bool projectPoint(const Camera& camera, int width, int height, const Eigen::Vector3d& p, cv::Point2d& pixel);

/// Tiles images (all of one size) `columns` wide, white where a row is short.
cv::Mat contactSheet(const std::vector<cv::Mat>& tiles, int columns);

/// Writes a PNG; throws std::runtime_error when it cannot.
/// Encodes `image` as PNG and writes it, every write checked (OutputError on a full disk).
void writePng(const std::string& path, const cv::Mat& image);

/// A video written frame by frame (a long run's frames are never all in memory):
/// .mp4 (MPEG-4 part 2) or .avi (Motion JPEG), at `fps`, every frame of `size`.
/// Throws std::runtime_error for another extension, when the encoder cannot open, or
/// for a frame of another size.
class VideoSink {
 public:
  VideoSink(const std::string& path, double fps, cv::Size size);
  ~VideoSink();  ///< closes the file (unchecked: call close() on success)
  /// Closes the file and reads it back: a video that did not write whole (a full disk)
  /// is a std::runtime_error.
  void close();
  VideoSink(const VideoSink&) = delete;
  VideoSink& operator=(const VideoSink&) = delete;
  void write(const cv::Mat& frame);
  int frames() const { return frames_; }

 private:
  std::string path_;
  cv::Size size_;
  int frames_ = 0;
  const VideoApi* api_ = nullptr;         ///< the video plugin's (renders/video_api.hpp)
  void* writer_ = nullptr;                ///< its encoder, open until close()
};

/// Writes frames as a video (VideoSink).
void writeVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps);

/// A signal over time, for an inset.
struct Trace {
  std::string name;  ///< with its unit, e.g. "acc_link2_tip (m/s^2)".
  std::vector<double> t, v;
  double limit = 0;         ///< > 0: +-limit in the trace's unit (a sensor's range, a torquer's capacity)
  std::string limit_label;  ///< what the limit is ("range", "capacity")
};

/// A panel of `size` showing `traces`, one strip each: the whole history in grey (each
/// pixel column spans its samples' least and greatest, so no peak is lost), the part up
/// to `now` in colour, a cursor at `now` and the value there. Placed beside a frame
/// (cv::hconcat), it hides none of the article.
cv::Mat tracePanel(const std::vector<Trace>& traces, double now, cv::Size size);

}  // namespace mmv::render
