#include "sim/io/compare_fields.hpp"

#include <string>

namespace mmv {

namespace {
using json = nlohmann::ordered_json;
using Opt = std::optional<json>;
Opt jsonText(const std::string& s) { return json(s); }
Opt unlessEmpty(const std::string& s) { return s.empty() ? Opt() : Opt(json(s)); }
}  // namespace

const std::vector<Field<SystemModeRow>>& systemModeFields() {
  using R = SystemModeRow;
  // clang-format off
  static const std::vector<Field<R>> fields{
      {"mode", "", "%d", "the system mode (1: the lowest)", [](const R& m) -> Opt { return json(m.mode); }},
      {"stable", "", nullptr, "a positive stiffness (omega^2 > 0)", [](const R& m) -> Opt { return json(m.stable); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency (null: unstable)",
       [](const R& m) -> Opt { return m.stable ? json(m.frequency_hz) : json(nullptr); }},
      {"strain_link", "", "%s", "the link with the most strain energy", [](const R& m) { return jsonText(m.strain_link); }},
      {"strain_share", "1", "%.6f", "that link's share of the strain energy", [](const R& m) -> Opt { return json(m.strain_share); }},
      {"kinetic_link", "", "%s", "the link with the most kinetic energy", [](const R& m) { return jsonText(m.kinetic_link); }},
      {"kinetic_share", "1", "%.6f", "that link's share of the kinetic energy", [](const R& m) -> Opt { return json(m.kinetic_share); }},
      {"nearest_component_mode", "", "%d", "the strain link's component mode nearest in frequency (0: none)",
       [](const R& m) -> Opt { return json(m.component_mode ? m.component_mode->number() : 0); }},
      {"nearest_component_frequency_hz", "Hz", "%.8g", "that component mode's frequency",
       [](const R& m) -> Opt { return json(m.component_hz); }},
      {"system_over_component_minus_1", "1", "%.6g", "frequency_hz / nearest_component_frequency_hz - 1",
       [](const R& m) -> Opt { return json(m.component_difference); }},
      {"family", "", "%s", "the spatial model's family: in-plane, out-of-plane, torsion or mixed",
       [](const R& m) { return unlessEmpty(m.family); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<SynthesisRowView>>& synthesisFields() {
  using V = SynthesisRowView;
  // clang-format off
  static const std::vector<Field<V>> fields{
      {"method", "", "%s", "the synthesis (assumed modes or Craig-Bampton, with its boundary condition and modes)",
       [](const V& v) { return jsonText(v.method->method); }},
      {"mode", "", "%d", "the full model's mode", [](const V& v) -> Opt { return json(v.row->mode); }},
      {"full_frequency_hz", "Hz", "%.8g", "its frequency", [](const V& v) -> Opt { return json(v.row->full_hz); }},
      {"synthesized_mode", "", "%d", "the synthesized mode that matches it best (by MAC)",
       [](const V& v) -> Opt { return json(v.row->synth_mode); }},
      {"synthesized_frequency_hz", "Hz", "%.8g", "that mode's frequency", [](const V& v) -> Opt { return json(v.row->synth_hz); }},
      {"relative_error", "1", "%.6g", "synthesized_frequency_hz / full_frequency_hz - 1",
       [](const V& v) -> Opt { return json(v.row->relative_error); }},
      {"mac", "1", "%.6f", "MAC of the two shapes at the named points", [](const V& v) -> Opt { return json(v.row->mac); }},
      {"verdict", "", "%s", "predicted, shifted or missed", [](const V& v) { return jsonText(v.row->verdict); }},
      {"dominant_link", "", "%s", "the link with the most strain energy in the full mode",
       [](const V& v) { return jsonText(v.row->dominant_link); }},
      {"family", "", nullptr, "the spatial model's family of the full mode", [](const V& v) { return unlessEmpty(v.row->family); }},
  };
  // clang-format on
  return fields;
}

}  // namespace mmv
