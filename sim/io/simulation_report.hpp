#pragma once
/// Writers for time runs (sim/time/simulation.hpp, and the isolator's): the summary as
/// text and JSON (docs/outputs.md), the sampled history as CSV, and the warnings a
/// run's numbers call for.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "sim/io/fields.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/target.hpp"

namespace mmv {

/// The warnings about a finished run: saturated sensors, torques above capacity, the
/// energy balance, closure drift (against `article_size_m`, 0 for none), table payload.
std::vector<std::string> simulationWarnings(const SimulationResult& r, double article_size_m);
std::string simulationText(const std::string& scene_name, const std::string& scene_source, const SimulationResult& r,
                           const std::vector<std::string>& warnings);
nlohmann::ordered_json simulationJson(const SimulationResult& r, const std::vector<std::string>& warnings);
/// `simulate --target-error`: what the pilot found, each whole run verified, the cost.
std::string targetText(const TargetOutcome& t);
nlohmann::ordered_json targetJson(const TargetOutcome& t);
/// The summary's per-joint and per-sensor rows (summary.json's torques and sensors, the
/// text tables' values, Python's SimulateResult.torques_table() and sensors_table()).
/// JSON only: a run's CSV is its history.
const std::vector<Field<JointTorqueSummary>>& jointTorqueFields();
const std::vector<Field<SensorSummary>>& sensorSummaryFields();
/// Each link's stress over the run (summary.json's stress, the text table, Python's
/// SimulateResult.stress_table()).
const std::vector<Field<LinkRunStress>>& linkRunStressFields();
/// history.csv: one header row (names with units), one row per sample, %.10g.
std::string simulationHistoryCsv(const SimulationRecord& rec);

}  // namespace mmv
