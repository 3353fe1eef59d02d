#pragma once
/// The per-mode quantities of `modes`, described once (in the style of Drake's
/// `Serialize`): each field's key (its key in modes.json's `modes[]` and its column in
/// modes.csv), unit, meaning and how it is read from a mode. modes.json's mode records,
/// modes.csv, the Python module's `ModesResult.table()` and the field table of
/// docs/outputs.md all come from this list, so they cannot disagree
/// (tests/sim/io/fields_test.cpp, python/tests).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/fields.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

struct ModeField {
  enum class Applies { Always, Spatial, Damped };
  const char* key;
  const char* unit;        ///< "Hz", "kg", "1" (a ratio), "" (text, a flag, a count, a table).
  const char* csv_format;  ///< printf format of its modes.csv column (%s: text); nullptr: JSON only (a table).
  Applies applies;         ///< which reports have it (JSON key and CSV column).
  const char* meaning;     ///< one line, for the docs and Python.
  /// The value; nullopt: not part of this mode's record (the damping of an unstable
  /// mode); a JSON null: defined but undefined (an unstable mode's frequency).
  std::optional<nlohmann::ordered_json> (*get)(const ModeInfo&);
};

/// Every per-mode field, in the order of modes.json and modes.csv.
const std::vector<ModeField>& modeFields();
/// True when report `r` has field `f` (spatial fields in a spatial report, damping in a damped one).
bool modeFieldApplies(const ModeField& f, const ModesReport& r);
/// The fields of mode `m` of `r` as a JSON object, in the list's order.
nlohmann::ordered_json modeFieldsJson(const ModesReport& r, const ModeInfo& m);
/// modes.csv: a column per field with a CSV format that `r` has; flags as 1/0, an
/// undefined value (null or absent) as an empty cell.
std::string modesCsv(const ModesReport& r);

}  // namespace mmv
