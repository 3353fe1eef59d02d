#include "sim/io/placement_report.hpp"
#include "sim/io/loading_report.hpp"
#include "sim/io/tam_report.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

constexpr double kIndistinguishable = 0.9;  ///< AutoMAC above which two modes look alike.

std::string conditionText(double c) { return std::isfinite(c) ? strf("%.3g", c) : "singular"; }

}  // namespace

std::vector<std::pair<int, int>> indistinguishableModes(const PlacementStudy& s) {
  std::vector<std::pair<int, int>> out;
  const Eigen::MatrixXd& mac = s.result.automac;
  for (Eigen::Index i = 0; i < mac.rows(); ++i)
    for (Eigen::Index j = i + 1; j < mac.cols(); ++j)
      if (mac(i, j) > kIndistinguishable) out.push_back({s.target_modes[i].number(), s.target_modes[j].number()});
  return out;
}

std::string placementText(const PlacementStudy& s) {
  std::ostringstream os;
  const PlacementResult& r = s.result;
  os << s.scene_name << ": " << r.kept_blocks.size()
     << (s.strain ? strf(" strain sensors (spans of %g m)", s.strain_span_m) : s.triaxial ? " triaxial blocks" : " uniaxial sensors") << " by "
     << s.method << " from " << s.candidates.size() << " candidates";
  if (!s.strain && !s.instrument.name.empty() && (s.instrument.name != "accelerometer" || s.instrument.mass_kg > 0))
    os << strf(" (instrument %s, %.4g g)", s.instrument.name.c_str(), 1e3 * s.instrument.mass_kg);
  os << "\n";
  if (s.requested > static_cast<int>(r.kept_blocks.size()))
    os << strf("warning: %zu of the %d asked for: resolving the separation%s left no more (lower it, or place more densely)\n",
               r.kept_blocks.size(), s.requested, s.strain ? " (films at least a span apart: they do not overlap)" : "");
  const bool iterated = s.loading && !s.loading->iterations.empty();
  os << (iterated ? "Target modes of the model carrying them (Hz):" : "Target modes (Hz):");
  for (std::size_t j = 0; j < s.target_modes.size(); ++j)
    os << strf(" %d (%.4g)", s.target_modes[j].number(), s.target_frequencies_hz[j]);
  os << "\n\n";
  Table t({"station", "axis", "x_m", "y_m", "z_m", s.method == "effective independence" ? "EfI" : "score"});
  for (std::size_t i = 0; i < r.kept_blocks.size(); ++i) {
    const PlacementCandidate& c = s.candidates[r.kept_blocks[i]];
    t.add({c.fixed ? c.station + " (scene's)" : c.station, c.axis, strf("%.4f", c.world_x), strf("%.4f", c.world_y), strf("%.4f", c.world_z), strf("%.4g", r.block_score[i])});
  }
  os << t.text();
  os << strf("\nFisher information: det %.4g, condition number %s; largest off-diagonal AutoMAC %.4f\n",
             r.fisher_determinant, conditionText(r.fisher_condition).c_str(), r.max_offdiagonal_mac);
  const auto alike = indistinguishableModes(s);
  if (alike.empty()) {
    os << "Every pair of target modes is told apart (AutoMAC <= " << kIndistinguishable << ")\n";
  } else {
    os << "Modes this set cannot tell apart (AutoMAC > " << kIndistinguishable << "):";
    for (const auto& [a, b] : alike) os << " " << a << "&" << b;
    os << "\n";
  }
  if (s.loading) os << loadingText(*s.loading);
  os << tamText(s);
  return os.str();
}

const std::vector<Field<PlacementRow>>& placementFields() {
  using Value = std::optional<nlohmann::ordered_json>;
  static const std::vector<Field<PlacementRow>> fields = {
      {"station", "", "%s", "the station, <link>@<m>m", [](const PlacementRow& r) -> Value { return r.candidate->station; }},
      {"link", "", "%s", "the link it is on", [](const PlacementRow& r) -> Value { return r.candidate->link; }},
      {"x_along_link_m", "m", "%.6g", "from the link's root, along it",
       [](const PlacementRow& r) -> Value { return r.candidate->x_m; }},
      {"axis", "", "%s", "axial, transverse, normal (spatial) or triaxial (a block)",
       [](const PlacementRow& r) -> Value { return r.candidate->axis; }},
      {"world_x_m", "m", "%.6g", "world x at the equilibrium", [](const PlacementRow& r) -> Value { return r.candidate->world_x; }},
      {"world_y_m", "m", "%.6g", "world y at the equilibrium", [](const PlacementRow& r) -> Value { return r.candidate->world_y; }},
      {"world_z_m", "m", "%.6g", "world z at the equilibrium", [](const PlacementRow& r) -> Value { return r.candidate->world_z; }},
      {"chosen", "", "%d", "1 when the set keeps it", [](const PlacementRow& r) -> Value { return r.chosen ? 1 : 0; }},
      {"score", "1", "%.6g",
       "its score when chosen: its EfI (its rows' effective independence summed, at the end), or the method's ranking value",
       [](const PlacementRow& r) -> Value {
         return r.chosen ? Value(nlohmann::ordered_json(r.score)) : std::nullopt;
       }},
      {"fixed", "", "%d", "1 for a scene accelerometer kept in advance (--keep-scene-sensors)",
       [](const PlacementRow& r) -> Value { return r.candidate->fixed ? 1 : 0; }},
  };
  return fields;
}

std::vector<PlacementRow> placementRows(const PlacementStudy& s) {
  std::vector<PlacementRow> rows(s.candidates.size());
  for (std::size_t b = 0; b < s.candidates.size(); ++b) rows[b].candidate = &s.candidates[b];
  for (std::size_t i = 0; i < s.result.kept_blocks.size(); ++i) {
    rows[s.result.kept_blocks[i]].chosen = true;
    rows[s.result.kept_blocks[i]].score = s.result.block_score[i];
  }
  return rows;
}

nlohmann::ordered_json placementJson(const PlacementStudy& s) {
  nlohmann::ordered_json j;
  const PlacementResult& r = s.result;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "place-sensors";
  j["scene"] = s.scene_name;
  j["method"] = s.method;
  j["sensor"] = s.strain ? "strain" : s.triaxial ? "triaxial" : "uniaxial";
  if (s.strain) j["strain_span_m"] = s.strain_span_m;
  if (s.strain)  // the strain instrument's figures, in its unit
    j["instrument"] = {{"name", s.instrument.name}, {"mass_kg", 0.0}, {"axes", 1}, {"range_m_per_m", s.instrument.spec.range},
                       {"resolution_m_per_m", s.instrument.spec.resolution}};
  else if (!s.instrument.name.empty())  // the article's (the isolator's sensors are not scene data)
    j["instrument"] = {{"name", s.instrument.name},           {"mass_kg", s.instrument.mass_kg},
                       {"axes", s.instrument.axes},           {"range_m_per_s2", s.instrument.spec.range},
                       {"resolution_m_per_s2", s.instrument.spec.resolution}};
  j["target_modes"] = nlohmann::ordered_json::array();
  for (const ModeNumber m : s.target_modes) j["target_modes"].push_back(m.number());
  j["target_frequencies_hz"] = s.target_frequencies_hz;
  j["candidates"] = s.candidates.size();
  j["requested"] = s.requested;  // the count asked for: the chosen list may be shorter (the separation)
  auto chosen = nlohmann::ordered_json::array();
  const std::vector<PlacementRow> rows = placementRows(s);
  const auto record = [](const Field<PlacementRow>& f) { return std::string(f.key) != "chosen"; };
  for (int b : r.kept_blocks) chosen.push_back(fieldsJson(placementFields(), rows[b], record));  // in the order kept
  j["chosen"] = chosen;
  j["fisher_determinant"] = r.fisher_determinant;
  j["fisher_condition"] = std::isfinite(r.fisher_condition) ? nlohmann::ordered_json(r.fisher_condition) : nlohmann::ordered_json();
  j["max_offdiagonal_automac"] = r.max_offdiagonal_mac;
  auto alike = nlohmann::ordered_json::array();
  for (const auto& [a, b] : indistinguishableModes(s)) alike.push_back({a, b});
  j["indistinguishable_mode_pairs"] = alike;
  if (!s.tams.empty()) j["tam"] = tamJson(s);
  if (s.loading) j["mass_loading"] = loadingJson(*s.loading);
  return j;
}

std::string placementCandidatesCsv(const PlacementStudy& s) {
  return fieldsCsv(placementFields(), placementRows(s), [](const Field<PlacementRow>&) { return true; });
}

std::string placementAutoMacCsv(const PlacementStudy& s) {
  std::ostringstream os;
  os << "mode";
  for (const ModeNumber m : s.target_modes) os << ",mode_" << m.number();
  os << '\n';
  for (Eigen::Index i = 0; i < s.result.automac.rows(); ++i) {
    os << s.target_modes[i].number();
    for (Eigen::Index j = 0; j < s.result.automac.cols(); ++j) os << ',' << strf("%.6f", s.result.automac(i, j));
    os << '\n';
  }
  return os.str();
}

}  // namespace mmv
