#include "sim/io/mat_file.hpp"

#include "sim/core/errors.hpp"
#include <matio.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>

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

void write(mat_t* mat, MatVar var, const std::string& what) {
  if (!var) throw OutputError("cannot create .mat variable " + what);
  if (Mat_VarWrite(mat, var.get(), MAT_COMPRESSION_NONE) != 0) throw OutputError("cannot write .mat variable " + what);
}

void writeMatrix(mat_t* mat, const char* name, const Eigen::MatrixXd& m) {
  // matio copies nothing: the data must live until the write; Eigen is column-major like MATLAB.
  Eigen::MatrixXd copy = m;
  size_t dims[2] = {static_cast<size_t>(m.rows()), static_cast<size_t>(m.cols())};
  write(mat, MatVar(Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, copy.data(), 0)), name);
}

void writeStrings(mat_t* mat, const char* name, const std::vector<std::string>& items) {
  size_t dims[2] = {items.size(), 1};
  MatVar cell(Mat_VarCreate(name, MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0));
  if (!cell) throw OutputError(std::string("cannot create .mat cell ") + name);
  for (std::size_t i = 0; i < items.size(); ++i) {
    size_t sdims[2] = {1, items[i].size()};
    // MAT_F_DONT_COPY_DATA is not used: matio copies the characters, the cell owns them.
    matvar_t* s = Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UINT8, 2, sdims, const_cast<char*>(items[i].data()), 0);
    if (!s) throw OutputError(std::string("cannot create .mat string in ") + name);
    Mat_VarSetCell(cell.get(), static_cast<int>(i), s);
  }
  write(mat, std::move(cell), name);
}

/// Reads `name` back from the closed file and checks it is the matrix written (matio
/// buffers its writes, so a full disk can surface only here).
void checkMatrix(mat_t* mat, const std::string& path, const char* name, const Eigen::MatrixXd& m) {
  MatVar v(Mat_VarRead(mat, name));
  const bool ok = v && v->class_type == MAT_C_DOUBLE && v->rank == 2 && v->dims[0] == static_cast<size_t>(m.rows()) &&
                  v->dims[1] == static_cast<size_t>(m.cols()) &&
                  (m.size() == 0 || (v->data && Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(v->data), m.rows(), m.cols()) == m));
  if (!ok) throw OutputError(path + ": " + name + " did not write whole (disk full?)");
}

}  // namespace

void writeMat(const std::string& path, const MatContents& c) {
  MatFile mat(Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5));
  if (!mat) throw OutputError(path + ": cannot create .mat file");
  for (const auto& [name, m] : c.matrices) writeMatrix(mat.get(), name.c_str(), m);
  for (const auto& [name, items] : c.strings) writeStrings(mat.get(), name.c_str(), items);
  if (Mat_Close(mat.release()) != 0) throw OutputError(path + ": cannot write the .mat file (disk full?)");
  MatFile back(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!back) throw OutputError(path + ": the .mat file written does not open (disk full?)");
  for (const auto& [name, m] : c.matrices) checkMatrix(back.get(), path, name.c_str(), m);
  for (const auto& [name, items] : c.strings)
    if (!MatVar(Mat_VarReadInfo(back.get(), name.c_str()))) throw OutputError(path + ": " + name + " did not write whole (disk full?)");
}

MatContents readMat(const std::string& path, long max_bytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneFileError(path + ": no such file (or not a regular file)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > static_cast<std::uintmax_t>(max_bytes))
    throw SceneFileError(path + ": larger than " + std::to_string(max_bytes) + " bytes, more than a .mat file mmvlab reads here");
  MatFile mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!mat) throw SceneFileError(path + ": cannot open as a .mat file (MAT 5)");
  MatContents c;
  while (matvar_t* raw = Mat_VarReadNext(mat.get())) {
    MatVar v(raw);
    const std::string name = v->name ? v->name : "";
    if (v->class_type == MAT_C_DOUBLE && v->rank == 2 && !v->isComplex && v->data_type == MAT_T_DOUBLE) {
      c.matrices.emplace_back(name, Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(v->data), static_cast<Eigen::Index>(v->dims[0]),
                                                                      static_cast<Eigen::Index>(v->dims[1])));
    } else if (v->class_type == MAT_C_CELL && v->rank == 2) {
      std::vector<std::string> items;
      const std::size_t n = v->dims[0] * v->dims[1];
      for (std::size_t i = 0; i < n; ++i) {
        const matvar_t* e = Mat_VarGetCell(v.get(), static_cast<int>(i));
        const std::size_t len = e ? e->dims[0] * e->dims[1] : 0;
        if (!e || e->class_type != MAT_C_CHAR || (len > 0 && !e->data))
          throw SceneError(path + ": " + name + ": a cell that is not a string (mmvlab writes strings only)");
        std::string text;
        if (e->data_type == MAT_T_UINT16 || e->data_type == MAT_T_UTF16) {  // MATLAB's and matio's own reading of char
          for (std::size_t k = 0; k < len; ++k) text += static_cast<char>(static_cast<const std::uint16_t*>(e->data)[k] & 0x7f);
        } else if (e->data_type == MAT_T_UINT8 || e->data_type == MAT_T_UTF8 || e->data_type == MAT_T_INT8) {
          text.assign(static_cast<const char*>(e->data), len);
        } else {
          throw SceneError(path + ": " + name + ": a string of an encoding mmvlab does not read");
        }
        items.push_back(text);
      }
      c.strings.emplace_back(name, items);
    } else {
      throw SceneError(path + ": variable " + name + " is neither a real double matrix nor a cell of strings");
    }
  }
  return c;
}

void writeStateSpaceMat(const std::string& path, const StateSpace& d) {
  const StateSpace s = d.standardForm();
  writeMat(path, {{{"A", s.A}, {"B", s.B}, {"C", s.C}, {"D", s.D}, {"E", s.E}, {"Ad", d.A}, {"Bd", d.B}, {"Ed", d.E}},
                  {{"InputName", d.input_names},
                   {"OutputName", d.output_names},
                   {"StateName", d.state_names},
                   {"InputUnit", d.input_units},
                   {"OutputUnit", d.output_units}}});
}

}  // namespace mmv
