// The field lists of sim/io/fields.hpp as Python sees them: mmvlab.fields(name) (with
// mmvlab.mode_fields() and mmvlab.check_line_fields() kept by their names) describe the
// columns of the results' table() (python/mmvlab/__init__.py).
#include <pybind11/pybind11.h>

#include <functional>
#include <map>
#include <string>

#include "sim/core/errors.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/compare_fields.hpp"
#include "sim/io/config_sweep_report.hpp"
#include "sim/io/convergence_fields.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/loading_report.hpp"
#include "sim/io/mode_fields.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/io/simulation_report.hpp"
#include "sim/io/tam_report.hpp"
#include "sim/io/exciter_report.hpp"
#include "sim/io/trade_report.hpp"
#include "sim/io/update_report.hpp"

namespace py = pybind11;

namespace {

/// A field list as dicts {key, unit, csv, number, meaning}: `csv` a CSV column,
/// `number` whether its values are numbers (else text).
template <class Row>
py::list describe(const std::vector<mmv::Field<Row>>& fields) {
  py::list out;
  for (const auto& f : fields) {
    // A CSV column is a number unless it is printed as text; a JSON-only field, when it has a unit.
    const bool number = f.csv_format ? std::string(f.csv_format) != "%s" : *f.unit != '\0';
    out.append(py::dict(py::arg("key") = f.key, py::arg("unit") = f.unit, py::arg("csv") = f.csv_format != nullptr,
                        py::arg("number") = number, py::arg("meaning") = f.meaning));
  }
  return out;
}

/// The lists by the name mmvlab.fields() takes.
const std::map<std::string, std::function<py::list()>>& namedLists() {
  static const std::map<std::string, std::function<py::list()>> lists{
      {"check_lines", [] { return describe(mmv::checkLineFields()); }},
      {"compare_synthesis", [] { return describe(mmv::synthesisFields()); }},
      {"compare_system_modes", [] { return describe(mmv::systemModeFields()); }},
      {"convergence_modes", [] { return describe(mmv::convergenceModeFields()); }},
      {"convergence_points", [] { return describe(mmv::convergencePointFields()); }},
      {"correlation_pairs", [] { return describe(mmv::correlationPairFields()); }},
      {"exciter_modes", [] { return describe(mmv::exciterModeFields()); }},
      {"exciter_ranking", [] { return describe(mmv::exciterCandidateFields()); }},
      {"hamsas_modes", [] { return describe(mmv::hamsasModeFields()); }},
      {"mass_loading_iterations", [] { return describe(mmv::loadedIterationFields()); }},
      {"mass_loading_modes", [] { return describe(mmv::loadingModeFields()); }},
      {"placement_candidates", [] { return describe(mmv::placementFields()); }},
      {"simulate_sensors", [] { return describe(mmv::sensorSummaryFields()); }},
      {"simulate_torques", [] { return describe(mmv::jointTorqueFields()); }},
      {"simulate_stress", [] { return describe(mmv::linkRunStressFields()); }},
      {"sweep_config_tracks", [] { return describe(mmv::trackFields()); }},
      {"tam_modes", [] { return describe(mmv::tamModeFields()); }},
      {"trade_runs", [] { return describe(mmv::tradeRunFields()); }},
      {"update_pairs", [] { return describe(mmv::updatePairFields()); }},
      {"update_parameters", [] { return describe(mmv::updateParameterFields()); }},
  };
  return lists;
}

}  // namespace

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
  m.def("fields", [](const std::string& name) {
    const auto& lists = namedLists();
    if (auto it = lists.find(name); it != lists.end()) return it->second();
    std::string known;
    for (const auto& [k, _] : lists) known += (known.empty() ? "" : ", ") + k;
    throw mmv::UsageError("name: no field list '" + name + "' (known: " + known + ")");
  });
  m.def("field_list_names", [] {
    py::list out;
    for (const auto& [k, _] : namedLists()) out.append(k);
    return out;
  });
  m.def("check_line_fields", [] {
    py::list out;
    for (const auto& f : mmv::checkLineFields())
      out.append(py::dict(py::arg("key") = f.key, py::arg("unit") = f.unit, py::arg("meaning") = f.meaning));
    return out;
  });
}
