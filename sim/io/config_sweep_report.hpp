#pragma once
/// Writers for a configuration sweep (sim/modes/config_sweep.hpp): one CSV row per grid point,
/// the text table, JSON (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/modes/config_sweep.hpp"

namespace mmv {

std::string configSweepCsv(const ConfigSweepResult& r);
std::string configSweepText(const ConfigSweepResult& r);
nlohmann::ordered_json configSweepJson(const ConfigSweepResult& r);

}  // namespace mmv
