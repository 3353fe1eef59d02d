#pragma once
/// Writers for a speed-accuracy trade (sim/time/trade.hpp): the table as text, JSON
/// and CSV (docs/outputs.md), each naming the cheapest run within `target` (m).

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "sim/io/fields.hpp"
#include "sim/time/trade.hpp"

namespace mmv {

std::string tradeText(const TradeStudy& s, double target_m);
nlohmann::ordered_json tradeJson(const TradeStudy& s, double target_m);
/// trade.csv: a row per run, a column per field of tradeRunFields().
std::string tradeCsv(const TradeStudy& s);
/// The fields of a run, in the order of trade.json's runs and trade.csv's columns.
const std::vector<Field<TradeRun>>& tradeRunFields();

}  // namespace mmv
