// The Python module's native part, `mmvlab._mmvlab`: the studies of sim/app behind a
// small C++ surface that mmvlab/__init__.py wraps. What crosses: the scene as an opaque
// handle, options as Python values checked by the studies (named as Python spells them),
// results as the JSON text the CLI prints (one writer for both, so they cannot differ)
// plus the text report. While a study runs the GIL is released; at every progress step
// (sim/core/progress.hpp) the module takes it back to run Python's signal handlers (Ctrl-C
// raises KeyboardInterrupt between two steps) and the caller's progress callback.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/app/study.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"

namespace py = pybind11;

namespace {

using mmv::app::Front;

/// The scene and the warnings its loading made, as Python holds it.
struct PyScene {
  mmv::Scene scene;
  std::vector<std::string> warnings;
};

/// Ends a study from a progress step: Python has an exception pending (its signal
/// handler raised one, or the progress callback did). Not a std::exception, so no layer
/// turns it into one of mmvlab's errors on its way out.
struct PythonErrorPending {};

/// The callback of the study running now (None: none); set and read with the GIL held.
py::object* g_callback = nullptr;
std::chrono::steady_clock::time_point g_last_report;

void checkpoint() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw PythonErrorPending{};
  if (!g_callback || g_callback->is_none()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - g_last_report < std::chrono::milliseconds(100)) return;  // at most ten calls a second
  const std::vector<mmv::ProgressLevel> levels = mmv::progressSnapshot();
  if (levels.size() < 2) return;  // only the module's own outer stage: nothing to say yet
  g_last_report = now;
  std::vector<py::tuple> stages;
  for (const auto& l : levels) stages.push_back(py::make_tuple(l.what, l.done, l.total, l.unit));
  try {
    (*g_callback)(stages);
  } catch (py::error_already_set& e) {
    e.restore();  // pending again: re-raised in the caller's thread once the study has unwound
    throw PythonErrorPending{};
  }
}

/// Runs `study` without the GIL, with the checkpoint installed.
template <class Study>
auto released(py::object callback, Study study) -> decltype(study()) {
  g_callback = &callback;
  g_last_report = {};
  mmv::setProgressCheckpoint(&checkpoint);
  struct Restore {
    ~Restore() {
      mmv::setProgressCheckpoint(nullptr);
      g_callback = nullptr;
    }
  } restore;
  try {
    py::gil_scoped_release nogil;
    const mmv::ProgressStage outer("python");  // stages are recorded on this thread
    return study();
  } catch (const PythonErrorPending&) {
    throw py::error_already_set();
  }
}

PyScene loadScene(const std::optional<std::string>& path, const std::vector<std::string>& sets, int segments,
                  bool no_gravity, bool strict) {
  mmv::app::SceneRequest r;
  r.path = path.value_or("");
  if (path && path->empty()) throw mmv::UsageError("path: an empty path (None: the embedded default scene)");
  r.sets = sets;
  r.segments = segments;
  r.no_gravity = no_gravity;
  r.strict = strict;
  r.front = Front::Python;
  mmv::app::LoadedScene l = mmv::app::loadScene(r);
  return PyScene{std::move(l.scene), std::move(l.warnings)};
}

/// The scene a study runs on: `segments` (0: as loaded) applied to a copy.
std::pair<mmv::Scene, std::vector<std::string>> withSegments(const PyScene& s, int segments) {
  std::pair<mmv::Scene, std::vector<std::string>> out{s.scene, {}};
  if (segments != 0) mmv::app::applySegments(out.first, segments, Front::Python, out.second);
  return out;
}

py::tuple modes(const PyScene& scene, int segments, int count, const std::vector<std::string>& points, bool error_estimate,
                double target_error, double time_budget, py::object progress) {
  auto [sc, warnings] = withSegments(scene, segments);
  mmv::app::ModesRequest r;
  r.modes = count;
  r.points = points;
  r.error_estimate = error_estimate;
  r.target_error = target_error;
  r.time_budget = time_budget;
  r.segments_given = segments != 0;
  r.front = Front::Python;
  const mmv::app::ModesStudy s = released(progress, [&] { return mmv::app::runModesStudy(sc, r); });
  return py::make_tuple(s.json.dump(), s.text, s.csv, warnings);
}

py::tuple check(const PyScene& scene, int segments, double margin, double band_min, double band_max, py::object progress) {
  auto [sc, warnings] = withSegments(scene, segments);
  mmv::app::CheckRequest r;
  r.margin_pct = margin;
  r.band_min_hz = band_min;
  r.band_max_hz = band_max;
  r.front = Front::Python;
  const mmv::app::CheckStudy s = released(progress, [&] { return mmv::app::runCheckStudy(sc, r); });
  return py::make_tuple(s.json.dump(), s.text, s.markdown, warnings);
}

py::tuple placeSensors(const PyScene& scene, int segments, const std::vector<int>& target_modes, std::optional<double> below_hz,
                       double spacing, int count, bool triaxial, const std::string& method, py::object progress) {
  auto [sc, warnings] = withSegments(scene, segments);
  mmv::app::PlacementRequest r;
  r.modes = target_modes;
  r.below_given = below_hz.has_value();
  r.below_hz = below_hz.value_or(r.below_hz);
  r.spacing_m = spacing;
  r.count = count;
  r.triaxial = triaxial;
  r.method = method;
  r.front = Front::Python;
  const mmv::app::PlacementStudyResult s = released(progress, [&] { return mmv::app::runPlacementStudy(sc, r); });
  return py::make_tuple(s.json.dump(), s.text, warnings);
}

std::string sceneKind(const PyScene& s) { return std::holds_alternative<mmv::HamsasScene>(s.scene) ? "hamsas" : "article"; }

}  // namespace

PYBIND11_MODULE(_mmvlab, m) {
  m.doc() = "mmvlab's studies (the native part; use the mmvlab package)";
  // The error classes: the same split as the CLI's exit codes (docs/architecture.md).
  // Kept for the interpreter's life (module attributes hold them too).
  static PyObject* base = PyErr_NewException("mmvlab._mmvlab.Error", PyExc_RuntimeError, nullptr);
  m.attr("Error") = py::handle(base);
  auto sub = [&m](const char* name, PyObject* also) {
    py::tuple bases = also ? py::make_tuple(py::handle(base), py::handle(also)) : py::make_tuple(py::handle(base));
    PyObject* cls = PyErr_NewException((std::string("mmvlab._mmvlab.") + name).c_str(), bases.ptr(), nullptr);
    m.attr(name) = py::handle(cls);
    return cls;
  };
  static PyObject *usage = sub("UsageError", PyExc_ValueError), *scene_error = sub("SceneError", PyExc_ValueError),
                  *scene_file = sub("SceneFileError", PyExc_OSError), *numerical = sub("NumericalError", PyExc_ArithmeticError),
                  *unavailable = sub("UnavailableError", nullptr), *output = sub("OutputError", PyExc_OSError),
                  *internal = sub("InternalError", nullptr);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const mmv::UsageError& e) {
      PyErr_SetString(usage, e.what());
    } catch (const mmv::SceneFileError& e) {
      PyErr_SetString(scene_file, e.what());
    } catch (const mmv::SceneError& e) {
      PyErr_SetString(scene_error, e.what());
    } catch (const mmv::NumericalError& e) {
      PyErr_SetString(numerical, e.what());
    } catch (const mmv::UnavailableError& e) {
      PyErr_SetString(unavailable, e.what());
    } catch (const mmv::OutputError& e) {
      PyErr_SetString(output, e.what());
    } catch (const mmv::InternalError& e) {
      PyErr_SetString(internal, e.what());
    }
  });

  py::class_<PyScene>(m, "Scene")
      .def_property_readonly("name", [](const PyScene& s) { return mmv::sceneName(s.scene); })
      .def_property_readonly("source", [](const PyScene& s) { return mmv::sceneSource(s.scene); })
      .def_property_readonly("kind", &sceneKind)
      .def_readonly("warnings", &PyScene::warnings);
  m.def("load_scene", &loadScene, py::arg("path"), py::arg("sets"), py::arg("segments"), py::arg("no_gravity"),
        py::arg("strict"));
  m.def("modes", &modes, py::arg("scene"), py::arg("segments"), py::arg("modes"), py::arg("points"), py::arg("error_estimate"),
        py::arg("target_error"), py::arg("time_budget"), py::arg("progress"));
  m.def("check", &check, py::arg("scene"), py::arg("segments"), py::arg("margin"), py::arg("band_min_hz"),
        py::arg("band_max_hz"), py::arg("progress"));
  m.def("place_sensors", &placeSensors, py::arg("scene"), py::arg("segments"), py::arg("modes"), py::arg("below_hz"),
        py::arg("spacing"), py::arg("count"), py::arg("triaxial"), py::arg("method"), py::arg("progress"));
}
