#pragma once
/// `simulate`: a time run of either kind of scene (sim/time/simulation.hpp, the
/// isolator's: sim/hamsas/hamsas_simulation.hpp), as the scene sets it up or as the
/// accuracy contract chooses it (sim/time/target.hpp), optionally verified
/// (sim/time/verify.hpp).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/core/integrators.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/target.hpp"

namespace mmv::app {

/// `simulate`'s options, declared once (sim/app/options.hpp). Every number is optional:
/// absent, the scene's setting (or the option's default) holds; present, it is checked
/// (an explicit 0 duration is refused, not read as "the scene's").
struct SimulateParams {
  std::optional<std::string> integrator;      ///< a name of the integrator table
  std::optional<double> accuracy;             ///< (0, 1)
  std::optional<double> absolute_tolerance;   ///< (0, 1), SUNDIALS integrators only
  std::optional<double> duration;             ///< s, > 0
  std::optional<double> sample_rate;          ///< rows per second, > 0
  bool verify = false;                        ///< a companion run at tolerance / 10
  std::optional<double> verify_target;        ///< m, > 0, implies verify; absent: 1 % of the scored motion
  std::optional<double> target_error;         ///< m, > 0: the cheapest run that meets it
  std::vector<std::string> points;            ///< where target_error is held; empty: the scene's, else every tip
  std::optional<double> time_budget;          ///< s, > 0: the target within it

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.integrator, Option("integrator", integratorListing()).whenAbsent("the scene's"));
    v(s.accuracy, Option("accuracy", "Integrator relative accuracy").above(0).below(1).whenAbsent("the scene's"));
    v(s.absolute_tolerance, Option("absolute_tolerance", "SUNDIALS integrators: absolute tolerance (m, rad, m/s, rad/s)")
                                .above(0)
                                .below(1)
                                .whenAbsent("the scene's, else the accuracy"));
    v(s.duration, Option("duration", "Seconds simulated").unit("s").above(0).whenAbsent("the scene's"));
    v(s.sample_rate, Option("sample_rate", "Output rows per second").unit("Hz").above(0).whenAbsent("the scene's"));
    v(s.verify, Option("verify", "Run the same run again at a 10x tighter tolerance and report the difference on the scored "
                                 "points as the run's estimated error (doubles the cost at least)"));
    v(s.verify_target, Option("verify_target", "Error the verification is held to; implies verify")
                           .unit("m")
                           .above(0)
                           .whenAbsent("1 % of the scored points' largest motion"));
    v(s.target_error, Option("target_error", "Error to meet on the scored points: the cheapest integrator, tolerance and "
                                             "segments that meet it are chosen on a pilot window, run and verified "
                                             "(docs/accuracy.md)")
                          .unit("m")
                          .above(0)
                          .whenAbsent("none"));
    v(s.points, Option("points", "Link tips or stations the target error is held on, e.g. link3a.tip (default: the scene's "
                                 "score_points, else every tip)")
                    .commaSeparated());
    v(s.time_budget, Option("time_budget", "Wall seconds the target error may take in all (pilot, run, verification); past "
                                           "it the target is refused")
                         .unit("s")
                         .above(0)
                         .whenAbsent("no limit"));
  }
};

struct SimulateRequest : SimulateParams {
  Front front = Front::Cli;
};

/// What the study tells its front end while it runs: a warning as soon as it is known
/// (the table program's, the run's), and each run's progress: `what` names the quantity
/// ("time run, seconds simulated"), `done` of `total`, `detail` the contract's stage.
struct SimulateHooks {
  std::function<void(const std::string& warning)> warn;
  std::function<void(const std::string& what, double done, double total, const std::string& detail)> progress;
};

struct SimulateStudy {
  SimulationResult result;
  std::vector<std::string> warnings;   ///< every warning of the run, as in summary.json
  std::optional<TargetOutcome> target; ///< the contract's choice (target_error)
  SimulationSpec spec;                 ///< the settings run (the contract's integrator and accuracy)
  int segments_chosen = 0;             ///< the contract's segments per link (0: the scene's)
  nlohmann::ordered_json summary;      ///< summary.json, `simulate --json`
  std::string text;
};

/// Checks every option (UsageError naming it) before any model is built, then runs.
SimulateStudy runSimulateStudy(const Scene& scene, const SimulateRequest& request, const SimulateHooks& hooks = {});

}  // namespace mmv::app
