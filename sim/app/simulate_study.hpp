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

#include "sim/app/study.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/target.hpp"

namespace mmv::app {

/// Every number is optional: absent, the scene's setting (or the option's default) holds;
/// present, it is checked (an explicit 0 duration is refused, not read as "the scene's").
struct SimulateRequest {
  std::string integrator;                     ///< empty: the scene's; else a name of the integrator table.
  std::optional<double> accuracy;             ///< (0, 1)
  std::optional<double> absolute_tolerance;   ///< > 0, SUNDIALS integrators only
  std::optional<double> duration;             ///< s, > 0
  std::optional<double> sample_rate;          ///< rows per second, > 0
  bool verify = false;                        ///< a companion run at tolerance / 10
  std::optional<double> verify_target;        ///< m, > 0, implies verify; absent: 1 % of the scored motion
  std::optional<double> target_error;         ///< m, > 0: the cheapest run that meets it
  std::vector<std::string> points;            ///< where target_error is held; empty: the scene's, else every tip
  std::optional<double> time_budget;          ///< s, > 0: the target within it
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
