#include "sim/io/fields.hpp"

#include "sim/core/text.hpp"

namespace mmv {

std::string fieldCsvCell(const char* format, const std::optional<nlohmann::ordered_json>& v) {
  if (!v || v->is_null()) return "";
  if (v->is_boolean()) return v->get<bool>() ? "1" : "0";
  if (v->is_string()) return csvEscape(v->get<std::string>());
  if (v->is_number_integer()) return std::to_string(v->get<long>());
  return strf(format, v->get<double>());
}

}  // namespace mmv
