#include "sim/io/mode_fields.hpp"

#include <cmath>

#include "sim/core/text.hpp"

namespace mmv {
namespace {

using json = nlohmann::ordered_json;
using Opt = std::optional<json>;

json shares(const std::vector<PartShare>& v) {
  json o = json::object();
  for (const auto& s : v) o[s.part] = s.fraction;
  return o;
}

bool damped(const ModeInfo& m) { return m.stable && !m.rigid_body && m.has_damping; }

}  // namespace

const std::vector<ModeField>& modeFields() {
  using A = ModeField::Applies;
  // clang-format off
  static const std::vector<ModeField> fields{
      {"number", "", "%d", A::Always, "mode number, 1-based, by frequency",
       [](const ModeInfo& m) -> Opt { return json(m.number); }},
      {"stable", "", "%d", A::Always, "false: the equilibrium is unstable in this mode (omega^2 < 0)",
       [](const ModeInfo& m) -> Opt { return json(m.stable); }},
      {"rigid_body", "", "%d", A::Always, "a mechanism: zero frequency up to round-off",
       [](const ModeInfo& m) -> Opt { return json(m.rigid_body); }},
      {"frequency_hz", "Hz", "%.10g", A::Always, "undamped natural frequency (null for an unstable mode)",
       [](const ModeInfo& m) -> Opt { return m.stable ? json(m.frequency_hz) : json(nullptr); }},
      {"omega_squared_rad2_per_s2", "rad^2/s^2", "%.10g", A::Always, "eigenvalue of K phi = omega^2 M phi",
       [](const ModeInfo& m) -> Opt { return json(m.omega2); }},
      {"modal_mass_kg", "kg", "%.8g", A::Always, "modal mass of the shape scaled to 1 m at peak_point",
       [](const ModeInfo& m) -> Opt { return json(m.modal_mass_kg); }},
      {"peak_point", "", "%s", A::Always, "the point that moves most",
       [](const ModeInfo& m) -> Opt { return json(m.peak_point); }},
      {"effective_mass_x_kg", "kg", "%.8g", A::Always, "effective mass for base motion along x",
       [](const ModeInfo& m) -> Opt { return json(m.effective_mass_x_kg); }},
      {"effective_mass_y_kg", "kg", "%.8g", A::Always, "effective mass for base motion along y",
       [](const ModeInfo& m) -> Opt { return json(m.effective_mass_y_kg); }},
      {"geometric_stiffness_share", "1", "%.6g", A::Always, "share of omega^2 from gravity's geometric stiffness",
       [](const ModeInfo& m) -> Opt { return json(m.geometric_stiffness_share); }},
      {"dominant_link_kinetic", "", "%s", A::Always, "the link with the most kinetic energy",
       [](const ModeInfo& m) -> Opt { return json(m.dominant_link_kinetic); }},
      {"dominant_link_strain", "", "%s", A::Always, "the link with the most strain energy",
       [](const ModeInfo& m) -> Opt { return json(m.dominant_link_strain); }},
      {"kinetic_energy_share", "1", nullptr, A::Always, "kinetic energy share by part (links, torquers, tip masses)",
       [](const ModeInfo& m) -> Opt { return shares(m.kinetic); }},
      {"strain_energy_share", "1", nullptr, A::Always, "strain energy share by part",
       [](const ModeInfo& m) -> Opt { return shares(m.strain); }},
      {"kinetic_energy_share_by_link", "1", nullptr, A::Always, "kinetic energy share by link",
       [](const ModeInfo& m) -> Opt { return shares(m.kinetic_by_link); }},
      {"strain_energy_share_by_link", "1", nullptr, A::Always, "strain energy share by link",
       [](const ModeInfo& m) -> Opt { return shares(m.strain_by_link); }},
      {"effective_mass_z_kg", "kg", "%.8g", A::Spatial, "effective mass for base motion along z (spatial model)",
       [](const ModeInfo& m) -> Opt { return json(m.effective_mass_z_kg); }},
      {"family", "", "%s", A::Spatial, "in-plane, out-of-plane, torsion, mixed or rigid (spatial model)",
       [](const ModeInfo& m) -> Opt { return json(m.family.label); }},
      {"strain_share_by_axis", "1", nullptr, A::Spatial, "strain energy in the plane, out of it and in torsion",
       [](const ModeInfo& m) -> Opt {
         return json{{"in_plane", m.family.in_plane}, {"out_of_plane", m.family.out_of_plane}, {"torsion", m.family.torsion}};
       }},
      {"growth_rate_per_s", "1/s", "%.8g", A::Always, "sqrt(-omega^2) of an unstable mode (absent when stable)",
       [](const ModeInfo& m) -> Opt { return m.stable ? Opt() : Opt(json(std::sqrt(-m.omega2))); }},
      {"damping_ratio", "1", "%.6g", A::Damped, "damping ratio of the damped eigenvalue belonging to the mode",
       [](const ModeInfo& m) -> Opt { return damped(m) ? Opt(json(m.damping_ratio)) : Opt(); }},
      {"damped_natural_frequency_hz", "Hz", "%.10g", A::Damped, "|lambda| / 2 pi of that eigenvalue",
       [](const ModeInfo& m) -> Opt { return damped(m) ? Opt(json(m.damped_natural_hz)) : Opt(); }},
  };
  // clang-format on
  return fields;
}

bool modeFieldApplies(const ModeField& f, const ModesReport& r) {
  switch (f.applies) {
    case ModeField::Applies::Always: return true;
    case ModeField::Applies::Spatial: return r.spatial;
    case ModeField::Applies::Damped: return r.damped;
  }
  return false;
}

json modeFieldsJson(const ModesReport& r, const ModeInfo& m) {
  return fieldsJson(modeFields(), m, [&](const ModeField& f) { return modeFieldApplies(f, r); });
}

std::string modesCsv(const ModesReport& r) {
  return fieldsCsv(modeFields(), r.modes, [&](const ModeField& f) { return modeFieldApplies(f, r); });
}


}  // namespace mmv
