#include "sim/io/finite_check.hpp"

#include <cmath>
#include <regex>
#include <sstream>

#include "sim/core/text.hpp"

namespace mmv {
namespace {

std::string pointerTo(const nlohmann::ordered_json& j, const std::string& at) {
  if (j.is_number_float()) return std::isfinite(j.get<double>()) ? "" : (at.empty() ? "/" : at);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (std::string p = pointerTo(it.value(), at + "/" + it.key()); !p.empty()) return p;
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      if (std::string p = pointerTo(j[i], at + "/" + std::to_string(i)); !p.empty()) return p;
  }
  return "";
}

}  // namespace

std::string firstNonFiniteLine(const std::string& text) {
  static const std::regex nonfinite(R"((^|[^A-Za-z_])[-+]?(nan|inf)([^A-Za-z_]|$))", std::regex::icase);
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n)
    if (std::regex_search(line, nonfinite)) return strf("line %d: '%s'", n, printable(line).c_str());
  return "";
}

std::string firstNonFiniteJson(const nlohmann::ordered_json& json) { return pointerTo(json, ""); }

}  // namespace mmv
