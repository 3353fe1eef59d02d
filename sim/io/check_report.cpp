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
  for (const auto& l : r.lines) {
    nlohmann::ordered_json o;
    o["id"] = l.id;
    o["group"] = l.group;
    o["requirement"] = l.requirement;
    o["demand"] = l.unit.empty() || !std::isfinite(l.demand) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(l.demand);
    o["capacity"] = l.has_capacity ? nlohmann::ordered_json(l.capacity) : nlohmann::ordered_json(nullptr);
    o["unit"] = l.unit;
    o["margin_pct"] = l.has_capacity ? nlohmann::ordered_json(l.margin_pct) : nlohmann::ordered_json(nullptr);
    o["verdict"] = verdictName(l.verdict);
    o["note"] = l.note;
    lines.push_back(o);
  }
  j["seconds"] = r.seconds;
  return j;
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
