// Writers for `mmvlab compare`: text or Markdown report, JSON, CSV files.

#include "sim/io/report_compare.hpp"

#include <cmath>
#include <sstream>

#include "sim/io/compare_fields.hpp"
#include "sim/io/report.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {

std::string pct(double x) { return strf("%+.2f", 100 * x); }

std::string frequency(const SystemModeRow& r) { return r.stable ? strf("%.4f", r.frequency_hz) : "UNSTABLE"; }

/// A family as a table tag: in, out, tors, mix.
std::string familyTag(const std::string& family) {
  if (family == "in-plane") return "in";
  if (family == "out-of-plane") return "out";
  if (family == "torsion") return "tors";
  return family == "mixed" ? "mix" : family;
}

Table componentTable(const CompareReport& r) {
  std::vector<std::string> head{"link", "tip_mass_kg", "mu"};
  int n = 0;
  for (const auto& c : r.components) n = std::max<int>(n, c.modes.size());
  for (int k = 1; k <= n; ++k) head.push_back(strf("mode%d_Hz (closed form)", k));
  Table t(head);
  for (const auto& c : r.components) {
    std::vector<std::string> row{c.link, strf("%.4f", c.tip.mass), strf("%.4f", c.mass_ratio)};
    for (const auto& m : c.modes)
      row.push_back((m.has_closed_form ? strf("%.4f (%.4f)", m.frequency_hz, m.closed_form_hz) : strf("%.4f", m.frequency_hz)) +
                    (m.family.empty() ? "" : " " + familyTag(m.family)));
    t.add(row);
  }
  return t;
}

Table systemTable(const std::vector<SystemModeRow>& rows, bool spatial) {
  std::vector<std::string> head{"mode", "frequency_Hz", "strain: link (share)", "kinetic: link (share)",
                                "nearest component mode of that link", "system/component-1_%"};
  if (spatial) head.insert(head.begin() + 2, "family");
  Table t(head);
  for (const auto& m : rows) {  // the cells are the records' values (systemModeFields), as JSON and CSV hold them
    const auto rec = fieldsJson(systemModeFields(), m, [](const auto&) { return true; });
    const std::string strain = rec["strain_link"], kinetic = rec["kinetic_link"];
    const int component = rec["nearest_component_mode"];
    std::vector<std::string> row{
        std::to_string(rec["mode"].get<int>()),
        rec["frequency_hz"].is_number() ? strf("%.4f", rec["frequency_hz"].get<double>()) : "UNSTABLE",
        strf("%s (%.0f %%)", strain.c_str(), 100 * rec["strain_share"].get<double>()),
        strf("%s (%.0f %%)", kinetic.c_str(), 100 * rec["kinetic_share"].get<double>()),
        component ? strf("%s #%d %.4f Hz", strain.c_str(), component, rec["nearest_component_frequency_hz"].get<double>()) : "-",
        component ? pct(rec["system_over_component_minus_1"].get<double>()) : "-"};
    if (spatial) row.insert(row.begin() + 2, familyTag(rec.value("family", std::string())));
    t.add(row);
  }
  return t;
}

Table synthesisTable(const CompareReport& r) {
  std::vector<std::string> head{"mode", "full_Hz", "link", "assumed_Hz", "err_%", "MAC", "verdict", "CB_Hz", "err_%", "MAC", "verdict"};
  if (r.spatial) head.insert(head.begin() + 3, "family");
  Table t(head);
  // The cells are the rows' records (synthesisFields), as JSON and CSV hold them.
  const auto record = [](const SynthesisResult& s, std::size_t i) {
    return fieldsJson(synthesisFields(), SynthesisRowView{&s, &s.rows[i]}, [](const auto&) { return true; });
  };
  const auto cells = [](const nlohmann::ordered_json& rec) {
    return std::vector<std::string>{strf("%.4f", rec["synthesized_frequency_hz"].get<double>()),
                                    pct(rec["relative_error"].get<double>()), strf("%.3f", rec["mac"].get<double>()),
                                    rec["verdict"].get<std::string>()};
  };
  for (std::size_t i = 0; i < r.assumed.rows.size(); ++i) {
    const auto a = record(r.assumed, i);
    std::vector<std::string> row{std::to_string(a["mode"].get<int>()), strf("%.4f", a["full_frequency_hz"].get<double>()),
                                 a["dominant_link"].get<std::string>()};
    for (auto& c : cells(a)) row.push_back(c);
    if (r.spatial) row.insert(row.begin() + 3, familyTag(a.value("family", std::string())));
    if (i < r.craig_bampton.rows.size())
      for (auto& c : cells(record(r.craig_bampton, i))) row.push_back(c);
    t.add(row);
  }
  return t;
}

Table macTable(const SynthesisResult& s) {
  std::vector<std::string> head{"synth \\ full"};
  for (Eigen::Index j = 0; j < s.mac.cols(); ++j) head.push_back(strf("%ld", static_cast<long>(j + 1)));
  Table t(head);
  for (Eigen::Index i = 0; i < s.mac.rows(); ++i) {
    std::vector<std::string> row{strf("%ld", static_cast<long>(i + 1))};
    for (Eigen::Index j = 0; j < s.mac.cols(); ++j) row.push_back(strf("%.2f", s.mac(i, j)));
    t.add(row);
  }
  return t;
}

Table tipRuleTable(const CompareReport& r) {
  std::vector<std::string> head{"tip-mass rule"};
  if (!r.tip_rules.empty())
    for (const auto& [link, f] : r.tip_rules[0].first_component_hz) head.push_back(link + " mode1_Hz");
  head.push_back("assumed-modes: max |err|_%");
  head.push_back("predicted");
  Table t(head);
  for (const auto& e : r.tip_rules) {
    std::vector<std::string> row{e.rule};
    for (const auto& [link, f] : e.first_component_hz) row.push_back(strf("%.4f", f));
    row.push_back(strf("%.2f", 100 * e.max_abs_error));
    row.push_back(strf("%d of %zu", e.predicted, r.assumed.rows.size()));
    t.add(row);
  }
  return t;
}

Table topologyTable(const CompareReport& r) {
  std::vector<std::string> head{"mode"};
  for (const auto& t : r.topologies) {
    head.push_back(t.topology + "_Hz");
    head.push_back(t.topology + ": strain link");
  }
  Table t(head);
  std::size_t n = 0;
  for (const auto& c : r.topologies) n = std::max(n, c.modes.size());
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::string> row{strf("%zu", i + 1)};
    for (const auto& c : r.topologies) {
      if (i < c.modes.size()) {
        row.push_back(frequency(c.modes[i]));
        row.push_back(strf("%s (%.0f %%)", c.modes[i].strain_link.c_str(), 100 * c.modes[i].strain_share));
      } else {
        row.insert(row.end(), {"-", "-"});
      }
    }
    t.add(row);
  }
  return t;
}

/// The whole report; `md` selects Markdown headings and tables.
std::string render(const CompareReport& r, bool md) {
  std::ostringstream os;
  auto heading = [&](const std::string& h) { os << (md ? "\n## " + h + "\n\n" : "\n" + h + "\n"); };
  auto table = [&](const Table& t) { os << (md ? t.markdown() : t.text()); };
  os << (md ? "# " : "") << "Component modes against system modes: " << r.scene_name << "\n";
  os << (md ? "\n" : "") << "Scene: " << r.scene_source << "; topology: " << r.topology << "; joints:";
  for (const auto& [j, a] : r.joint_angles_deg) os << ' ' << j << ' ' << strf("%g", a) << " deg";
  os << strf("; gravity %.4g m/s^2\n", r.gravity);
  os << "Components: each link alone, no gravity, " << componentBCName(r.component.bc) << ", tip mass: "
     << (r.component.explicit_tip ? "explicit" : tipMassRuleName(r.component.rule)) << " (Euler-Bernoulli closed form in parentheses)\n";
  if (r.spatial)
    os << (md ? "\n" : "") << "Spatial model: families in (in-plane), out (out-of-plane), tors (torsion), mix (mixed); each closed form is "
          "its family's; out of the plane and in torsion the joint's pin clamps the root (docs/spatial.md)\n";

  heading("Table 2: component modes (Hz)");
  table(componentTable(r));
  heading("Table 3: system modes at the equilibrium, each with the link that dominates it");
  table(systemTable(r.system, r.spatial));
  heading("Synthesis from component modes against the full model (Ritz: the k-th synthesized frequency is never below the k-th full one)");
  os << (md ? "" : "  ") << "assumed: " << r.assumed.method << " (" << r.assumed.reduced_dofs << " of " << r.assumed.full_dofs
     << " DOF); CB: " << r.craig_bampton.method << " (" << r.craig_bampton.reduced_dofs << " DOF)\n"
     << (md ? "\n" : "");
  table(synthesisTable(r));
  os << (md ? "\n" : "") << (md ? "" : "  ")
     << "verdict: predicted = MAC >= 0.9 and |err| <= 1 %; shifted = MAC >= 0.9, larger error; missed = MAC < 0.9\n";
  heading("MAC, assumed-modes synthesis (rows) against the full model (columns)");
  table(macTable(r.assumed));
  heading("Effect of the component tip-mass rule (the report's text and its TREETOPS numbers disagree)");
  table(tipRuleTable(r));
  if (!r.topologies.empty()) {
    heading("Open against closed topology: system modes");
    table(topologyTable(r));
  }
  return os.str();
}

std::string macCsv(const SynthesisResult& s) {
  std::ostringstream os;
  os << "synthesized_mode";
  for (Eigen::Index j = 0; j < s.mac.cols(); ++j) os << ",full_mode_" << j + 1;
  os << '\n';
  for (Eigen::Index i = 0; i < s.mac.rows(); ++i) {
    os << i + 1;
    for (Eigen::Index j = 0; j < s.mac.cols(); ++j) os << ',' << strf("%.6f", s.mac(i, j));
    os << '\n';
  }
  return os.str();
}

nlohmann::ordered_json synthesisJson(const SynthesisResult& s) {
  nlohmann::ordered_json j;
  j["method"] = s.method;
  j["full_dofs"] = s.full_dofs;
  j["reduced_dofs"] = s.reduced_dofs;
  auto rows = nlohmann::ordered_json::array();
  const auto record = [](const auto& f) { return std::string(f.key) != "method"; };  // the rows sit under it
  for (const auto& r : s.rows) rows.push_back(fieldsJson(synthesisFields(), SynthesisRowView{&s, &r}, record));
  j["modes"] = rows;
  auto mac = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < s.mac.rows(); ++i) {
    auto row = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < s.mac.cols(); ++k) row.push_back(s.mac(i, k));
    mac.push_back(row);
  }
  j["mac"] = mac;
  return j;
}

nlohmann::ordered_json systemJson(const std::vector<SystemModeRow>& rows) {
  auto a = nlohmann::ordered_json::array();
  for (const auto& m : rows) a.push_back(fieldsJson(systemModeFields(), m, [](const auto&) { return true; }));
  return a;
}

}  // namespace

std::string formatCompareText(const CompareReport& r) { return render(r, false); }
std::string formatCompareMarkdown(const CompareReport& r) { return render(r, true); }

nlohmann::ordered_json compareToJson(const CompareReport& r) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "compare";
  j["scene"] = {{"name", r.scene_name}, {"source", r.scene_source}};
  j["topology"] = r.topology;
  j["model"] = r.spatial ? "spatial" : "planar";
  auto joints = nlohmann::ordered_json::array();
  for (const auto& [n, a] : r.joint_angles_deg) joints.push_back({{"name", n}, {"angle_deg", a}});
  j["joints"] = joints;
  j["gravity_m_per_s2"] = r.gravity;
  j["component_boundary_condition"] = componentBCName(r.component.bc);
  j["component_tip_mass_rule"] = r.component.explicit_tip ? "explicit" : tipMassRuleName(r.component.rule);
  auto comps = nlohmann::ordered_json::array();
  for (const auto& c : r.components) {
    auto modes = nlohmann::ordered_json::array();
    for (const auto& m : c.modes) {
      modes.push_back({{"frequency_hz", m.frequency_hz},
                       {"closed_form_hz", m.has_closed_form ? nlohmann::ordered_json(m.closed_form_hz) : nlohmann::ordered_json(nullptr)}});
      if (!m.family.empty()) modes.back()["family"] = m.family;
    }
    comps.push_back({{"link", c.link},
                     {"tip_mass_kg", c.tip.mass},
                     {"tip_rotary_inertia_kg_m2", c.tip.rotary_inertia},
                     {"mass_ratio", c.mass_ratio},
                     {"link_mass_kg", c.link_mass_kg},
                     {"modes", modes}});
  }
  j["component_modes"] = comps;
  j["system_modes"] = systemJson(r.system);
  j["synthesis"] = {{"assumed_modes", synthesisJson(r.assumed)}, {"craig_bampton", synthesisJson(r.craig_bampton)}};
  auto rules = nlohmann::ordered_json::array();
  for (const auto& e : r.tip_rules) {
    auto f = nlohmann::ordered_json::object();
    for (const auto& [link, hz] : e.first_component_hz) f[link] = hz;
    rules.push_back({{"rule", e.rule}, {"first_component_frequency_hz", f}, {"max_abs_relative_error", e.max_abs_error},
                     {"predicted", e.predicted}});
  }
  j["tip_mass_rules"] = rules;
  auto topo = nlohmann::ordered_json::array();
  for (const auto& t : r.topologies) topo.push_back({{"topology", t.topology}, {"system_modes", systemJson(t.modes)}});
  j["topologies"] = topo;
  return j;
}

std::vector<std::pair<std::string, std::string>> compareCsvFiles(const CompareReport& r) {
  std::ostringstream comp, sys, syn;
  // The spatial model adds a last column, each mode's family.
  const auto family = [&](const std::string& f) { return r.spatial ? "," + f : std::string(); };
  comp << "link,boundary_condition,tip_mass_rule,tip_mass_kg,mass_ratio,mode,frequency_hz,closed_form_hz" << family("family") << '\n';
  for (const auto& c : r.components)
    for (std::size_t k = 0; k < c.modes.size(); ++k)
      comp << csvEscape(c.link) << ',' << componentBCName(r.component.bc) << ',' << c.tip_rule << ','
           << strf("%.6g,%.6g,%zu,%.8g,", c.tip.mass, c.mass_ratio, k + 1, c.modes[k].frequency_hz)
           << (c.modes[k].has_closed_form ? strf("%.8g", c.modes[k].closed_form_hz) : "") << family(c.modes[k].family) << '\n';
  // The spatial model's system modes have a family column; the planar model's none.
  const auto planar_less_family = [&](const auto& f) { return r.spatial || std::string(f.key) != "family"; };
  sys << fieldsCsv(systemModeFields(), r.system, planar_less_family);
  std::vector<SynthesisRowView> synthesized;
  for (const SynthesisResult* s : {&r.assumed, &r.craig_bampton})
    for (const auto& row : s->rows) synthesized.push_back({s, &row});
  syn << fieldsCsv(synthesisFields(), synthesized, [](const auto&) { return true; });
  return {{"component_modes.csv", comp.str()},
          {"system_modes.csv", sys.str()},
          {"synthesis.csv", syn.str()},
          {"mac_assumed_modes.csv", macCsv(r.assumed)},
          {"mac_craig_bampton.csv", macCsv(r.craig_bampton)}};
}

}  // namespace mmv
