#pragma once
/// Writers for the shaker's pre-test analysis (sim/linear/exciter.hpp), each from one
/// field list: exciterModeFields (placement.json's exciter.modes, exciter.csv, the text
/// table's values, Python's PlacementResult.exciter_table()) and exciterCandidateFields
/// (exciter.ranking, exciter_ranking.csv).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/fields.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/table_levels.hpp"

namespace mmv {

/// mode, frequency_hz, loaded_mode, loaded_hz, shift, mac, zeta, sine_force_n,
/// sine_limit, sine_acc, best_channel, sine_snr_db, channels_seen, sine_stroke_m,
/// random_snr_db, seen.
const std::vector<Field<ExciterStudy::Mode>>& exciterModeFields();
/// rank is the row's position; station, axis, node, direction, score, weakest_mode,
/// max_shift, loads.
struct RankedExciter {
  int rank = 0;
  const ExciterCandidate* c = nullptr;
};
const std::vector<Field<RankedExciter>>& exciterCandidateFields();

/// placement.json's "exciter": the shaker, its attachment, the criteria, the modes, the
/// random run and the first `ranked` candidates of the ranking.
nlohmann::ordered_json exciterJson(const ExciterStudy& e, std::size_t ranked = 10);
/// The text section.
std::string exciterText(const ExciterStudy& e);
/// exciter.csv (a row per target mode) and exciter_ranking.csv (every candidate).
std::string exciterCsv(const ExciterStudy& e);
std::string exciterRankingCsv(const ExciterStudy& e);

/// The base table's levels (sim/linear/table_levels.hpp), from tableLevelFields: mode,
/// frequency_hz, axis, table_acc, table_amplitude_m, limit, acc, best_channel, snr_db,
/// channels_seen, within_bandwidth, seen. placement.json's "table_levels" (the table's
/// stroke and bandwidth, the sensor's resolution and range, the modes) and the text section.
const std::vector<Field<TableLevels::Mode>>& tableLevelFields();
nlohmann::ordered_json tableLevelsJson(const TableLevels& t);
std::string tableLevelsText(const TableLevels& t);

}  // namespace mmv
