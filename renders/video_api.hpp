#pragma once
/// The video plugin (libmmvlab_video.so, renders/video_plugin.cpp): OpenCV's video I/O and
/// FFmpeg behind a C table, loaded by VideoSink on a render's first video. A still or a
/// plot never loads them (about 50 ms of shared libraries; docs/benchmarks.md, "Renders").

#include <cstddef>

namespace mmv::render {

inline constexpr int kVideoApiVersion = 1;

struct VideoApi {
  enum Codec { kMp4 = 0, kAvi = 1 };  ///< MPEG-4 part 2 in .mp4; Motion JPEG in .avi
  int version;                        ///< kVideoApiVersion
  /// An encoder writing `path` at `fps`, every frame width x height; null when it cannot open.
  void* (*open)(const char* path, int codec, double fps, int width, int height);
  /// Appends one 8-bit BGR frame (`step` bytes a row) of the encoder's size.
  void (*write)(void* writer, const unsigned char* bgr, int width, int height, std::size_t step);
  /// Finishes the file and frees the encoder.
  void (*release)(void* writer);
  /// The frames of the video at `path` as its container states them; -1 when it does not open.
  long (*frame_count)(const char* path);
};

}  // namespace mmv::render
