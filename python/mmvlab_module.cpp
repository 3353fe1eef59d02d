// The Python module's native part, `mmvlab._mmvlab`: the studies of sim/app behind a
// small C++ surface that mmvlab/__init__.py wraps. What crosses: the scene as an opaque
// handle, options as Python values checked by the studies (named as Python spells them),
// results as the JSON text the CLI prints (one writer for both, so they cannot differ)
// plus the text report. While a study runs the GIL is released; at every progress step
// (sim/core/progress.hpp) the module takes it back to run Python's signal handlers (Ctrl-C
// raises KeyboardInterrupt between two steps) and the caller's progress callback.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <vector>

#include "sim/app/component_studies.hpp"
#include "sim/app/config_sweep_study.hpp"
#include "sim/app/correlate_study.hpp"
#include "sim/app/linear_study.hpp"
#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/app/simulate_study.hpp"
#include "sim/app/design_sweep_study.hpp"
#include "sim/app/hamsas_linear_study.hpp"
#include "sim/app/trade_study.hpp"
#include "sim/app/study.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/report.hpp"
#include "sim/scene/scene.hpp"
#include "sim/core/text.hpp"
#include "declared_options.hpp"
#include "sim/app/verbs.hpp"
#include "study_runner.hpp"

namespace py = pybind11;

namespace {

using mmv::app::Front;
using mmv::python::PyScene;
using mmv::python::released;
using mmv::python::withSegments;

PyScene loadScene(const std::optional<std::string>& path, const std::vector<std::string>& sets, int segments,
                  bool no_gravity, bool strict) {
  mmv::app::SceneRequest r;
  r.path = path.value_or("");
  if (path && path->empty()) throw mmv::UsageError("path: an empty path (None: the embedded default scene)");
  r.sets = sets;
  if (segments != 0) r.segments = segments;  // 0: the scene's own
  r.no_gravity = no_gravity;
  r.strict = strict;
  r.front = Front::Python;
  mmv::app::LoadedScene l = mmv::app::loadScene(r);
  return PyScene{std::move(l.scene), std::move(l.warnings), std::move(l.request)};
}

py::tuple correlate(const PyScene& scene, int segments, const std::string& measured, const std::vector<std::string>& pairs,
                    double pair_distance, int count, double mac_threshold, double max_frequency_error,
                    std::optional<double> damping, const std::string& tam, py::object progress) {
  const PyScene prepared = withSegments(scene, segments);
  mmv::app::CorrelateRequest r;
  r.measured = measured;
  r.pairs = pairs;
  r.pair_distance_m = pair_distance;
  r.modes = count;
  r.mac_threshold = mac_threshold;
  r.max_frequency_error = max_frequency_error;
  r.damping_ratio = damping;
  r.tam = tam;
  r.front = Front::Python;
  const mmv::app::CorrelateStudy s = released(progress, [&] { return mmv::app::runCorrelateStudy(prepared.scene, r); });
  return py::make_tuple(s.json.dump(), s.text, s.mac_csv, prepared.warnings);
}

py::tuple placeSensors(const PyScene& scene, int segments, const std::vector<int>& target_modes, std::optional<double> below_hz,
                       double spacing, int count, bool triaxial, const std::string& method, const std::vector<std::string>& tam,
                       double sensor_mass, double min_separation, const std::vector<std::string>& keep_out, int channels,
                       bool keep_scene_sensors, const std::string& instrument, bool iterate_loaded, double strain_span,
                       double max_deflection, py::object progress) {
  const PyScene prepared = withSegments(scene, segments);
  mmv::app::PlacementRequest r;
  r.modes = target_modes;
  r.below_given = below_hz.has_value();
  r.below_hz = below_hz.value_or(r.below_hz);
  r.spacing_m = spacing;
  r.count = count;
  r.triaxial = triaxial;
  r.method = method;
  r.tam = tam;
  r.sensor_mass_kg = sensor_mass;
  r.min_separation_m = min_separation;
  r.keep_out = keep_out;
  r.channels = channels;
  r.keep_scene_sensors = keep_scene_sensors;
  r.instrument = instrument;
  r.iterate_loaded = iterate_loaded;
  r.strain_span_m = strain_span;
  r.max_deflection_m = max_deflection;
  r.front = Front::Python;
  const mmv::app::PlacementStudyResult s = released(progress, [&] { return mmv::app::runPlacementStudy(prepared.scene, r); });
  return py::make_tuple(s.json.dump(), s.text, s.tam_csv, prepared.warnings);
}

/// Responses H[k] (outputs x inputs) as one numpy array [frequency, output, input] that
/// owns its copy.
py::array_t<std::complex<double>> responses(const std::vector<Eigen::MatrixXcd>& h, Eigen::Index rows, Eigen::Index cols) {
  py::array_t<std::complex<double>> a({static_cast<py::ssize_t>(h.size()), static_cast<py::ssize_t>(rows),
                                       static_cast<py::ssize_t>(cols)});
  auto v = a.mutable_unchecked<3>();
  for (std::size_t k = 0; k < h.size(); ++k)
    for (Eigen::Index o = 0; o < rows; ++o)
      for (Eigen::Index i = 0; i < cols; ++i) v(k, o, i) = h[k](o, i);
  return a;
}

py::dict stateSpace(const mmv::StateSpace& s) {
  py::dict d;
  d["E"] = s.E, d["A"] = s.A, d["B"] = s.B, d["C"] = s.C, d["D"] = s.D;  // Eigen matrices copied into numpy
  d["input_names"] = s.input_names, d["input_units"] = s.input_units;
  d["output_names"] = s.output_names, d["output_units"] = s.output_units, d["state_names"] = s.state_names;
  return d;
}

/// A grid (Hz) as a numpy array that owns its copy.
Eigen::VectorXd gridCopy(const std::vector<double>& f) {
  return Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(f.size()));
}

/// frf on the isolator: the 6 x 6 transmissibility per frequency, [frequency, table DOF, ground DOF].
py::dict hamsasFrf(const mmv::HamsasScene& scene, const mmv::app::LinearRequest& r, py::object progress) {
  const mmv::app::HamsasFrfStudy s = released(progress, [&] { return mmv::app::runHamsasFrfStudy(scene, r); });
  py::dict d;
  d["json"] = s.json.dump();
  d["text"] = s.text;
  d["warnings"] = std::vector<std::string>{};
  d["frequencies_hz"] = gridCopy(s.f);
  d["T"] = responses(s.T, 6, 6);
  std::vector<std::string> dofs;
  for (int k = 0; k < 6; ++k) dofs.push_back(mmv::hamsasDofName(k));
  d["dof_names"] = dofs;
  return d;
}

/// rom on the isolator: the actuator-to-sensor model, its reduction and both responses.
py::dict hamsasRom(const mmv::HamsasScene& scene, const mmv::app::LinearRequest& r, py::object progress) {
  const mmv::app::HamsasRomStudy s = released(progress, [&] { return mmv::app::runHamsasRomStudy(scene, r); });
  const std::vector<double>& f = s.f;
  std::vector<Eigen::MatrixXcd> hf, hr;
  for (double x : f) hf.push_back(s.full.response(2 * M_PI * x)), hr.push_back(s.red.model.response(2 * M_PI * x));
  py::dict d;
  d["json"] = s.json.dump();
  d["text"] = s.text;
  d["warnings"] = std::vector<std::string>{};
  d["frequencies_hz"] = gridCopy(f);
  d["H"] = responses(hf, s.full.C.rows(), s.full.B.cols());
  d["H_reduced"] = responses(hr, s.full.C.rows(), s.full.B.cols());
  d["reduced"] = stateSpace(s.red.model);
  d["full"] = stateSpace(s.full);
  return d;
}

/// frf and rom: the study, then what Python gets of it (`rom`: the romJson document).
py::dict linear(const PyScene& scene, int segments, const std::vector<std::string>& inputs,
                const std::vector<std::string>& outputs, std::optional<double> f_min, std::optional<double> f_max, int points,
                int rom_modes, std::optional<std::pair<double, double>> band, bool residualize,
                std::optional<double> damping, double rom_target, double target_error, double time_budget, bool rom,
                const std::string& vary, py::object progress) {
  const PyScene prepared = withSegments(scene, segments);
  const mmv::Scene& sc = prepared.scene;
  mmv::app::LinearRequest r;
  r.inputs = inputs;
  r.outputs = outputs;
  r.range_given = f_min || f_max;
  r.f_min = f_min.value_or(r.f_min);
  r.f_max = f_max.value_or(r.f_max);
  r.points = points;
  r.rom_modes = rom_modes;
  r.band = band;
  r.residualize = residualize;
  r.damping_given = damping.has_value();
  r.damping_ratio = damping.value_or(r.damping_ratio);
  r.rom_target = rom_target;
  r.target_error = target_error;
  r.time_budget = time_budget;
  r.segments_given = segments != 0;
  r.vary = vary;
  r.front = Front::Python;
  if (const auto* h = std::get_if<mmv::HamsasScene>(&sc)) return rom ? hamsasRom(*h, r, progress) : hamsasFrf(*h, r, progress);
  const mmv::app::LinearStudy a = released(progress, [&] { return mmv::app::runLinearStudy(std::get<mmv::ArticleScene>(sc), r); });
  const nlohmann::ordered_json json = rom ? a.romJson() : a.frfJson();
  mmv::app::checkResultFinite(json);
  std::vector<Eigen::MatrixXcd> hr;
  for (double w : a.w) hr.push_back(a.red.model.response(w));
  py::dict d;
  d["json"] = json.dump();
  d["text"] = a.summaryText();
  d["warnings"] = prepared.warnings;
  // A VectorXd by value (not a Map of the study's vector, which dies here): numpy owns the copy.
  d["frequencies_hz"] = gridCopy(a.f);
  const Eigen::Index no = a.lm.full.C.rows(), ni = a.lm.full.B.cols();
  d["H"] = responses(a.hf, no, ni);
  d["H_reduced"] = responses(hr, no, ni);
  d["reduced"] = stateSpace(a.red.model);
  if (rom) d["full"] = stateSpace(a.lm.full);
  return d;
}

/// A record's rows as one [sample, column] array that owns its copy.
py::array_t<double> table(const mmv::SimulationRecord& rec) {
  const std::size_t n = rec.rows.size(), m = rec.columns.size();
  py::array_t<double> a({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(m)});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) v(i, j) = rec.rows[i][j];
  return a;
}

py::dict simulate(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  const PyScene prepared = withSegments(scene, segments);
  const mmv::Scene& sc = prepared.scene;
  mmv::app::SimulateRequest r;
  mmv::python::readOptions(options, "simulate", r);
  r.front = Front::Python;
  const mmv::app::SimulateStudy s = released(progress, [&] { return mmv::app::runSimulateStudy(sc, r); });
  py::dict d;
  d["json"] = s.summary.dump();
  d["text"] = s.text;
  d["warnings"] = prepared.warnings;
  // The column names of history.csv and states.csv, by the same function.
  const auto csvNames = [](const std::vector<std::string>& columns) {
    std::vector<std::string> out;
    for (const auto& c : columns) out.push_back(mmv::csvColumnName(c));
    return out;
  };
  d["columns"] = csvNames(s.result.record.columns);
  d["history"] = table(s.result.record);
  d["state_columns"] = csvNames(s.result.states.columns);
  d["states"] = table(s.result.states);
  return d;
}

py::tuple sweep(const std::string& spec, const std::string& out, int jobs, std::optional<std::pair<int, int>> shard,
                bool restart, py::object progress) {
  mmv::app::DesignSweepRequest r;
  r.spec = spec;
  r.out = out;
  r.jobs = jobs;
  if (shard) r.shard.index = shard->first, r.shard.count = shard->second;
  r.restart = restart;
  r.front = Front::Python;
  const mmv::app::DesignSweepStudy s = released(progress, [&] {
    mmv::app::DesignSweepStudy study = mmv::app::runDesignSweepStudy(r);
    mmv::OutputDir dir(study.dir, /*force=*/true);  // sweep.csv and sweep.json, as the CLI commits them
    dir.replaceOnlyOwnFiles();
    dir.reportNothing();
    mmv::app::stageDesignSweepOutputs(study, dir);
    dir.commit();
    return study;
  });
  return py::make_tuple(s.json.dump(), s.text, s.result.table);
}


/// A declared verb's study (sim/app/verbs.hpp): its keyword arguments read by the same
/// field list as the command line's options (python/declared_options.hpp), the study run
/// without the GIL, the JSON, the text, one more text output and the warnings returned.
template <class Request, class Run, class Third>
py::tuple declaredStudy(const char* verb, const PyScene& scene, int segments, const py::dict& options, py::object progress,
                        Run run, Third third) {
  const PyScene prepared = withSegments(scene, segments);
  Request r;
  mmv::python::readOptions(options, verb, r);
  r.front = Front::Python;
  if constexpr (std::is_same_v<Request, mmv::app::ModesRequest>) r.segments_given = segments != 0;
  const auto s = released(progress, [&] { return run(prepared.scene, r); });
  return py::make_tuple(s.json.dump(), s.text, third(s), prepared.warnings);
}

py::tuple modes(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::ModesRequest>("modes", scene, segments, options, progress, &mmv::app::runModesStudy,
                                               [](const mmv::app::ModesStudy& s) { return s.csv; });
}

py::tuple converge(const PyScene& scene, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::ConvergeRequest>("converge", scene, 0, options, progress, &mmv::app::runConvergeStudy,
                                                  [](const mmv::app::ConvergeStudy& s) { return s.csv; });
}

py::tuple compare(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::CompareRequest>("compare", scene, segments, options, progress, &mmv::app::runCompareStudy,
                                                 [](const mmv::app::CompareStudy& s) { return s.markdown; });
}

py::tuple sweepConfig(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::ConfigSweepRequest>("sweep_config", scene, segments, options, progress,
                                                     &mmv::app::runConfigSweepStudy,
                                                     [](const mmv::app::ConfigSweepStudy& s) { return s.csv; });
}

py::tuple trade(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::TradeRequest>("trade", scene, segments, options, progress,
                                               [](const mmv::Scene& sc, const mmv::app::TradeRequest& r) { return mmv::app::runTradeStudy(sc, r); },
                                               [](const mmv::app::TradeStudyResult& s) { return s.csv; });
}

py::tuple check(const PyScene& scene, int segments, const py::dict& options, py::object progress) {
  return declaredStudy<mmv::app::CheckRequest>("check", scene, segments, options, progress, &mmv::app::runCheckStudy,
                                               [](const mmv::app::CheckStudy& s) { return s.markdown; });
}

std::string sceneKind(const PyScene& s) { return std::holds_alternative<mmv::HamsasScene>(s.scene) ? "hamsas" : "article"; }

}  // namespace

void defineFieldLists(py::module_& m);
void defineUpdate(py::module_& m);

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
    } catch (const mmv::OptionError& e) {  // found by an analysis: the option as Python spells it
      PyErr_SetString(usage, (mmv::app::declaredOptionName(Front::Python, e.option()) + e.rest()).c_str());
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
      .def_readonly("warnings", &PyScene::warnings)
      // Picklable (a process pool takes scenes): the scene's own text, its source (relative
      // program files resolve against it, so the receiving process must see the same
      // files), and the patches it was read with, read again by the same reader.
      .def(py::pickle(
          [](const PyScene& s) {
            const std::string& source = std::visit([](const auto& x) -> const std::string& { return x.positions.file; }, s.scene);
            return py::make_tuple(1, mmv::sceneText(s.scene), source, s.request.path, s.request.sets,
                                  s.request.segments ? py::object(py::int_(*s.request.segments)) : py::object(py::none()),
                                  s.request.no_gravity, s.request.strict, s.warnings);
          },
          [](const py::tuple& t) {
            if (t.size() != 9 || t[0].cast<int>() != 1) throw std::runtime_error("mmvlab.Scene: not a pickled scene of this version");
            mmv::app::SceneRequest r;
            r.path = t[3].cast<std::string>();
            r.sets = t[4].cast<std::vector<std::string>>();
            if (!t[5].is_none()) r.segments = t[5].cast<int>();
            r.no_gravity = t[6].cast<bool>();
            r.strict = t[7].cast<bool>();
            r.front = Front::Python;
            mmv::Scene scene = mmv::parseScene(t[1].cast<std::string>(), t[2].cast<std::string>(), r.sets,
                                               mmv::app::sceneFlags(r.segments, r.no_gravity, r.front));
            return PyScene{std::move(scene), t[8].cast<std::vector<std::string>>(), std::move(r)};
          }));
  m.attr("__version__") = mmv::mmvlabVersion();
  m.def("load_scene", &loadScene, py::arg("path"), py::arg("sets"), py::arg("segments"), py::arg("no_gravity"),
        py::arg("strict"));
  m.def("modes", &modes, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  m.def("linear", &linear, py::arg("scene"), py::arg("segments"), py::arg("inputs"), py::arg("outputs"), py::arg("f_min"),
        py::arg("f_max"), py::arg("points"), py::arg("rom_modes"), py::arg("band"), py::arg("residualize"), py::arg("damping"),
        py::arg("rom_target"), py::arg("target_error"), py::arg("time_budget"), py::arg("rom"), py::arg("vary"),
        py::arg("progress"));
  m.def("simulate", &simulate, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  m.def("sweep", &sweep, py::arg("spec"), py::arg("out"), py::arg("jobs"), py::arg("shard"), py::arg("restart"),
        py::arg("progress"));
  m.def("converge", &converge, py::arg("scene"), py::arg("options"), py::arg("progress"));
  m.def("compare", &compare, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  m.def("check", &check, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  // The declared verbs' option lists (sim/app/verbs.hpp), for __init__.py's signatures and
  // docstrings and the test that holds them to the command line's --help.
  m.def("declared_verbs", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& v : mmv::app::declaredVerbs()) out.emplace_back(v.name, v.summary);
    return out;
  });
  m.def("options", [](const std::string& verb) {
    try {
      return mmv::python::describeForPython(mmv::app::declaredVerb(verb).options());
    } catch (const std::out_of_range&) {
      throw mmv::UsageError("options: no declared verb '" + mmv::printable(verb) + "'");
    }
  }, py::arg("verb"));
  defineFieldLists(m);  // python/field_lists.cpp
  defineUpdate(m);      // python/update_binding.cpp
  m.def("sweep_config", &sweepConfig, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  m.def("trade", &trade, py::arg("scene"), py::arg("segments"), py::arg("options"), py::arg("progress"));
  m.def("correlate", &correlate, py::arg("scene"), py::arg("segments"), py::arg("measured"), py::arg("pairs"),
        py::arg("pair_distance"), py::arg("modes"), py::arg("mac_threshold"), py::arg("max_frequency_error"),
        py::arg("damping"), py::arg("tam"), py::arg("progress"));
  m.def("place_sensors", &placeSensors, py::arg("scene"), py::arg("segments"), py::arg("modes"), py::arg("below_hz"),
        py::arg("spacing"), py::arg("count"), py::arg("triaxial"), py::arg("method"), py::arg("tam"), py::arg("sensor_mass"),
        py::arg("min_separation"), py::arg("keep_out"), py::arg("channels"), py::arg("keep_scene_sensors"), py::arg("instrument"),
        py::arg("iterate_loaded"), py::arg("strain_span"), py::arg("max_deflection"), py::arg("progress"));
}
