#pragma once
/// Writers for a speed-accuracy trade (sim/time/trade.hpp): the table as text, JSON
/// and CSV (docs/outputs.md), each naming the cheapest run within `target` (m).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/time/trade.hpp"

namespace mmv {

std::string tradeText(const TradeStudy& s, double target_m);
nlohmann::ordered_json tradeJson(const TradeStudy& s, double target_m);
std::string tradeCsv(const TradeStudy& s);

}  // namespace mmv
