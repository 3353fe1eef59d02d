#include "sim/modes/compare.hpp"

#include <algorithm>
#include <cmath>

namespace mmv {

ArticleScene openTopology(const ArticleScene& scene) {
  ArticleScene s = scene;
  s.article.closures.clear();
  return s;
}

namespace {

ArticleScene withTopology(const ArticleScene& scene, const std::string& topology) {
  if (topology == "open") return openTopology(scene);
  if (topology == "closed" && scene.article.closures.empty())
    throw OptionError("--topology", " closed: " + scene.source + " has no closures (add them under 'closures:')");
  return scene;
}

double shareOf(const std::vector<PartShare>& shares, const std::string& part) {
  for (const auto& s : shares)
    if (s.part == part) return s.fraction;
  return 0;
}

std::vector<SystemModeRow> systemModes(const ArticleScene& scene, int count, const std::vector<ComponentResult>& components) {
  ModesOptions mo;
  mo.max_modes = count;
  mo.with_shapes = false;
  const ModesReport rep = runModes(scene, mo);
  std::vector<SystemModeRow> rows;
  for (const auto& m : rep.modes) {
    SystemModeRow r;
    r.mode = m.number;
    r.frequency_hz = m.frequency_hz;
    r.stable = m.stable;
    r.strain_link = m.dominant_link_strain;
    r.kinetic_link = m.dominant_link_kinetic;
    r.strain_share = shareOf(m.strain_by_link, r.strain_link);
    r.kinetic_share = shareOf(m.kinetic_by_link, r.kinetic_link);
    r.family = m.family.label;
    for (const auto& c : components) {
      if (c.link != r.strain_link) continue;
      double best = INFINITY;
      for (std::size_t k = 0; k < c.modes.size(); ++k) {
        if (r.family != "mixed" && c.modes[k].family != r.family) continue;
        const double d = r.frequency_hz / c.modes[k].frequency_hz - 1.0;
        if (std::abs(d) < std::abs(best)) {
          best = d;
          r.component_mode = ModeNumber::atIndex(static_cast<int>(k));
          r.component_hz = c.modes[k].frequency_hz;
          r.component_difference = d;
        }
      }
    }
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

CompareReport runCompare(const ArticleScene& scene, const CompareOptions& o) {
  CompareReport rep;
  rep.scene_name = scene.name;
  rep.scene_source = scene.source;
  rep.spatial = scene.article.model == ArticleModel::Spatial;
  // The main tables are the scene's own topology when it is among those asked for
  // (`--topology open,closed` on a closed scene: closed), else the first asked for.
  const std::string own = scene.article.closures.empty() ? "open" : "closed";
  rep.topology = o.topologies.empty() || std::find(o.topologies.begin(), o.topologies.end(), own) != o.topologies.end()
                     ? own
                     : o.topologies.front();
  const ArticleScene main = withTopology(scene, rep.topology);
  for (const auto& j : main.article.joints) rep.joint_angles_deg.push_back({j.name, j.angle * 180.0 / M_PI});
  rep.gravity = std::hypot(main.gravity[0], main.gravity[1]);
  rep.component = o.component;

  ComponentOptions co = o.component;
  co.num_modes = o.modes_per_link;
  for (const auto& l : main.article.links)
    if (!l.rigid) rep.components.push_back(calcComponentModes(main, l.name, co));
  rep.system = systemModes(main, o.system_modes, rep.components);

  SynthesisOptions so;
  so.component = o.component;
  so.modes_per_link = o.modes_per_link;
  so.compare_modes = o.system_modes;
  so.method = CmsMethod::AssumedModes;
  rep.assumed = synthesize(main, so);
  so.method = CmsMethod::CraigBampton;
  rep.craig_bampton = synthesize(main, so);

  for (TipMassRule rule : {TipMassRule::None, TipMassRule::Torquer, TipMassRule::Outboard}) {
    TipRuleEffect e;
    e.rule = tipMassRuleName(rule);
    ComponentOptions c = o.component;
    c.rule = rule;
    c.explicit_tip.reset();
    c.num_modes = 1;
    for (const auto& l : main.article.links)
      if (!l.rigid) e.first_component_hz.push_back({l.name, calcComponentModes(main, l.name, c).modes.at(0).frequency_hz});
    SynthesisOptions sr = so;
    sr.method = CmsMethod::AssumedModes;
    sr.component = c;
    const SynthesisResult r = synthesize(main, sr);
    for (const auto& row : r.rows) {
      e.max_abs_error = std::max(e.max_abs_error, std::abs(row.relative_error));
      e.predicted += row.verdict == "predicted";
    }
    rep.tip_rules.push_back(e);
  }

  if (o.topologies.size() > 1) {
    for (const auto& t : o.topologies) {
      const ArticleScene s = withTopology(scene, t);
      std::vector<ComponentResult> comps;
      for (const auto& l : s.article.links)
        if (!l.rigid) comps.push_back(calcComponentModes(s, l.name, co));
      rep.topologies.push_back({t, systemModes(s, o.system_modes, comps)});
    }
  }
  return rep;
}

}  // namespace mmv
