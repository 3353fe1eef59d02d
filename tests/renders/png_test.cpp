// PNGs through libpng (renders/png.hpp) against OpenCV's codecs, which mmvlab no longer
// loads: the same file bytes from the same pixels, the same pixels from the same file.
#include "renders/png.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

namespace mmv {
namespace {

namespace fs = std::filesystem;

/// Every figure the docs ship (plots, frames, contact sheets, the review page).
std::vector<fs::path> shippedFigures() {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(MMVLAB_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".png") out.push_back(e.path());
  return out;
}

TEST(Png, EncodesEveryShippedFigureAsOpenCvDid) {
  const auto figures = shippedFigures();
  ASSERT_GE(figures.size(), 20u);
  for (const auto& p : figures) {
    const cv::Mat m = cv::imread(p.string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(m.empty()) << p;
    std::vector<unsigned char> theirs;
    ASSERT_TRUE(cv::imencode(".png", m, theirs)) << p;
    EXPECT_TRUE(render::encodePng(m) == theirs) << p << ": " << m.channels() << " channels";
  }
}

TEST(Png, ReadsEveryShippedFigureAsOpenCvDoes) {
  for (const auto& p : shippedFigures()) {
    const cv::Mat ours = render::readPng(p.string()), theirs = cv::imread(p.string(), cv::IMREAD_COLOR);
    ASSERT_EQ(ours.type(), CV_8UC3) << p;
    ASSERT_EQ(ours.size(), theirs.size()) << p;
    EXPECT_EQ(cv::norm(ours, theirs, cv::NORM_INF), 0) << p;
  }
}

TEST(Png, GreyAndAlphaImagesRoundTripAndMatchOpenCv) {
  cv::Mat grey(37, 53, CV_8UC1), bgra(29, 41, CV_8UC4);
  cv::randu(grey, 0, 256);
  cv::randu(bgra, 0, 256);
  for (const cv::Mat& m : {grey, bgra}) {
    std::vector<unsigned char> theirs;
    ASSERT_TRUE(cv::imencode(".png", m, theirs));
    const std::vector<unsigned char> ours = render::encodePng(m);
    EXPECT_TRUE(ours == theirs) << m.channels() << " channels";
    const fs::path f = fs::temp_directory_path() / ("mmvlab_png_" + std::to_string(::getpid()) + ".png");
    std::ofstream(f, std::ios::binary).write(reinterpret_cast<const char*>(ours.data()), static_cast<std::streamsize>(ours.size()));
    EXPECT_EQ(cv::norm(render::readPng(f.string()), cv::imread(f.string(), cv::IMREAD_COLOR), cv::NORM_INF), 0);
    fs::remove(f);
  }
}

TEST(Png, RefusesWhatItCannotWriteOrRead) {
  EXPECT_THROW(render::encodePng(cv::Mat(4, 4, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5))), std::runtime_error);
  EXPECT_THROW(render::encodePng(cv::Mat()), std::runtime_error);
  const fs::path f = fs::temp_directory_path() / ("mmvlab_notpng_" + std::to_string(::getpid()) + ".png");
  std::ofstream(f) << "not a PNG at all";
  try {
    render::readPng(f.string());
    ADD_FAILURE() << "a text file read as a PNG";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(f.string() + ": not a PNG image"), std::string::npos) << e.what();
  }
  fs::remove(f);
  EXPECT_THROW(render::readPng((f.string() + ".absent")), std::runtime_error);
}

}  // namespace
}  // namespace mmv
