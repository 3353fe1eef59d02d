#include "renders/png.hpp"

#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <stdexcept>

namespace mmv::render {
namespace {

// libpng reports errors by longjmp: the functions that call it hold no C++ object
// whose destructor a jump would skip (the buffers belong to their callers).

void appendBytes(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + n);
}

void noFlush(png_structp) {}

void quietWarning(png_structp, png_const_charp) {}

/// True when libpng encoded the rows into `out`.
bool encodeRows(png_bytep* rows, int width, int height, int color_type, std::vector<unsigned char>* out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, quietWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, appendBytes, noFlush);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_compression_strategy(png, Z_RLE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, color_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (color_type != PNG_COLOR_TYPE_GRAY) png_set_bgr(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

/// Reads the header (`*width`, `*height`) when `rows` is null, else the image into
/// `rows` (BGR, 8 bits); false when the file is not a PNG libpng can read.
bool decodeRows(std::FILE* f, png_bytep* rows, png_uint_32* width, png_uint_32* height) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, quietWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, f);
  png_read_info(png, info);
  int depth = 0, color = 0;
  png_get_IHDR(png, info, width, height, &depth, &color, nullptr, nullptr, nullptr);
  if (rows) {
    if (depth == 16) png_set_strip_16(png);
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if ((color & PNG_COLOR_MASK_COLOR) == 0) {
      if (depth < 8) png_set_expand_gray_1_2_4_to_8(png);
      png_set_gray_to_rgb(png);
    }
    png_set_strip_alpha(png);
    png_set_bgr(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_read_image(png, rows);
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

std::vector<unsigned char> encodePng(const cv::Mat& image) {
  const int channels = image.channels();
  if (image.depth() != CV_8U || (channels != 1 && channels != 3 && channels != 4) || image.empty())
    throw std::runtime_error("a PNG is written from an 8-bit image of 1, 3 or 4 channels");
  const int type = channels == 1 ? PNG_COLOR_TYPE_GRAY : channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA;
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.rows));
  for (int r = 0; r < image.rows; ++r) rows[static_cast<std::size_t>(r)] = const_cast<png_bytep>(image.ptr<unsigned char>(r));
  std::vector<unsigned char> out;
  if (!encodeRows(rows.data(), image.cols, image.rows, type, &out)) throw std::runtime_error("libpng could not encode the image");
  return out;
}

cv::Mat readPng(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error(path + ": cannot be opened");
  png_uint_32 width = 0, height = 0;
  const bool header = decodeRows(f, nullptr, &width, &height);
  if (!header || width == 0 || height == 0 || width > 1u << 16 || height > 1u << 16) {
    std::fclose(f);
    throw std::runtime_error(path + ": not a PNG image");
  }
  cv::Mat image(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 r = 0; r < height; ++r) rows[r] = image.ptr<unsigned char>(static_cast<int>(r));
  std::rewind(f);
  const bool ok = decodeRows(f, rows.data(), &width, &height);
  std::fclose(f);
  if (!ok) throw std::runtime_error(path + ": not a PNG image");
  return image;
}

}  // namespace mmv::render
