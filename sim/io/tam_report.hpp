#pragma once
/// Writers for the test-analysis models of a placement (sim/modes/tam.hpp): per target
/// mode its checks, from one field list (tamModeFields: placement.json's tam records,
/// tam.csv, the text table's values, Python's PlacementResult.tam_table()).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/fields.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// One target mode's checks under one TAM.
struct TamModeRow {
  const TamResult* tam = nullptr;
  std::size_t j = 0;  ///< the target's position
  ModeNumber mode{1};
  double frequency_hz = 0;
};
std::vector<TamModeRow> tamModeRows(const PlacementStudy& s);
/// method (tam.csv only: the JSON nests the rows under it), mode, frequency_hz, tam_mode,
/// tam_frequency_hz, frequency_error, self_diagonal, self_off_diagonal, cross_diagonal,
/// cross_off_diagonal, pass, reason.
const std::vector<Field<TamModeRow>>& tamModeFields();

/// placement.json's "tam": the sensor directions, the criteria and each model.
nlohmann::ordered_json tamJson(const PlacementStudy& s);
/// The text section (empty without TAMs).
std::string tamText(const PlacementStudy& s);
/// tam.csv: a row per model and target mode.
std::string tamCsv(const PlacementStudy& s);

/// tam.mat: the TAMs for the lab's correlation tools and for `correlate --tam`:
///   Method (cell: guyan, irs, serep as built), M_<method>, K_<method> (a x a, over the
///   channels), T_<method> (n x a: the model's coordinates per channel reading);
///   Channel (cell: "station axis"), ChannelNode (a x 1: test-geometry node numbers),
///   ChannelDirection (a x 3: world unit vectors), TargetMode (1 x m),
///   TargetFrequencyHz (1 x m), PhiA (a x m: the mass-normalised target modes at the
///   channels).
MatContents tamMat(const PlacementStudy& s);

}  // namespace mmv
