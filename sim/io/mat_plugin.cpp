// The .mat plugin (sim/io/mat_plugin.hpp): MAT 5 through matio. Writes are read back
// (matio buffers them: a full disk surfaces only there).
#include "sim/io/mat_plugin.hpp"

#include <matio.h>

#include <cstdint>
#include <memory>

namespace mmv {
namespace {

/// RAII for a matio file and for variables not yet handed to a cell.
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

MatStatus output(const std::string& message) { return {1, message}; }

MatStatus writeVar(mat_t* mat, MatVar var, const std::string& what) {
  if (!var) return output("cannot create .mat variable " + what);
  if (Mat_VarWrite(mat, var.get(), MAT_COMPRESSION_NONE) != 0) return output("cannot write .mat variable " + what);
  return {};
}

MatStatus writeMatrix(mat_t* mat, const std::string& name, const Eigen::MatrixXd& m) {
  // Written from the matrix itself (Eigen is column-major like MATLAB): without
  // MAT_F_DONT_COPY_DATA matio copies the data (2 MB a matrix of the full model at 64
  // segments a link), with it it keeps the pointer, frees nothing and only reads (the
  // const_cast is for its non-const parameter). The matrix outlives the write.
  size_t dims[2] = {static_cast<size_t>(m.rows()), static_cast<size_t>(m.cols())};
  return writeVar(mat, MatVar(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(m.data()),
                                            MAT_F_DONT_COPY_DATA)), name);
}

MatStatus writeStrings(mat_t* mat, const std::string& name, const std::vector<std::string>& items) {
  size_t dims[2] = {items.size(), 1};
  MatVar cell(Mat_VarCreate(name.c_str(), MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0));
  if (!cell) return output("cannot create .mat cell " + name);
  for (std::size_t i = 0; i < items.size(); ++i) {
    size_t sdims[2] = {1, items[i].size()};
    // MAT_F_DONT_COPY_DATA is not used: matio copies the characters, the cell owns them.
    matvar_t* s = Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UINT8, 2, sdims, const_cast<char*>(items[i].data()), 0);
    if (!s) return output("cannot create .mat string in " + name);
    Mat_VarSetCell(cell.get(), static_cast<int>(i), s);
  }
  return writeVar(mat, std::move(cell), name);
}

/// Whether `name` reads back from the closed file as the matrix written.
bool sameMatrix(mat_t* mat, const std::string& name, const Eigen::MatrixXd& m) {
  MatVar v(Mat_VarRead(mat, name.c_str()));
  return v && v->class_type == MAT_C_DOUBLE && v->rank == 2 && v->dims[0] == static_cast<size_t>(m.rows()) &&
         v->dims[1] == static_cast<size_t>(m.cols()) &&
         (m.size() == 0 || (v->data && Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(v->data), m.rows(), m.cols()) == m));
}

MatStatus write(const std::string& path, const MatContents& c) {
  MatFile mat(Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5));
  if (!mat) return output(path + ": cannot create .mat file");
  for (const auto& [name, m] : c.matrices)
    if (MatStatus s = writeMatrix(mat.get(), name, m); s.kind) return s;
  for (const auto& [name, items] : c.strings)
    if (MatStatus s = writeStrings(mat.get(), name, items); s.kind) return s;
  if (Mat_Close(mat.release()) != 0) return output(path + ": cannot write the .mat file (disk full?)");
  MatFile back(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!back) return output(path + ": the .mat file written does not open (disk full?)");
  for (const auto& [name, m] : c.matrices)
    if (!sameMatrix(back.get(), name, m)) return output(path + ": " + name + " did not write whole (disk full?)");
  for (const auto& [name, items] : c.strings)
    if (!MatVar(Mat_VarReadInfo(back.get(), name.c_str()))) return output(path + ": " + name + " did not write whole (disk full?)");
  return {};
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
      for (std::size_t k = 0; k < len; ++k) text += static_cast<char>(static_cast<const std::uint16_t*>(e->data)[k] & 0x7f);
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

const MatApi kApi{kMatApiVersion, &write, &read};

}  // namespace
}  // namespace mmv

extern "C" __attribute__((visibility("default"))) const mmv::MatApi* mmvlab_mat_api() { return &mmv::kApi; }
