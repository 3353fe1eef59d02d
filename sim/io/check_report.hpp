#pragma once
/// Writers of `mmvlab check` (sim/plan/check.hpp): an aligned text table, JSON, CSV and
/// Markdown for a review pack. check.json's lines and check.csv come from one field list.

#include <nlohmann/json.hpp>
#include <string>

#include "sim/io/fields.hpp"
#include "sim/plan/check.hpp"

namespace mmv {

std::string checkText(const CheckReport& r);
nlohmann::ordered_json checkJson(const CheckReport& r);
std::string checkMarkdown(const CheckReport& r);

/// The per-requirement fields (sim/io/fields.hpp): check.json's `lines` records, check.csv's
/// columns and the Python table (`CheckResult.table()`), in this order.
const std::vector<Field<CheckLine>>& checkLineFields();
/// check.csv: one row per requirement, a column per field.
std::string checkCsv(const CheckReport& r);

}  // namespace mmv
