#pragma once
/// The tables and accuracy statements of `mmvlab report`, made from the studies' JSON
/// documents: exactly what `check --json`, `modes --json`, `place-sensors --json` and
/// `frf --json` print, so the page and those commands cannot disagree.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/html_page.hpp"

namespace mmv {

/// check's lines: group, requirement, demand, capacity, unit, margin, verdict, basis (the
/// line's note). A row's class is its verdict.
html::Table checkTable(const nlohmann::ordered_json& check);
/// The mode table: frequency, its estimated discretization error, damping ratio (when
/// the scene is damped), where the strain and the kinetic energy are, effective masses.
html::Table modeTable(const nlohmann::ordered_json& modes);
/// The chosen sensors: station, link, position along it, axis, world position, score.
html::Table sensorTable(const nlohmann::ordered_json& placement);
/// Each input-output pair: peak, its half-power damping, level at 10 Hz, reduced-model error.
html::Table frfTable(const nlohmann::ordered_json& frf);

/// The article's strength (docs/strength.md): per link its static peak stress at the
/// held equilibrium (where, the allowable over its factor, the margin of safety, the
/// verdict; `modes --json`'s equilibrium.static_stress) and check's worst held and run
/// stress lines for it (demand and verdict). A row's class is its worst verdict.
html::Table strengthTable(const nlohmann::ordered_json& modes, const nlohmann::ordered_json& check);
std::vector<std::string> strengthAccuracy(const nlohmann::ordered_json& modes);

/// "How accurate" lines for each part, from the same documents.
std::vector<std::string> checkAccuracy(const nlohmann::ordered_json& check);
std::vector<std::string> modesAccuracy(const nlohmann::ordered_json& modes);
std::vector<std::string> placementAccuracy(const nlohmann::ordered_json& placement);
std::vector<std::string> frfAccuracy(const nlohmann::ordered_json& frf);

/// A check verdict's CSS class on the page: pass, warn, fail, info, advisory, na.
std::string verdictClass(const std::string& verdict);

/// A number as the page prints it: 4 significant digits ("-" for null or not finite).
std::string reportNumber(const nlohmann::ordered_json& v, double scale = 1.0);
/// A relative error as the page prints it: "0.18 %", or "< 0.001 %".
std::string reportPercent(double e);
/// A JSON value as text: a string as it is, null as "-", anything else as JSON.
std::string reportText(const nlohmann::ordered_json& v);
/// The largest share of a {name: share} object, as "name (42 %)".
std::string reportLargestShare(const nlohmann::ordered_json& shares);

/// HAM-SAS (sim/io/review_hamsas.cpp), from `modes --json` and `frf --json` of an
/// isolator scene: the measured features against the model; the modes (frequency, the
/// body group and direction with most kinetic energy, the largest kinetic and strain
/// shares, gravity's share); per direction the table-from-ground transmissibility's
/// peak and its level at 10 Hz against the 70-80 dB goal; their accuracy lines.
html::Table hamsasFeatureTable(const nlohmann::ordered_json& modes);
html::Table hamsasModeTable(const nlohmann::ordered_json& modes);
html::Table transmissibilityTable(const nlohmann::ordered_json& frf);
std::vector<std::string> hamsasModesAccuracy(const nlohmann::ordered_json& modes);
std::vector<std::string> transmissibilityAccuracy(const nlohmann::ordered_json& frf);

}  // namespace mmv
