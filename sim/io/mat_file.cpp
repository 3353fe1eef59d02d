#include "sim/io/mat_file.hpp"

#include "sim/core/errors.hpp"
#include <matio.h>

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

void writeStateSpaceMat(const std::string& path, const StateSpace& d) {
  MatFile mat(Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5));
  if (!mat) throw OutputError(path + ": cannot create .mat file");
  const StateSpace s = d.standardForm();
  writeMatrix(mat.get(), "A", s.A);
  writeMatrix(mat.get(), "B", s.B);
  writeMatrix(mat.get(), "C", s.C);
  writeMatrix(mat.get(), "D", s.D);
  writeMatrix(mat.get(), "E", s.E);
  writeMatrix(mat.get(), "Ad", d.A);
  writeMatrix(mat.get(), "Bd", d.B);
  writeMatrix(mat.get(), "Ed", d.E);
  writeStrings(mat.get(), "InputName", d.input_names);
  writeStrings(mat.get(), "OutputName", d.output_names);
  writeStrings(mat.get(), "StateName", d.state_names);
  writeStrings(mat.get(), "InputUnit", d.input_units);
  writeStrings(mat.get(), "OutputUnit", d.output_units);
  if (Mat_Close(mat.release()) != 0) throw OutputError(path + ": cannot write the .mat file (disk full?)");
  MatFile back(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!back) throw OutputError(path + ": the .mat file written does not open (disk full?)");
  const std::pair<const char*, const Eigen::MatrixXd*> written[] = {{"A", &s.A}, {"B", &s.B}, {"C", &s.C}, {"D", &s.D},
                                                                    {"E", &s.E}, {"Ad", &d.A}, {"Bd", &d.B}, {"Ed", &d.E}};
  for (const auto& [name, m] : written) checkMatrix(back.get(), path, name, *m);
  for (const char* name : {"InputName", "OutputName", "StateName", "InputUnit", "OutputUnit"})
    if (!MatVar(Mat_VarReadInfo(back.get(), name))) throw OutputError(path + ": " + name + " did not write whole (disk full?)");
}

}  // namespace mmv
