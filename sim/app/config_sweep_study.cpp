#include "sim/app/config_sweep_study.hpp"

#include <cmath>
#include <sstream>

#include "sim/app/component_studies.hpp"
#include "sim/core/text.hpp"
#include "sim/io/config_sweep_report.hpp"

namespace mmv::app {
namespace {

/// JOINT:FROM:TO:STEP, angles in degrees, checked against the scene's joints.
GridAxis parseGrid(const std::string& text, const ArticleScene& scene, Front front) {
  const std::string option = declaredName<ConfigSweepParams>("grids", front);
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
  const std::string form = option + " " + text + ": expected JOINT:FROM_DEG:TO_DEG:STEP_DEG, e.g. joint2:-45:45:5";
  if (parts.size() != 4) throw UsageError(form);
  GridAxis ax;
  ax.joint = parts[0];
  if (!scene.article.findJoint(ax.joint)) {
    std::vector<std::string> names;
    std::string known;
    for (const auto& j : scene.article.joints) names.push_back(j.name), known += (known.empty() ? "" : ", ") + j.name;
    throw UsageError(option + " " + text + ": unknown joint '" + ax.joint + "'" + didYouMean(ax.joint, names) +
                     " (known: " + known + ")");
  }
  double* v[3] = {&ax.from_deg, &ax.to_deg, &ax.step_deg};
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> x = finiteNumber(parts[i + 1]);
    if (!x) throw UsageError(form);
    *v[i] = *x;
  }
  if (!(ax.step_deg > 0) || ax.to_deg < ax.from_deg) throw UsageError(option + " " + text + ": need FROM <= TO and STEP > 0");
  if (ax.count() > GridAxis::kMaxValues)
    throw UsageError(strf("%s %s: %.4g values on one axis, above the limit of %.0f", option.c_str(), text.c_str(), ax.count(),
                          GridAxis::kMaxValues));
  return ax;
}

}  // namespace

ConfigSweepStudy runConfigSweepStudy(const Scene& scene, const ConfigSweepRequest& r) {
  checkOptions<ConfigSweepParams>(r, r.front);
  const ArticleScene& article = articleOf(scene, "sweep-config");
  const auto opt = [&](const char* key) { return declaredName<ConfigSweepParams>(key, r.front); };
  ConfigSweepOptions o;
  if (r.grids.empty() || r.grids.size() > 2) throw UsageError(opt("grids") + ": give one or two grids");
  for (const auto& g : r.grids) o.axes.push_back(parseGrid(g, article, r.front));
  if (o.axes.size() == 2 && o.axes[0].joint == o.axes[1].joint)
    throw UsageError(opt("grids") + ": the two grids name the same joint");
  o.modes = r.modes;
  parseComponentOptions(r.bc, r.tip_mass, r.front, o.synthesis.component);
  o.synthesis.method = r.method == "craig-bampton" ? CmsMethod::CraigBampton : CmsMethod::AssumedModes;  // declared choices
  o.synthesis.modes_per_link = r.component_modes;
  ConfigSweepStudy s{runConfigSweep(article, o), {}, {}, {}};
  s.json = configSweepJson(s.result);
  s.text = configSweepText(s.result);
  s.csv = configSweepCsv(s.result);
  checkResultFinite(s.json);
  return s;
}

}  // namespace mmv::app
