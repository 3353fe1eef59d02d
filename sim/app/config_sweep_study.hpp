#pragma once
/// `sweep-config`: a configuration sweep (sim/modes/config_sweep.hpp): one article over a
/// grid of joint angles, its system modes tracked by shape and the component synthesis
/// judged at each angle.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/modes/config_sweep.hpp"

namespace mmv::app {

struct ConfigSweepRequest {
  std::vector<std::string> grids;   ///< one or two JOINT:FROM_DEG:TO_DEG:STEP_DEG
  int modes = 6;                    ///< modes tracked, 1 .. 100
  int component_modes = 4;          ///< modes per link in the synthesis, 1 .. 200
  std::string bc = "clamped-free";  ///< as compare's
  std::string tip_mass = "torquer"; ///< as compare's
  std::string method = "assumed";   ///< assumed or craig-bampton
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
