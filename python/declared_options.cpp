#include "declared_options.hpp"

#include <limits>

namespace mmv::python {

namespace {

[[noreturn]] void wrongType(const app::Option& o, const char* expected, py::handle value) {
  throw py::type_error(o.key() + ": expected " + expected + " (got " + std::string(py::str(py::type::of(value).attr("__name__"))) + ")");
}

bool isNumber(py::handle v) { return PyNumber_Check(v.ptr()) && !PyUnicode_Check(v.ptr()) && !PyBytes_Check(v.ptr()); }

int asInt(py::handle v, const app::Option& o) {
  if (PyBool_Check(v.ptr()) || !PyIndex_Check(v.ptr())) wrongType(o, "an int", v);  // 12.0 is a float, True a bool
  const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(v.ptr()));
  long long x = 0;
  try {
    x = i.cast<long long>();
  } catch (const py::cast_error&) {
    x = std::numeric_limits<long long>::max();
  }
  if (x > std::numeric_limits<int>::max() || x < std::numeric_limits<int>::min())
    throw UsageError(o.key() + ": beyond an int's range (got " + std::string(py::str(v)) + ")");
  return static_cast<int>(x);
}

double asDouble(py::handle v, const app::Option& o) {
  if (PyBool_Check(v.ptr()) || !isNumber(v)) wrongType(o, "a number", v);
  const double x = PyFloat_AsDouble(v.ptr());
  if (x == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  return x;
}

std::string asString(py::handle v, const app::Option& o) {
  if (!PyUnicode_Check(v.ptr())) wrongType(o, "a str", v);
  return v.cast<std::string>();
}

/// A sequence's items (a str is one item: points="link1.tip").
template <class T, class One>
std::vector<T> asList(py::handle v, const app::Option& o, One one) {
  std::vector<T> out;
  if (PyUnicode_Check(v.ptr())) {
    out.push_back(one(v, o));
    return out;
  }
  if (!PySequence_Check(v.ptr()) && !PyIter_Check(v.ptr()) && !py::hasattr(v, "__iter__")) wrongType(o, "a sequence", v);
  for (py::handle item : py::iter(v)) out.push_back(one(item, o));
  return out;
}

}  // namespace

void readOption(py::handle v, const app::Option& o, bool& out) {
  // numpy's bool_ is not a bool: its truth value is (as `if flag:` takes it).
  if (!PyBool_Check(v.ptr()) && std::string(py::str(py::type::of(v).attr("__name__"))) != "bool_") wrongType(o, "a bool", v);
  out = py::bool_(py::reinterpret_borrow<py::object>(v));
}
void readOption(py::handle v, const app::Option& o, int& out) { out = asInt(v, o); }
void readOption(py::handle v, const app::Option& o, double& out) { out = asDouble(v, o); }
void readOption(py::handle v, const app::Option& o, std::string& out) { out = asString(v, o); }
void readOption(py::handle v, const app::Option& o, std::vector<std::string>& out) { out = asList<std::string>(v, o, asString); }
void readOption(py::handle v, const app::Option& o, std::vector<int>& out) {
  if (PyUnicode_Check(v.ptr())) wrongType(o, "a sequence of int", v);
  out = asList<int>(v, o, asInt);
}
void readOption(py::handle v, const app::Option& o, std::vector<double>& out) {
  if (PyUnicode_Check(v.ptr())) wrongType(o, "a sequence of numbers", v);
  out = asList<double>(v, o, asDouble);
}
void readOption(py::handle v, const app::Option& o, app::Band& out) {
  if (PyUnicode_Check(v.ptr())) wrongType(o, "(F_MIN_HZ, F_MAX_HZ)", v);
  const std::vector<double> b = asList<double>(v, o, asDouble);
  if (b.size() != 2) throw UsageError(strf("%s: expected (F_MIN_HZ, F_MAX_HZ), two numbers (got %zu)", o.key().c_str(), b.size()));
  out = {b[0], b[1]};
}

py::list describeForPython(const std::vector<app::OptionDescription>& options) {
  py::list out;
  for (const auto& d : options) {
    py::dict e;
    e["key"] = d.option.key();
    e["type"] = d.type;
    e["default"] = py::module_::import("json").attr("loads")(d.default_value.dump());
    e["help"] = d.help_text;
    e["unit"] = d.option.unitName();
    e["range"] = d.option.rangeText();
    e["choices"] = d.option.choiceList();
    e["flag"] = d.option.cliFlag();
    e["negated"] = d.option.negatedFlag();
    e["required"] = d.option.isRequired();
    out.append(e);
  }
  return out;
}

}  // namespace mmv::python
