#pragma once
/// `mmvlab update`'s outputs (sim/linear/model_update.hpp): the text report, update.json,
/// parameters.csv, pairs.csv and iterations.csv. A parameter's and a pair's quantities are
/// each described once (updateParameterFields, updatePairFields: sim/io/fields.hpp) and
/// make the JSON records, the CSV columns and the text table's cells.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/fields.hpp"
#include "sim/linear/model_update.hpp"

namespace mmv {

const std::vector<Field<UpdatedParameter>>& updateParameterFields();
const std::vector<Field<UpdatePair>>& updatePairFields();

nlohmann::ordered_json updateJson(const ModelUpdateResult& r);
std::string updateText(const ModelUpdateResult& r);
std::string updateParametersCsv(const ModelUpdateResult& r);
std::string updatePairsCsv(const ModelUpdateResult& r);
/// iterations.csv: iteration, cost, damping, evaluations, then a column per parameter.
std::string updateIterationsCsv(const ModelUpdateResult& r);

}  // namespace mmv
