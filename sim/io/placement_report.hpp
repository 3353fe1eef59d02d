#pragma once
/// Writers for a sensor placement (sim/modes/place_sensors.hpp): the chosen set as a
/// text table and JSON, every candidate as CSV, the AutoMAC as CSV (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>

#include "sim/io/fields.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// One candidate block as candidates.csv and placement.json's chosen records see it.
struct PlacementRow {
  const PlacementCandidate* candidate = nullptr;
  bool chosen = false;
  double score = 0;  ///< its block's score, when chosen.
};
/// The per-candidate fields (sim/io/fields.hpp): candidates.csv's columns and, less
/// `chosen`, placement.json's `chosen` records, in this order.
const std::vector<Field<PlacementRow>>& placementFields();
/// Every candidate block, in candidate order, with whether and how it was chosen.
std::vector<PlacementRow> placementRows(const PlacementStudy& s);

std::string placementText(const PlacementStudy& s);
nlohmann::ordered_json placementJson(const PlacementStudy& s);
/// candidates.csv: a row per candidate, a column per placementFields() field.
std::string placementCandidatesCsv(const PlacementStudy& s);
/// automac.csv: the target modes' AutoMAC as the chosen set sees it.
std::string placementAutoMacCsv(const PlacementStudy& s);
/// The pairs of target modes the set cannot tell apart (AutoMAC above 0.9).
std::vector<std::pair<int, int>> indistinguishableModes(const PlacementStudy& s);

}  // namespace mmv
