#include "sim/app/component_studies.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "sim/core/integrators.hpp"
#include "sim/io/convergence_fields.hpp"
#include "sim/io/report.hpp"
#include "sim/io/report_compare.hpp"

namespace mmv::app {

void parseComponentOptions(const std::string& bc, const std::string& tip_mass, Front front, ComponentOptions& o) {
  // The name is one of kComponentBcs: the declaration's choices were checked first.
  if (!parseComponentBC(bc, o.bc)) throw std::logic_error("parseComponentOptions: bc '" + bc + "' passed the declared check");
  if (parseTipMassRule(tip_mass, o.rule)) return;
  // Explicit: "MASS" (kg) or "MASS,ROTARY_INERTIA" (kg, kg*m^2).
  const auto comma = tip_mass.find(',');
  const std::string ms = tip_mass.substr(0, comma), js = comma == std::string::npos ? "0" : tip_mass.substr(comma + 1);
  char *e1 = nullptr, *e2 = nullptr;
  const double m = std::strtod(ms.c_str(), &e1), j = std::strtod(js.c_str(), &e2);
  if (ms.empty() || js.empty() || *e1 != '\0' || *e2 != '\0' || !std::isfinite(m) || !std::isfinite(j) || m < 0 || j < 0)
    throw UsageError(optionName(front, "--tip-mass") +
                     ": expected a rule (none, torquer, outboard) or MASS_KG[,ROTARY_INERTIA_KG_M2] >= 0 (got " + tip_mass + ")");
  o.explicit_tip = LumpedMass{m, j};
}

ConvergeStudy runConvergeStudy(const Scene& scene, const ConvergeRequest& r) {
  checkOptions<ConvergeParams>(r, r.front);
  ConvergeStudy s{runConvergence(articleOf(scene, "converge"), r.max_segments, r.modes), {}, {}, {}};
  s.json = convergenceToJson(s.study);
  s.text = formatConvergenceText(s.study);
  s.csv = convergenceCsv(s.study);
  checkResultFinite(s.json);  // before any file is committed
  checkResultFinite(s.text);
  return s;
}

CompareStudy runCompareStudy(const Scene& scene, const CompareRequest& r) {
  checkOptions<CompareParams>(r, r.front);
  CompareOptions o;
  parseComponentOptions(r.bc, r.tip_mass, r.front, o.component);
  o.modes_per_link = r.component_modes;
  o.system_modes = r.modes;
  o.topologies = r.topologies;
  CompareStudy s{runCompare(articleOf(scene, "compare"), o), {}, {}, {}};
  s.json = compareToJson(s.report);
  s.text = formatCompareText(s.report);
  s.markdown = formatCompareMarkdown(s.report);
  checkResultFinite(s.json);  // before any file is committed
  return s;
}

}  // namespace mmv::app
