#pragma once
/// Writers for the component-versus-system comparison (sim/modes/compare.hpp): the report as
/// aligned text or Markdown (written once, sim/core/text.hpp), JSON (docs/outputs.md), and
/// CSV files with units in the headers.

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "sim/modes/compare.hpp"

namespace mmv {

std::string formatCompareText(const CompareReport& r);
std::string formatCompareMarkdown(const CompareReport& r);
nlohmann::ordered_json compareToJson(const CompareReport& r);
/// (file name, contents) of every CSV file.
std::vector<std::pair<std::string, std::string>> compareCsvFiles(const CompareReport& r);

}  // namespace mmv
