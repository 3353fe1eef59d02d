#include "sim/app/verbs.hpp"

#include <stdexcept>

#include "sim/app/component_studies.hpp"
#include "sim/app/config_sweep_study.hpp"
#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/app/simulate_study.hpp"
#include "sim/app/trade_study.hpp"

namespace mmv::app {

const std::vector<VerbDeclaration>& declaredVerbs() {
  static const std::vector<VerbDeclaration> verbs = {
      declareVerb<ModesParams>("modes", "Static equilibrium with the torquers holding, then the system modes",
                               "modes.txt, modes.json, modes.csv (one row per mode) and modes.vtp (the article and its mode "
                               "shapes for ParaView)"),
      declareVerb<ConvergeParams>("converge", "Frequencies against segments per link (1, 2, 4, ...), Richardson error, time",
                                  "converge.txt, converge.json, converge.csv and convergence.png"),
      declareVerb<CompareParams>("compare",
                                 "Component modes (report Table 2) against system modes (Table 3), synthesis errors and MAC",
                                 "compare.md, CSV, JSON and MAC heat maps (PNG)"),
      declareVerb<ConfigSweepParams>("sweep-config",
                                     "System modes and synthesis error over a grid of joint angles, modes tracked by shape",
                                     "sweep.csv, sweep.json and PNG plots"),
      declareVerb<SimulateParams>("simulate", "Time run: slews, table programs, free motion; torques, energy, history",
                                  "history.csv, summary.json, run.json, scene.yaml, states.csv and the run's figures"),
      declareVerb<TradeParams>("trade", "Speed-accuracy trade of a time run: integrators x tolerances, segments",
                               "trade.csv, trade.json and trade.png"),
      declareVerb<CheckParams>("check", "Feasibility: torquers, gimbal, table, modes, sensors, lab; demand, capacity, margin, verdict",
                               "check.md (Markdown), check.json and check.csv"),
  };
  return verbs;
}

const VerbDeclaration& declaredVerb(const std::string& name) {
  for (const auto& v : declaredVerbs())
    if (v.name == name) return v;
  throw std::out_of_range("no declared verb '" + name + "'");
}

std::string declaredOptionName(Front front, const std::string& cli_flag) {
  if (front == Front::Cli) return cli_flag;
  for (const auto& v : declaredVerbs())
    for (const auto& d : v.options())
      if (d.option.cliFlag() == cli_flag) return d.option.key();
  return optionName(front, cli_flag);
}

}  // namespace mmv::app
