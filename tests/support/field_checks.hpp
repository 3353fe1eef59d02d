#pragma once
// What the field-list tests share: a CSV line's cells, a format's precision, a CSV row
// against its JSON record, a header against a list's keys.
#include <gtest/gtest.h>

#include <cmath>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/core/text.hpp"

namespace mmv::field_checks {

using json = nlohmann::ordered_json;

inline std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

/// The relative precision a printf format keeps ("%.8g": 8 significant digits).
inline double precisionOf(const char* format) {
  const std::string f = format;
  const auto dot = f.find('.');
  return dot == std::string::npos ? 0.0 : 0.6 * std::pow(10.0, -std::stoi(f.substr(dot + 1)) + 1);
}

/// Each of `cells` from `first` on is record `rec`'s value under `columns`, to the
/// printed digits (`rel` relative, `abs` for "%.6f" columns).
inline void expectCellsAreTheRecord(const std::vector<std::string>& cells, std::size_t first, const std::vector<std::string>& columns,
                             const json& rec, double rel, double abs = 1e-300) {
  ASSERT_EQ(cells.size(), first + columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::string& cell = cells[first + c];
    if (!rec.contains(columns[c]) || rec[columns[c]].is_null()) {
      EXPECT_EQ(cell, "") << columns[c];
      continue;
    }
    const json& v = rec[columns[c]];
    if (v.is_boolean()) EXPECT_EQ(cell, v.get<bool>() ? "1" : "0") << columns[c];
    else if (v.is_string()) EXPECT_EQ(cell, csvEscape(v.get<std::string>())) << columns[c];
    else if (v.is_number_integer()) EXPECT_EQ(std::stol(cell), v.get<long>()) << columns[c];
    else EXPECT_NEAR(std::stod(cell), v.get<double>(), rel * std::abs(v.get<double>()) + abs) << columns[c];
  }
}

/// Reads the CSV's header and expects it to be `fields`' keys, in order; returns them.
template <class Fields>
std::vector<std::string> headerIsTheFieldKeys(std::istream& csv, const Fields& fields) {
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> columns;
  for (const auto& f : fields) columns.push_back(f.key);
  EXPECT_EQ(splitCsvLine(line), columns);
  return columns;
}

/// The keys of `fields` that have a CSV column.
template <class Fields>
std::vector<std::string> csvKeys(const Fields& fields) {
  std::vector<std::string> keys;
  for (const auto& f : fields)
    if (f.csv_format) keys.push_back(f.key);
  return keys;
}

}  // namespace mmv::field_checks
