#pragma once
/// Field lists: a result row's quantities described once (in the style of Drake's
/// `Serialize`): key (the JSON key and the CSV column), unit, meaning, and how the value
/// is read. The JSON record, the CSV table and the Python table of a row type are made
/// from its one list, so they cannot name or compute a quantity differently. The lists:
/// modeFields() (sim/io/mode_fields.hpp), tradeRunFields() (sim/io/trade_report.hpp),
/// trackFields() (sim/io/config_sweep_report.hpp), checkLineFields() (sim/io/check_report.hpp),
/// placementFields() (sim/io/placement_report.hpp), correlationPairFields()
/// (sim/io/correlation_report.hpp).

#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/core/errors.hpp"

namespace mmv {

template <class Row>
struct Field {
  const char* key;
  const char* unit;        ///< "Hz", "kg", "1" (a ratio), "" (text, a flag, a count, a table).
  const char* csv_format;  ///< printf format of its CSV column (%s: text); nullptr: JSON only.
  const char* meaning;     ///< one line, for the docs and Python.
  /// The value; nullopt: not part of this row's record; a JSON null: defined but undefined.
  std::optional<nlohmann::ordered_json> (*get)(const Row&);
};

/// One CSV cell: flags as 1/0, text escaped (csvEscape), an integer as it is, a number
/// in `format`, nothing (an absent or null value) as an empty cell.
std::string fieldCsvCell(const char* format, const std::optional<nlohmann::ordered_json>& value);

/// The record of `row`: every field that `has(field)` admits and the row holds, in order.
template <class F, class Row, class Has>
nlohmann::ordered_json fieldsJson(const std::vector<F>& fields, const Row& row, Has has) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& f : fields)
    if (has(f))
      if (auto v = f.get(row)) j[f.key] = std::move(*v);
  return j;
}

/// The value of field `key` of `row` (an internal error when the list has none): a text
/// table reads its cells through it, so it shows what the JSON and the CSV hold.
template <class F, class Row>
std::optional<nlohmann::ordered_json> fieldValue(const std::vector<F>& fields, const Row& row, const char* key) {
  for (const auto& f : fields)
    if (std::strcmp(f.key, key) == 0) return f.get(row);
  throw InternalError(std::string("no field '") + key + "' in the list");
}

/// The CSV header of the fields with a CSV format that `has(field)` admits ("a,b,c").
template <class F, class Has>
std::string fieldsCsvHeader(const std::vector<F>& fields, Has has) {
  std::string out;
  for (const auto& f : fields)
    if (f.csv_format && has(f)) out += (out.empty() ? "" : ",") + std::string(f.key);
  return out;
}

/// `row`'s cells under fieldsCsvHeader's columns ("1,2.5,,x"); `override(field)`, when it
/// returns a value, replaces the field's own (a row that says why it has no numbers).
template <class F, class Row, class Has, class Override>
std::string fieldsCsvRow(const std::vector<F>& fields, const Row& row, Has has, Override override) {
  std::string out;
  bool first = true;
  for (const auto& f : fields) {
    if (!f.csv_format || !has(f)) continue;
    const std::optional<nlohmann::ordered_json> mine = override(f);
    out += (first ? "" : ",") + fieldCsvCell(f.csv_format, mine ? mine : f.get(row));
    first = false;
  }
  return out;
}

/// A CSV table of `rows`: a column per field with a CSV format that `has(field)` admits.
template <class F, class Row, class Has>
std::string fieldsCsv(const std::vector<F>& fields, const std::vector<Row>& rows, Has has) {
  std::ostringstream os;
  os << fieldsCsvHeader(fields, has) << '\n';
  const auto none = [](const F&) { return std::optional<nlohmann::ordered_json>(); };
  for (const auto& row : rows) os << fieldsCsvRow(fields, row, has, none) << '\n';
  return os.str();
}

}  // namespace mmv
