#pragma once
/// Writers of `mmvlab check` (sim/plan/check.hpp): an aligned text table, JSON, and
/// Markdown for a review pack.

#include <nlohmann/json.hpp>
#include <string>

#include "sim/plan/check.hpp"

namespace mmv {

std::string checkText(const CheckReport& r);
nlohmann::ordered_json checkJson(const CheckReport& r);
std::string checkMarkdown(const CheckReport& r);

}  // namespace mmv
