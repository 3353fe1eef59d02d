// mmvlab.update: the update study (sim/app/update_study.hpp) for Python, as the other
// verbs in python/mmvlab_module.cpp: options checked by the study and named as Python
// spells them, the result as the CLI's JSON and text plus the updated scene's text.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "sim/app/update_study.hpp"
#include "study_runner.hpp"

namespace py = pybind11;

namespace {

using mmv::python::PyScene;

py::tuple update(const PyScene& scene, int segments, const std::vector<std::string>& params, const std::string& measured,
                 double frequency_sigma, double mac_sigma, bool mac, double regularization, int max_iterations,
                 const std::vector<std::string>& pairs, double pair_distance, int count, double mac_threshold,
                 double max_frequency_error, py::object progress) {
  const PyScene prepared = mmv::python::withSegments(scene, segments);
  mmv::app::UpdateRequest r;
  r.params = params;
  r.pairing.measured = measured;
  r.pairing.pairs = pairs;
  r.pairing.pair_distance_m = pair_distance;
  r.pairing.modes = count;
  r.pairing.mac_threshold = mac_threshold;
  r.pairing.max_frequency_error = max_frequency_error;
  r.pairing.front = mmv::app::Front::Python;
  r.frequency_sigma = frequency_sigma;
  r.mac_sigma = mac_sigma;
  r.mac_residuals = mac;
  r.regularization = regularization;
  r.max_iterations = max_iterations;
  const mmv::app::LoadedScene loaded{prepared.scene, {}, prepared.request};
  const mmv::app::UpdateStudy s = mmv::python::released(progress, [&] { return mmv::app::runUpdateStudy(loaded, r); });
  return py::make_tuple(s.json.dump(), s.text, s.result.updated_scene, prepared.warnings);
}

}  // namespace

void defineUpdate(py::module_& m) {
  m.def("update", &update, py::arg("scene"), py::arg("segments"), py::arg("params"), py::arg("measured"),
        py::arg("frequency_sigma"), py::arg("mac_sigma"), py::arg("mac"), py::arg("regularization"), py::arg("max_iterations"),
        py::arg("pairs"), py::arg("pair_distance"), py::arg("modes"), py::arg("mac_threshold"), py::arg("max_frequency_error"),
        py::arg("progress"));
}
