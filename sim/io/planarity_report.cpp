// The planarity section of `modes` on the spatial article: text and JSON.
#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace mmv {

std::string planarityText(const PlanarityReport& p) {
  std::string os = strf("\nPlanarity: modes in %.1f-%.0f Hz that leave the plane of motion (%d in-plane, %zu others in the band%s)\n",
                        p.band_low_hz, p.band_high_hz, p.in_plane_in_band, p.others.size(),
                        p.covers_band ? "" : strf("; modes solved only up to %.3g Hz", p.solved_up_to_hz).c_str());
  if (p.others.empty()) {
    os += "  none: every mode in the band bends the article in its plane\n";
  } else {
    os += "  shares: the mode's strain energy in-plane / out-of-plane / torsion; nearest: the closest in-plane mode\n";
    Table t({"mode", "frequency_Hz", "family", "in/out/torsion_%", "nearest_in_plane", "separation_%"});
    for (const auto& m : p.others)
      t.add({std::to_string(m.number.number()), strf("%.4f", m.frequency_hz), m.family.label,
             strf("%.0f/%.0f/%.0f", 100 * m.family.in_plane, 100 * m.family.out_of_plane, 100 * m.family.torsion),
             m.nearest_in_plane ? strf("%d (%.4f Hz)", m.nearest_in_plane->number(), m.nearest_hz) : "-",
             m.nearest_in_plane ? strf("%+.2f", m.separation_pct) : "-"});
    os += t.text();
  }
  if (!p.responses.empty()) {
    os += "Response out of the plane under each excitation, at the link tips: peak resonant response along the\n"
          "  plane's normal over that in the plane, equal modal damping in the band (decoupled: below 1e-9)\n";
    Table t({"excitation", "point", "out/in", "out_mode", "in_mode"});
    for (std::size_t i = 0; i < p.responses.size();) {
      std::size_t end = i;  // the excitation's rows
      bool all_decoupled = true;
      for (; end < p.responses.size() && p.responses[end].excitation == p.responses[i].excitation; ++end)
        all_decoupled = all_decoupled && p.responses[end].decoupled;
      if (all_decoupled) {
        t.add({p.responses[i].excitation, "every tip", "decoupled", "-", "-"});
      } else {
        for (std::size_t k = i; k < end; ++k) {
          const auto& r = p.responses[k];
          t.add({r.excitation, r.point, r.decoupled ? std::string("decoupled") : strf("%.3g", r.ratio),
                 r.decoupled ? "-" : std::to_string(r.out_mode.number()), std::to_string(r.in_mode.number())});
        }
      }
      i = end;
    }
    os += t.text();
  }
  return os;
}

nlohmann::ordered_json planarityJson(const PlanarityReport& p) {
  using json = nlohmann::ordered_json;
  json others = json::array();
  for (const auto& m : p.others)
    others.push_back({{"mode", m.number.number()},
                      {"frequency_hz", m.frequency_hz},
                      {"family", m.family.label},
                      {"strain_share", {{"in_plane", m.family.in_plane}, {"out_of_plane", m.family.out_of_plane}, {"torsion", m.family.torsion}}},
                      {"nearest_in_plane_mode", m.nearest_in_plane ? json(m.nearest_in_plane->number()) : json(nullptr)},
                      {"nearest_in_plane_hz", m.nearest_in_plane ? json(m.nearest_hz) : json(nullptr)},
                      {"separation_percent", m.nearest_in_plane ? json(m.separation_pct) : json(nullptr)}});
  json responses = json::array();
  for (const auto& r : p.responses)
    responses.push_back({{"excitation", r.excitation},
                         {"point", r.point},
                         {"out_of_plane_over_in_plane", r.ratio},
                         {"decoupled", r.decoupled},
                         {"out_of_plane_mode", r.out_mode.number()},
                         {"in_plane_mode", r.in_mode.number()}});
  return {{"band_hz", {p.band_low_hz, p.band_high_hz}},
          {"covers_band", p.covers_band},
          {"solved_up_to_hz", p.solved_up_to_hz},
          {"plane_normal", {p.normal[0], p.normal[1], p.normal[2]}},
          {"in_plane_modes_in_band", p.in_plane_in_band},
          {"other_modes_in_band", others},
          {"responses", responses}};
}

}  // namespace mmv
