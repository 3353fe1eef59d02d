#pragma once
/// `modes`: the system modes about the held equilibrium, for either kind of scene
/// (sim/modes/system_modes.hpp; the isolator's: sim/hamsas/hamsas_modes.hpp).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv::app {

/// `modes`' options, declared once (sim/app/options.hpp): the command line's and
/// Python's are made from this list.
struct ModesParams {
  int modes = 12;                    ///< modes to report; 0 = all.
  std::vector<std::string> points;   ///< named points or stations whose shapes are tabulated.
  std::vector<std::string> strains;  ///< "A:B[:in|out]" spans (two stations of one link) whose modal strain is tabulated
  bool error_estimate = true;        ///< each mode's discretization error (the scene again at segments / 2 and / 4)
  double target_error = 0;           ///< > 0: the segments chosen for this relative frequency error
  double time_budget = 0;            ///< s; > 0: the target's choice within it

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.modes, Option("modes", "Number of modes to report (0: all)").atLeast(0));
    v(s.points, Option("points", "Points or stations whose mode shapes are tabulated, e.g. link1@0.5, link3a@0.762m, link2.tip")
                    .commaSeparated());
    v(s.strains, Option("strains", "A:B[:in|out], two stations of one link: each mode's mean surface strain over "
                                   "the span (a film's or gauge's reading per unit modal coordinate), in the plane or out of it "
                                   "(spatial model), e.g. link3a@0.1m:link3a@0.5m")
                     .flag("--strain"));
    v(s.error_estimate, Option("error_estimate", "Estimate each mode's discretization error (the scene solved again with "
                                                 "segments / 2 and / 4)")
                            .negated("--no-error-estimate", "Skip each mode's discretization error estimate (the scene "
                                                            "solved again with segments / 2 and / 4)"));
    v(s.target_error, Option("target_error", "Relative frequency error each of the reported modes must meet, e.g. 1e-3: the "
                                             "fewest segments per link (1, 2, 4, ... 256) whose Richardson estimate meets it "
                                             "are chosen")
                          .range(1e-12, 0.5)
                          .off(0));
    v(s.time_budget, Option("time_budget", "Wall seconds the target error may take choosing the segments").unit("s").above(0).off(0, "no limit"));
  }
};

struct ModesRequest : ModesParams {
  bool segments_given = false;  ///< the segments were set by the user (then no target)
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
