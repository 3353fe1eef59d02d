#pragma once
/// `sweep-config`: a configuration sweep (sim/modes/config_sweep.hpp): one article over a
/// grid of joint angles, its system modes tracked by shape and the component synthesis
/// judged at each angle.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/component_studies.hpp"
#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/modes/config_sweep.hpp"

namespace mmv::app {

/// `sweep-config`'s options, declared once (sim/app/options.hpp).
struct ConfigSweepParams {
  std::vector<std::string> grids;   ///< one or two JOINT:FROM_DEG:TO_DEG:STEP_DEG
  int modes = 6;
  int component_modes = 4;
  std::string bc = "clamped-free";
  std::string tip_mass = "torquer";
  std::string method = "assumed";

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.grids, Option("grids", "JOINT:FROM_DEG:TO_DEG:STEP_DEG; give it once (a line) or twice (a 2-D grid)")
                   .flag("--grid")
                   .required());
    v(s.modes, Option("modes", "Modes tracked").range(1, 100));
    v(s.component_modes, Option("component_modes", "Modes per link in the synthesis").range(1, 200));
    v(s.bc, Option("bc", "Component boundary condition (assumed modes)").choices(kComponentBcs));
    v(s.tip_mass, Option("tip_mass", "Component tip mass: torquer, outboard, none, or MASS_KG[,INERTIA_KG_M2]"));
    v(s.method, Option("method", "Synthesis").choices("assumed,craig-bampton"));
  }
};

struct ConfigSweepRequest : ConfigSweepParams {
  Front front = Front::Cli;
};

struct ConfigSweepStudy {
  ConfigSweepResult result;
  nlohmann::ordered_json json;
  std::string text, csv;
};

/// Checks every option (UsageError naming it) before any model is built, then sweeps.
ConfigSweepStudy runConfigSweepStudy(const Scene& scene, const ConfigSweepRequest& request);

}  // namespace mmv::app
