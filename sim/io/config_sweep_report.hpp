#pragma once
/// Writers for a configuration sweep (sim/modes/config_sweep.hpp): one CSV row per grid point,
/// the text table, JSON (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/io/fields.hpp"
#include "sim/modes/config_sweep.hpp"

namespace mmv {

/// A tracked mode's fields at a point: sweep.csv's columns after JOINT_deg, point_kind and
/// track, and the JSON's `points[].tracks[]` records, from this one list.
const std::vector<Field<TrackPoint>>& trackFields();
/// sweep.csv: a row per point and track (an unsolved point: one row, its verdict saying why).
std::string configSweepCsv(const ConfigSweepResult& r);
std::string configSweepText(const ConfigSweepResult& r);
nlohmann::ordered_json configSweepJson(const ConfigSweepResult& r);

}  // namespace mmv
