#pragma once
// The Python adapter of the declared options (sim/app/options.hpp): a verb's keyword
// arguments read into its options struct by the same field list the command line is made
// from, and the list itself for mmvlab/__init__.py, which makes each declared verb's
// signature, defaults and docstring from it (`_mmvlab.options(verb)`). The values are
// only converted here; their ranges are the study's to check, once.
#include <pybind11/pybind11.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sim/app/options.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv::python {

namespace py = pybind11;

/// One value as the field's type; a TypeError naming the keyword for the wrong kind.
void readOption(py::handle value, const app::Option& o, bool& out);
void readOption(py::handle value, const app::Option& o, int& out);
void readOption(py::handle value, const app::Option& o, double& out);
void readOption(py::handle value, const app::Option& o, std::string& out);
void readOption(py::handle value, const app::Option& o, std::vector<std::string>& out);
void readOption(py::handle value, const app::Option& o, std::vector<int>& out);
void readOption(py::handle value, const app::Option& o, std::vector<double>& out);
void readOption(py::handle value, const app::Option& o, app::Band& out);
/// None: absent (the scene's setting); else the value.
template <class T>
void readOption(py::handle value, const app::Option& o, std::optional<T>& out) {
  if (value.is_none()) {
    out.reset();
    return;
  }
  T v{};
  readOption(value, o, v);
  out = v;
}

/// `options` with each keyword of `kwargs` read into its declared field (the others keep
/// their defaults); a keyword no field declares is a TypeError naming the closest ones.
template <class Options>
void readOptions(const py::dict& kwargs, const std::string& verb, Options& options) {
  std::set<std::string> known;
  Options::fields(options, [&](auto& field, const app::Option& o) {
    known.insert(o.key());
    if (kwargs.contains(o.key().c_str())) readOption(kwargs[o.key().c_str()], o, field);
  });
  for (const auto& item : kwargs) {
    const std::string key = py::str(item.first);
    if (!known.count(key))
      throw py::type_error(verb + "() got an unexpected keyword argument '" + key + "'" +
                           didYouMean(key, std::vector<std::string>(known.begin(), known.end())));
  }
}

/// Every declared option of `Options` as Python dicts {key, type, default, help, unit,
/// range, choices, flag}: what __init__.py builds the signature and docstring from.
py::list describeForPython(const std::vector<app::OptionDescription>& options);

}  // namespace mmv::python
