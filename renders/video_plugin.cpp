// The video plugin (renders/video_api.hpp): the only code that links OpenCV's video I/O.
#include <opencv2/videoio.hpp>

#include <cmath>

#include "renders/video_api.hpp"

namespace {

using mmv::render::VideoApi;

void* openVideo(const char* path, int codec, double fps, int width, int height) {
  const int fourcc = codec == VideoApi::kMp4 ? cv::VideoWriter::fourcc('m', 'p', '4', 'v') : cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
  try {
    auto* w = new cv::VideoWriter(path, cv::CAP_FFMPEG, fourcc, fps, cv::Size(width, height));
    if (w->isOpened()) return w;
    delete w;
  } catch (const cv::Exception&) {
  }
  return nullptr;
}

void writeFrame(void* writer, const unsigned char* bgr, int width, int height, std::size_t step) {
  const cv::Mat frame(height, width, CV_8UC3, const_cast<unsigned char*>(bgr), step);
  static_cast<cv::VideoWriter*>(writer)->write(frame);
}

void releaseVideo(void* writer) {
  auto* w = static_cast<cv::VideoWriter*>(writer);
  w->release();
  delete w;
}

long frameCount(const char* path) {
  cv::VideoCapture back(path, cv::CAP_FFMPEG);
  return back.isOpened() ? std::lround(back.get(cv::CAP_PROP_FRAME_COUNT)) : -1;
}

const VideoApi kApi{mmv::render::kVideoApiVersion, openVideo, writeFrame, releaseVideo, frameCount};

}  // namespace

extern "C" __attribute__((visibility("default"))) const void* mmvlab_video_api() { return &kApi; }
