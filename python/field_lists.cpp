// The field lists of sim/io/fields.hpp as Python sees them: mmvlab.mode_fields() and
// mmvlab.check_line_fields() describe the columns of ModesResult.table() and
// CheckResult.table() (python/mmvlab/__init__.py).
#include <pybind11/pybind11.h>

#include "sim/io/check_report.hpp"
#include "sim/io/mode_fields.hpp"

namespace py = pybind11;

void defineFieldLists(py::module_& m) {
  m.def("mode_fields", [] {
    py::list out;
    for (const auto& f : mmv::modeFields())
      out.append(py::dict(py::arg("key") = f.key, py::arg("unit") = f.unit, py::arg("csv") = f.csv_format != nullptr,
                          py::arg("applies") = f.applies == mmv::ModeField::Applies::Always    ? "always"
                                               : f.applies == mmv::ModeField::Applies::Spatial ? "spatial"
                                                                                               : "damped",
                          py::arg("meaning") = f.meaning));
    return out;
  });
  m.def("check_line_fields", [] {
    py::list out;
    for (const auto& f : mmv::checkLineFields())
      out.append(py::dict(py::arg("key") = f.key, py::arg("unit") = f.unit, py::arg("meaning") = f.meaning));
    return out;
  });
}
