#include "sim/io/placement_geometry.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace mmv {

namespace {
using json = nlohmann::ordered_json;
using Opt = std::optional<json>;
}  // namespace

std::vector<PlacementChannel> placementChannels(const PlacementStudy& s) {
  std::vector<char> kept(s.candidates.size(), 0);
  for (int b : s.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  std::vector<PlacementChannel> out;
  for (const auto& d : s.directions)
    if (kept[static_cast<std::size_t>(d.block)])
      out.push_back({static_cast<int>(out.size()) + 1, &s.candidates[static_cast<std::size_t>(d.block)], &d});
  return out;
}

const std::vector<Field<PlacementChannel>>& placementChannelFields() {
  using C = PlacementChannel;
  // clang-format off
  static const std::vector<Field<C>> fields{
      {"channel", "", "%d", "the acquisition channel (1: the first chosen direction)", [](const C& c) -> Opt { return json(c.channel); }},
      {"node", "", "%d", "its test-geometry node (link position x 100000 + mm from the root; HAM-SAS: body x 100 + 0 for the mass centre, 1-8 for a corner)",
       [](const C& c) -> Opt { return json(c.candidate->node); }},
      {"station", "", "%s", "the station, <link>@<m>m (HAM-SAS: <body>.com or <body>.corner<k>)", [](const C& c) -> Opt { return json(c.candidate->station); }},
      {"link", "", "%s", "the link it is on (HAM-SAS: the body)", [](const C& c) -> Opt { return json(c.candidate->link); }},
      {"axis", "", "%s", "axial, transverse or normal (of the link at the station; HAM-SAS: world x, y or z)", [](const C& c) -> Opt { return json(c.direction->axis); }},
      {"direction_x", "1", "%.6f", "the measuring axis, world x component", [](const C& c) -> Opt { return json(c.direction->world[0]); }},
      {"direction_y", "1", "%.6f", "the measuring axis, world y component", [](const C& c) -> Opt { return json(c.direction->world[1]); }},
      {"direction_z", "1", "%.6f", "the measuring axis, world z component", [](const C& c) -> Opt { return json(c.direction->world[2]); }},
      {"quantity", "", "%s", "what it measures: acceleration, or strain (a gauge or film, --strain-span; its station A:B, or A:B:out for the +z face's bending out of the plane (spatial model), its node the span's middle, its direction the link's axis there)",
       [](const C& c) -> Opt { return json(c.direction->axis == "strain" ? "strain" : "acceleration"); }},
      {"unit", "", "%s", "of the reading: m/s^2, or m/m", [](const C& c) -> Opt { return json(c.direction->axis == "strain" ? "m/m" : "m/s^2"); }},
      {"sensitivity_mv_per_unit", "mV/(m/s^2)", "%.6g", "the sensor's calibration, for the lab to fill (empty)",
       [](const C&) -> Opt { return json(nullptr); }},
      {"serial", "", "%s", "the sensor's serial number, for the lab to fill (empty)", [](const C&) -> Opt { return json(nullptr); }},
  };
  // clang-format on
  return fields;
}

std::string placementChannelsCsv(const PlacementStudy& s) {
  return fieldsCsv(placementChannelFields(), placementChannels(s), [](const auto&) { return true; });
}

uff::File placementGeometry(const PlacementStudy& s, const std::string& scene_name) {
  uff::File f;
  f.model_name = scene_name;
  f.description = "mmvlab place-sensors: the chosen sensors' stations and the target modes' predicted shapes";
  std::map<int, const PlacementCandidate*> stations;  // by node: a uniaxial station's directions share it
  for (const auto& c : placementChannels(s)) stations[c.candidate->node] = c.candidate;
  std::map<std::string, std::vector<const PlacementCandidate*>> by_link;
  for (const auto& [node, c] : stations) {
    f.nodes.push_back({node, {c->world_x, c->world_y, c->world_z}});
    by_link[c->link].push_back(c);
  }
  int trace = 0;
  for (auto& [link, list] : by_link) {
    std::sort(list.begin(), list.end(), [](const auto* a, const auto* b) { return std::tie(a->x_m, a->node) < std::tie(b->x_m, b->node); });
    uff::TraceLine t{++trace, link, {}};
    for (const auto* c : list) t.nodes.push_back(c->node);
    if (t.nodes.size() >= 2) f.trace_lines.push_back(t);
  }
  for (std::size_t j = 0; j < s.target_modes.size(); ++j) {
    uff::ModeShape m;
    m.mode = s.target_modes[j].number();
    m.frequency_hz = s.target_frequencies_hz[j];
    m.modal_mass = 1.0;
    for (const auto& [node, c] : stations) {
      m.nodes.push_back(node);
      m.translations.push_back(c->shape[j]);
    }
    f.modes.push_back(m);
  }
  return f;
}

}  // namespace mmv
