#pragma once
/// Writers for analysis results: readable text tables (units in headers) and JSON
/// (schema in docs/outputs.md, snake_case keys with units in names).

#include <nlohmann/json.hpp>
#include <string>

#include "sim/modes/system_modes.hpp"

namespace mmv {

struct ConvergenceStudy;  // sim/modes/converge.hpp

std::string formatModesText(const ModesReport& r);
nlohmann::ordered_json modesToJson(const ModesReport& r);

/// The discretization error block of `modes` (empty when not asked for).
std::string discretizationText(const DiscretizationEstimate& d);
std::string segmentsChoiceText(const SegmentsChoice& c);
nlohmann::ordered_json segmentsChoiceJson(const SegmentsChoice& c);
nlohmann::ordered_json discretizationJson(const DiscretizationEstimate& d);

/// The static stress block (docs/strength.md): every link's peak stress at the
/// equilibrium, where, its allowable with the factor and the margin of safety.
std::string staticStressText(const std::vector<LinkStaticStress>& links, const StrengthFactors& f);
nlohmann::ordered_json staticStressJson(const std::vector<LinkStaticStress>& links, const StrengthFactors& f);

/// The spatial model's planarity section of `modes` (sim/modes/planarity.hpp).
std::string planarityText(const PlanarityReport& p);
nlohmann::ordered_json planarityJson(const PlanarityReport& p);

std::string formatConvergenceText(const ConvergenceStudy& c);
nlohmann::ordered_json convergenceToJson(const ConvergenceStudy& c);

/// modes.csv: sim/io/mode_fields.hpp (modesCsv), from the one list of per-mode fields;
/// converge.csv: sim/io/convergence_fields.hpp (convergenceCsv).

/// The version stamped into every JSON document.
const char* mmvlabVersion();

}  // namespace mmv
