#pragma once
/// Writers for a configuration sweep (sim/modes/sweep.hpp): one CSV row per grid point,
/// the text table, JSON (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/modes/sweep.hpp"

namespace mmv {

std::string sweepCsv(const SweepResult& r);
std::string sweepText(const SweepResult& r);
nlohmann::ordered_json sweepJson(const SweepResult& r);

}  // namespace mmv
