// The .mat plugin (sim/io/mat_plugin.hpp): MAT 5 read through matio (mmvlab writes
// its own: sim/io/mat5_writer.hpp).
#include "sim/io/mat_plugin.hpp"

#include <matio.h>

#include <cstdint>
#include <memory>

namespace mmv {
namespace {

/// RAII for a matio file and its variables.
struct MatCloser {
  void operator()(mat_t* m) const {
    if (m) Mat_Close(m);
  }
};
struct VarFreer {
  void operator()(matvar_t* v) const {
    if (v) Mat_VarFree(v);
  }
};
using MatFile = std::unique_ptr<mat_t, MatCloser>;
using MatVar = std::unique_ptr<matvar_t, VarFreer>;

/// UTF-16 code units (MATLAB's char) as UTF-8; a lone surrogate becomes U+FFFD.
std::string utf8(const std::uint16_t* u, std::size_t n) {
  std::string out;
  for (std::size_t k = 0; k < n; ++k) {
    char32_t cp = u[k];
    if (cp >= 0xd800 && cp < 0xdc00 && k + 1 < n && u[k + 1] >= 0xdc00 && u[k + 1] < 0xe000) {
      cp = 0x10000 + ((cp - 0xd800) << 10) + (u[k + 1] - 0xdc00);
      ++k;
    } else if (cp >= 0xd800 && cp < 0xe000) {
      cp = 0xfffd;
    }
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xc0 | cp >> 6);
      out += static_cast<char>(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xe0 | cp >> 12);
      out += static_cast<char>(0x80 | (cp >> 6 & 0x3f));
      out += static_cast<char>(0x80 | (cp & 0x3f));
    } else {
      out += static_cast<char>(0xf0 | cp >> 18);
      out += static_cast<char>(0x80 | (cp >> 12 & 0x3f));
      out += static_cast<char>(0x80 | (cp >> 6 & 0x3f));
      out += static_cast<char>(0x80 | (cp & 0x3f));
    }
  }
  return out;
}

/// A cell of strings, as MATLAB (UTF-16) or matio (UTF-8) writes char.
MatStatus readStrings(const std::string& path, const std::string& name, matvar_t* v, std::vector<std::string>& items) {
  const std::size_t n = v->dims[0] * v->dims[1];
  for (std::size_t i = 0; i < n; ++i) {
    const matvar_t* e = Mat_VarGetCell(v, static_cast<int>(i));
    const std::size_t len = e ? e->dims[0] * e->dims[1] : 0;
    if (!e || e->class_type != MAT_C_CHAR || (len > 0 && !e->data))
      return {3, path + ": " + name + ": a cell that is not a string (mmvlab writes strings only)"};
    std::string text;
    if (e->data_type == MAT_T_UINT16 || e->data_type == MAT_T_UTF16) {
      text = utf8(static_cast<const std::uint16_t*>(e->data), len);
    } else if (e->data_type == MAT_T_UINT8 || e->data_type == MAT_T_UTF8 || e->data_type == MAT_T_INT8) {
      text.assign(static_cast<const char*>(e->data), len);
    } else {
      return {3, path + ": " + name + ": a string of an encoding mmvlab does not read"};
    }
    items.push_back(text);
  }
  return {};
}

MatStatus read(const std::string& path, MatContents& c) {
  MatFile mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!mat) return {2, path + ": cannot open as a .mat file (MAT 5)"};
  while (matvar_t* raw = Mat_VarReadNext(mat.get())) {
    MatVar v(raw);
    const std::string name = v->name ? v->name : "";
    if (v->class_type == MAT_C_DOUBLE && v->rank == 2 && !v->isComplex && v->data_type == MAT_T_DOUBLE) {
      c.matrices.emplace_back(name, Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(v->data), static_cast<Eigen::Index>(v->dims[0]),
                                                                      static_cast<Eigen::Index>(v->dims[1])));
    } else if (v->class_type == MAT_C_CELL && v->rank == 2) {
      std::vector<std::string> items;
      if (MatStatus s = readStrings(path, name, v.get(), items); s.kind) return s;
      c.strings.emplace_back(name, items);
    } else {
      return {3, path + ": variable " + name + " is neither a real double matrix nor a cell of strings"};
    }
  }
  return {};
}

const MatApi kApi{kMatApiVersion, &read};

}  // namespace
}  // namespace mmv

extern "C" __attribute__((visibility("default"))) const mmv::MatApi* mmvlab_mat_api() { return &mmv::kApi; }
