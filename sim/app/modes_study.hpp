#pragma once
/// `modes`: the system modes about the held equilibrium, for either kind of scene
/// (sim/modes/system_modes.hpp; the isolator's: sim/hamsas/hamsas_modes.hpp).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv::app {

struct ModesRequest {
  int modes = 12;                   ///< modes to report; 0 = all.
  std::vector<std::string> points;  ///< named points or stations whose shapes are tabulated.
  std::vector<std::string> strains;  ///< "A:B" spans (two stations of one link) whose modal strain is tabulated
  bool error_estimate = true;       ///< each mode's discretization error (the scene again at segments / 2 and / 4)
  double target_error = 0;          ///< > 0: the segments chosen for this relative frequency error
  double time_budget = 0;           ///< s; > 0: the target's choice within it
  bool segments_given = false;      ///< the segments were set by the user (then no target)
  Front front = Front::Cli;
};

struct ModesStudy {
  std::optional<ModesReport> report;  ///< the article's (none for HAM-SAS)
  nlohmann::ordered_json json;
  std::string text;
  std::string csv;  ///< modes.csv (the article's modeFields, HAM-SAS's hamsasModeFields)
  std::string vtp;  ///< modes.vtp, the article and its modes for ParaView (sim/io/vtk_export.hpp); none for HAM-SAS
};

/// The modes of `scene` as `request` asks; every option checked here.
ModesStudy runModesStudy(const Scene& scene, const ModesRequest& request);

}  // namespace mmv::app
