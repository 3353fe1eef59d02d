#pragma once
/// The accuracy contract of a time run (`simulate --target-error E`): the tool picks
/// the cheapest integrator, tolerance and segments per link that meet E on the scored
/// points, runs it, verifies it and reports what it chose and what it cost, or says
/// that E cannot be met within the time budget.
///
///  0. The scene's own run first (its fidelity, sim/time/fidelity.hpp, and integrator;
///     `--integrator` names another): the whole run and a companion at a 10x tighter
///     tolerance, links in modal coordinates with their modes up to twice the frequency (as `--verify`).
///     Met as below, it is the choice, for 2-4x its own cost. Missed by less than 10x E,
///     the companion (paid for) becomes the run against one 10x tighter again, twice at
///     most; else (or when the run fails) the steps below follow. The first companion is
///     recorded in full (a narrow miss hands it the run); later ones, which seldom
///     become the run, record the scored points only (SimulationSpec::scored_only) and
///     are run again in full when they do.
///  1. Pilot: a trade (sim/time/trade.hpp) on the run's first `window` seconds (20 %
///     of the run, at least 1 s, at most the run), every integrator from its loosest
///     tolerance, runs that pass the cheapest one within the target cut short, then
///     the segment ladder (the scene's count / 2, / 4, at least 2) with the cheapest
///     run's integrator and tolerance. The window's target is E scaled by window /
///     duration: an integrator's error grows with the time integrated, at most about
///     linearly for a stable run, so a run within the scaled target on the window is
///     expected within E over the whole run.
///  2. The cheapest pilot run within the window's target is run over the whole
///     duration and verified by a companion at the scene's own segments and a 10x
///     tighter tolerance (sim/time/verify.hpp): the companion's difference estimates
///     the run's integration and (with fewer segments) discretization error against the
///     scene's model.
///     The run meets E when the estimate is within E / 2 (the margin for a companion
///     whose own error is not a tenth of the run's) and its energy balance holds at
///     every sample (a run its own summary calls inaccurate is not accepted; the pilot
///     asks the same of its runs).
///  3. A run whose estimate misses E / 2 is replaced by its companion (the next tighter
///     fidelity) with a new companion at a further 10x tighter tolerance, until the
///     estimate meets E, the tolerance passes 1e-12, or the time budget is spent.
///
/// Refused before the pilot: E at or below the pilot reference's own uncertainty (the
/// two 1e-10 runs' difference): nothing can verify it. The segments' error is measured
/// against the scene's segment count (the model the user wrote), not the continuum:
/// `converge` measures that.

#include <functional>
#include <string>
#include <vector>

#include "sim/time/trade.hpp"

namespace mmv {

struct TargetOptions {
  double target_m = 0;              ///< E, > 0.
  std::vector<std::string> points;  ///< scored points; empty: the scene's score_points, else every tip.
  std::vector<std::string> integrators;  ///< candidates; empty: TradeOptions' default list.
  double time_budget_s = 0;         ///< > 0: the whole choice, run and verification within it.
  bool scene_run_first = true;      ///< step 0 below (false: the pilot at once)
};

/// One whole-duration run and its verification.
struct TargetAttempt {
  std::string integrator;
  double accuracy = 0;
  int segments = 0;  ///< 0: the scene's.
  int modes = 0;     ///< per link; 0: every hinge.
  double run_seconds = 0, companion_seconds = 0;  ///< companion_seconds 0 when reused
  bool companion_reused = false;  ///< held to the previous attempt's companion (a modal run with more modes)
  double estimated_error_m = 0, at_s = 0;
  std::string point;
  bool energy_ok = true;  ///< the run's energy balance held at every sample (no energyBalanceWarning)
  bool met = false;       ///< the estimate within E / 2 and the energy balance held
  /// Non-empty: the scene's own run (step 0 above) and its model (FidelityChoice::reason),
  /// verified at a 10x tighter tolerance (links in modal coordinates: modes to twice the frequency).
  std::string model;
  bool companion_more_modes = false;  ///< its companion kept its modal links' modes up to twice the frequency
  bool failed = false;  ///< the run stopped (its integrator gave up; `model` says why): the pilot follows
};

struct TargetOutcome {
  double target_m = 0;
  double window_s = 0, window_target_m = 0;
  TradeStudy pilot;                    ///< the window's trade.
  std::vector<TargetAttempt> attempts; ///< in order; the last met the target.
  double total_seconds = 0;            ///< pilot, runs and verifications.
  bool has_segments = true;            ///< the scene has flexible links (a segment count to choose).
  SimulationResult result;             ///< the last attempt's run, its verification filled.
};

/// Runs the contract above on `problem` (the scene's whole run). Throws NumericalError
/// when E cannot be met (below the reference's resolution, or within the budget: the
/// message names the best estimate reached and what it cost), UsageError for a point
/// the problem does not score. `stage` is told what is under way ("pilot", "run",
/// "verification") with the fraction of it done.
TargetOutcome runToTarget(const TradeProblem& problem, const TargetOptions& options,
                          const std::function<void(const std::string& stage, double fraction)>& stage = {});

}  // namespace mmv
