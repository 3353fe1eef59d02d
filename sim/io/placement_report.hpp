#pragma once
/// Writers for a sensor placement (sim/modes/place_sensors.hpp): the chosen set as a
/// text table and JSON, every candidate as CSV, the AutoMAC as CSV (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/modes/place_sensors.hpp"

namespace mmv {

std::string placementText(const PlacementStudy& s);
nlohmann::ordered_json placementJson(const PlacementStudy& s);
/// candidates.csv: station, link, x_m, axis, world_x_m, world_y_m, chosen (0/1), score.
std::string placementCandidatesCsv(const PlacementStudy& s);
/// automac.csv: the target modes' AutoMAC as the chosen set sees it.
std::string placementAutoMacCsv(const PlacementStudy& s);
/// The pairs of target modes the set cannot tell apart (AutoMAC above 0.9).
std::vector<std::pair<int, int>> indistinguishableModes(const PlacementStudy& s);

}  // namespace mmv
