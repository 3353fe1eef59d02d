#pragma once
/// PNG files through libpng, without OpenCV's image codecs: those pull in GDAL, GDCM and
/// some 150 more shared libraries (120 ms of every process that writes a figure;
/// docs/benchmarks.md, "Renders"). The encoder uses the settings OpenCV's own PNG writer
/// uses by default (filter Sub, zlib level 1, run-length strategy), so a figure is the
/// same file byte for byte as cv::imencode(".png") made (tests/renders/png_test.cpp).

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace mmv::render {

/// `image` (8-bit; 1 channel grey, 3 BGR or 4 BGRA) as a PNG file's bytes. Throws
/// std::runtime_error for another type or when libpng fails.
std::vector<unsigned char> encodePng(const cv::Mat& image);

/// A PNG file as an 8-bit 3-channel BGR image (grey expanded, alpha dropped, 16 bits
/// reduced to 8, as cv::imread(path, IMREAD_COLOR)). Throws std::runtime_error naming
/// `path` when it cannot be read, is not a PNG, or is over 65536 pixels a side (mmvlab
/// draws at most 8192).
cv::Mat readPng(const std::string& path);

}  // namespace mmv::render
