#pragma once
/// Field lists of `mmvlab compare` (sim/modes/compare.hpp): a system mode's row
/// (compare.json's system_modes, system_modes.csv, the text table) and a synthesized
/// mode's row (compare.json's synthesis modes, synthesis.csv, the text table).

#include <vector>

#include "sim/io/fields.hpp"
#include "sim/modes/compare.hpp"

namespace mmv {

/// mode, stable (JSON only), frequency_hz, strain_link, strain_share, kinetic_link,
/// kinetic_share, nearest_component_mode, nearest_component_frequency_hz,
/// system_over_component_minus_1, family (the spatial model's; absent when empty).
const std::vector<Field<SystemModeRow>>& systemModeFields();

/// A synthesized mode with its method.
struct SynthesisRowView {
  const SynthesisResult* method = nullptr;
  const SynthesisRow* row = nullptr;
};
/// method (synthesis.csv only: the JSON nests rows under it), mode, full_frequency_hz,
/// synthesized_mode, synthesized_frequency_hz, relative_error, mac, verdict,
/// dominant_link, family (JSON only; absent when empty).
const std::vector<Field<SynthesisRowView>>& synthesisFields();

}  // namespace mmv
