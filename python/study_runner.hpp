#pragma once
// What every binding of the Python module shares (python/mmvlab_module.cpp,
// python/update_binding.cpp): the scene handle, and running a study without the GIL with
// Python's signals and the progress callback checked at every progress step.
#include <pybind11/pybind11.h>

#include <chrono>
#include <string>
#include <vector>

#include "sim/app/study.hpp"
#include "sim/core/progress.hpp"

namespace mmv::python {

namespace py = pybind11;

/// The scene and the warnings its loading made, as Python holds it.
struct PyScene {
  mmv::Scene scene;
  std::vector<std::string> warnings;
  mmv::app::SceneRequest request;  ///< what was read: a study's `segments=` reads it again
};

/// Ends a study from a progress step: Python has an exception pending (its signal
/// handler raised one, or the progress callback did). Not a std::exception, so no layer
/// turns it into one of mmvlab's errors on its way out.
struct PythonErrorPending {};

/// The callback of the study this thread runs (None: none); the checkpoint runs on the
/// thread whose study records progress (the first of several running at once).
inline thread_local py::object* g_callback = nullptr;
inline thread_local std::chrono::steady_clock::time_point g_last_report;
/// Studies running now, from any Python thread (changed with the GIL held): the
/// checkpoint is installed while there is one.
inline int g_running = 0;

inline void checkpoint() {
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
  if (g_running++ == 0) mmv::setProgressCheckpoint(&checkpoint);
  struct Restore {
    ~Restore() {  // with the GIL held again
      if (--g_running == 0) mmv::setProgressCheckpoint(nullptr);
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

/// The scene a study runs on: `segments` (0: as loaded) applied to a copy; `warnings`
/// holds only what applying them said (the loading's were given at load_scene).
inline PyScene withSegments(const PyScene& s, int segments) {
  if (segments == 0) return PyScene{s.scene, {}, s.request};
  mmv::app::LoadedScene l = mmv::app::withSegments(mmv::app::LoadedScene{s.scene, {}, s.request}, segments);
  return PyScene{std::move(l.scene), std::move(l.warnings), std::move(l.request)};
}

}  // namespace mmv::python
