// Writers of `mmvlab check`: one row per requirement (sim/io/check_report.hpp).
#include "sim/io/check_report.hpp"

#include <cmath>

#include "sim/core/text.hpp"

namespace mmv {

namespace {

std::string number(double v) { return std::isfinite(v) ? strf("%.4g", v) : "-"; }

Table checkTable(const CheckReport& r) {
  Table t({"group", "requirement", "demand", "capacity", "unit", "margin_%", "verdict"});
  for (const auto& l : r.lines) {
    const bool measured = !l.unit.empty();
    t.add({l.group, l.requirement, measured ? number(l.demand) : "-", l.has_capacity ? number(l.capacity) : "-", measured ? l.unit : "-",
           l.has_capacity ? strf("%.1f", l.margin_pct) : "-", verdictName(l.verdict)});
  }
  return t;
}

std::string heading(const CheckReport& r) {
  std::string s = "scene: " + r.scene_name + " (" + r.scene_source + ")";
  if (r.segments > 0) s += strf(", %d segments per flexible link", r.segments);
  return s;
}

std::string summary(const CheckReport& r) {
  std::string s = std::string("overall: ") + verdictName(r.overall);
  if (r.not_checked > 0) s += strf(" (%d requirement%s not checked: no capacity given)", r.not_checked, r.not_checked == 1 ? "" : "s");
  return s;
}

}  // namespace

std::string checkText(const CheckReport& r) {
  std::string s = "mmvlab check: can this article be tested with this equipment?\n" + heading(r) + "\n\n";
  s += checkTable(r).text();
  s += "\nnotes:\n";
  for (std::size_t i = 0; i < r.lines.size(); ++i)
    if (!r.lines[i].note.empty()) s += strf("  %2zu. %s: %s\n", i + 1, r.lines[i].requirement.c_str(), r.lines[i].note.c_str());
  s += "\n" + summary(r) + strf(" (%.2f s)\n", r.seconds);
  return s;
}

nlohmann::ordered_json checkJson(const CheckReport& r) {
  nlohmann::ordered_json j;
  j["scene"] = r.scene_name;
  j["scene_source"] = r.scene_source;
  j["overrides"] = r.overrides;
  j["segments"] = r.segments;
  j["overall"] = verdictName(r.overall);
  j["not_checked"] = r.not_checked;
  auto& lines = j["lines"] = nlohmann::ordered_json::array();
  const auto every = [](const Field<CheckLine>&) { return true; };
  for (const auto& l : r.lines) lines.push_back(fieldsJson(checkLineFields(), l, every));
  j["seconds"] = r.seconds;
  return j;
}

namespace {

using Value = std::optional<nlohmann::ordered_json>;
Value text(const std::string& s) { return nlohmann::ordered_json(s); }
Value numberOrNull(bool defined, double v) {
  return defined && std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

const std::vector<Field<CheckLine>>& checkLineFields() {
  static const std::vector<Field<CheckLine>> fields = {
      {"id", "", "%s", "stable name of the requirement across runs of a scene (a sweep's column)",
       [](const CheckLine& l) { return text(l.id); }},
      {"group", "", "%s", "torquers, gimbal, table, modes, planarity, sensors, shaker, lab or plausibility",
       [](const CheckLine& l) { return text(l.group); }},
      {"requirement", "", "%s", "what is checked", [](const CheckLine& l) { return text(l.requirement); }},
      {"demand", "unit", "%.8g", "what the test needs (null: a requirement with no measure)",
       [](const CheckLine& l) { return numberOrNull(!l.unit.empty(), l.demand); }},
      {"capacity", "unit", "%.8g", "what the equipment gives (null: not given)",
       [](const CheckLine& l) { return numberOrNull(l.has_capacity, l.capacity); }},
      {"unit", "", "%s", "the unit of demand and capacity", [](const CheckLine& l) { return text(l.unit); }},
      {"margin_pct", "%", "%.8g", "(capacity - demand) / capacity x 100 (null: no capacity)",
       [](const CheckLine& l) { return numberOrNull(l.has_capacity, l.margin_pct); }},
      {"verdict", "", "%s", "pass, warn (below the required margin), FAIL (below 0), advisory, info or n/a",
       [](const CheckLine& l) { return text(verdictName(l.verdict)); }},
      {"note", "", "%s", "where the worst case is, what is assumed, what to do", [](const CheckLine& l) { return text(l.note); }},
  };
  return fields;
}

std::string checkCsv(const CheckReport& r) {
  return fieldsCsv(checkLineFields(), r.lines, [](const Field<CheckLine>&) { return true; });
}

std::string checkMarkdown(const CheckReport& r) {
  std::string s = "# Feasibility check: " + r.scene_name + "\n\n" + heading(r) + "\n\n";
  for (const auto& o : r.overrides) s += "- override: `--set " + o + "`\n";
  s += "\n" + checkTable(r).markdown() + "\n## Notes\n\n";
  for (std::size_t i = 0; i < r.lines.size(); ++i)
    if (!r.lines[i].note.empty()) s += strf("%zu. **%s**: %s\n", i + 1, r.lines[i].requirement.c_str(), r.lines[i].note.c_str());
  s += "\n**" + summary(r) + "**\n";
  return s;
}

}  // namespace mmv
