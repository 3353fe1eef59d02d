#pragma once
/// The speed-accuracy trade of a time run: every integrator over a ladder of
/// tolerances, and the segments per link over a ladder, against a tight reference.
///
/// Error: the largest distance, over the samples and the scored points (every link tip,
/// or the tips the user names; for HAM-SAS the optical table and the spring box), between
/// a run's positions and the reference's (m). The reference is CPodes at accuracy 1e-10,
/// and CVODE BDF at 1e-10 is run too: their largest difference is the reference's own
/// uncertainty (errors below it cannot be told apart). For HAM-SAS the pair is RK-Merson
/// and ARKODE ERK at 1e-10: the isolator's lightly damped kHz joint modes keep BDF at
/// low order, which makes a tight BDF run cost minutes (docs/hamsas.md); the segment
/// ladder does not apply (rigid bodies). Cost: wall-clock CPU seconds and
/// right-hand-side evaluations (realizations). A run is on the Pareto front when no
/// other run is both cheaper and more accurate. A run that fails is listed with its
/// diagnostic instead of numbers.
///
/// A run is within the target when its error is and its energy balance holds at every
/// sample (TradeRun::energy_ok): no run its own summary would call inaccurate is named
/// the cheapest, or cuts and skips others.
///
/// On a budget: each integrator's tolerances run from the loosest to the tightest, and
///  - a run is skipped as costlier when a looser run of the same integrator already
///    cost more than the cheapest run within the target (a tighter tolerance never costs
///    an integrator less, so it could only be dearer than a run that already meets the
///    target: it cannot be the answer; `--all` runs it anyway, for the whole picture);
///  - a run is cut when it exceeds the per-run budget (checked at every sample) and
///    listed as over budget; once the total budget is spent the run under way is cut and
///    the remaining ones are listed as not run, so the trade ends within the total budget
///    plus a sample. The two reference runs are never cut: every error needs them.

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"
#include "sim/time/simulation.hpp"

namespace mmv {

/// Thrown from a run's progress callback when it exceeds the per-run budget.
struct RunBudgetExceeded : std::runtime_error {
  RunBudgetExceeded(double fraction_done, double after_s, bool total_budget, bool costlier_run = false)
      : std::runtime_error("run budget exceeded"),
        fraction(fraction_done),
        seconds(after_s),
        total(total_budget),
        costlier(costlier_run) {}
  double fraction, seconds;
  bool total;     ///< the trade's total budget, not the run's own
  bool costlier;  ///< cut as it passed the cost of the cheapest run within the target
};

/// What a run models: segments per flexible link (0: the scene's) and modes per link
/// (links in modal coordinates, sim/time/modal_links.hpp; each link at most its hinges;
/// 0: every hinge its own coordinate, whatever the scene says).
struct RunFidelity {
  int segments = 0;
  int modes = 0;
};

struct TradeRun {
  std::string integrator;
  double accuracy = 0;
  int segments = 0;  ///< 0: the scene's.
  int modes = 0;     ///< modes per link; 0: every hinge.
  bool ok = true;
  /// Why a run has no numbers: "failed" (the integrator's diagnostic in `failure`),
  /// "over_budget" (cut), "costlier" or "not_run" (skipped; `failure` says why); "ok".
  std::string status = "ok";
  std::string failure = {};
  double error_m = 0, seconds = 0;
  long evaluations = 0;
  bool pareto = false;
  /// The run's energy balance held within 1 % of its energy scale at every sample
  /// (energyBalanceWarning, sim/time/simulation.hpp).
  bool energy_ok = true;
};

struct TradeOptions {
  std::vector<std::string> integrators{"rk_merson", "rk3", "cpodes", "cvode_bdf", "cvode_adams", "arkode_erk", "arkode_dirk"};
  std::vector<double> accuracies{1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
  std::vector<int> segments{2, 4, 8};  ///< with the reference integrator at 1e-8 (compared to the scene's segments).
  /// Modes per link (fewer than the most hinges of a link), each run by `modes_integrator`
  /// over `modes_accuracies` as one more integrator of the grid (the same skipping):
  /// the reduced model's error against the segment reference and its cost.
  std::vector<int> modes{1, 2, 3, 4};
  std::string modes_integrator = "cvode_bdf";
  std::vector<double> modes_accuracies{1e-5, 1e-6, 1e-7};
  double duration = 0;  ///< 0: the scene's.
  std::vector<std::string> points;  ///< tips scored, e.g. "link3a.tip"; empty: every link tip.
  double target_m = 0;        ///< the error to meet; 0: defaultTradeTarget of the reference run.
  bool skip_costlier = true;  ///< skip the runs a looser run of their integrator shows cannot be the answer (above).
  double run_budget_s = 0;     ///< > 0: a run's wall-time limit (the reference runs excepted).
  double total_budget_s = 0;   ///< > 0: no run starts once the trade has taken this long.
  /// Cut a run (status "costlier") once it has cost more than the cheapest run within
  /// the target: it cannot be the answer, and its error is not wanted (the choice of
  /// `simulate --target-error`, sim/time/target.hpp; a trade shows every error).
  bool cut_costlier = false;
  /// Run the segment ladder with the cheapest integrator run within the target (its
  /// integrator and tolerance) instead of the reference integrator at 1e-8, and the
  /// modes ladder at its tolerance (with its integrator when that is one of SUNDIALS'
  /// ODE methods, else `modes_integrator`): the cheapest fidelity with that integrator;
  /// none within the target: no ladders.
  bool ladder_at_cheapest = false;
};

struct TradeStudy {
  std::string scene_name;
  double duration = 0;
  std::vector<std::string> points;  ///< as TradeOptions::points.
  std::string reference_integrator = "cpodes", check_integrator = "cvode_bdf";  ///< both at 1e-10.
  double reference_uncertainty_m = 0;
  /// The scored points' largest distance from where they start, in the reference run
  /// (m): the scale a default target is taken from.
  double reference_amplitude_m = 0;
  double reference_scale_m = 0;  ///< the scored points' extent (scoredScale)
  double reference_seconds = 0;
  double target_m = 0;        ///< the target the skipping used (TradeOptions::target_m or the default).
  double total_seconds = 0;   ///< the whole trade's wall time.
  std::vector<TradeRun> runs;
};

/// The target a trade names the cheapest run for when the user gives none: 1 % of the
/// reference's largest scored motion (a fixed length would be met by every run of a
/// micrometre isolator and by none of a metre slew); 1e-4 m if nothing moved.
double defaultTradeTarget(const TradeStudy& s);

/// What a trade runs: one kind of scene's time run as a function of the integrator
/// settings and the segments per link. Made by articleTradeProblem (below) or, for
/// the isolator, hamsasTradeProblem (sim/hamsas/hamsas_simulation.hpp).
struct TradeProblem {
  std::string scene_name;
  double duration = 0;                  ///< s.
  SimulationSpec simulation;            ///< the scene's settings (duration applied).
  std::vector<std::string> scorable;    ///< the names a trade can score.
  std::string scorable_kind;            ///< "link tip", "scored body": for messages.
  /// Other names it can score (the article's stations, `link1@0.75`): true, or false
  /// with `error` saying why; none: only `scorable`.
  std::function<bool(const std::string& name, std::string& error)> also_scores;
  std::string reference_integrator = "cpodes", check_integrator = "cvode_bdf";
  bool has_segments = true;             ///< rigid bodies only: no segment ladder.
  bool has_modes = false;               ///< links that can run in modal coordinates (planar open trees).
  int finest_segments = 0;              ///< the most segments of a flexible link (0: none).
  /// Runs with `spec` at `fidelity`, calling `progress` with the fraction done at every
  /// sample (it may throw to cut the run short).
  std::function<SimulationResult(const SimulationSpec& spec, const RunFidelity& fidelity,
                                 const std::function<void(double)>& progress)>
      run;
  /// The scene's own run (its fidelity, sim/time/fidelity.hpp) with `spec`, links in modal
  /// coordinates keeping 2^`refinement` times their modes; empty where there is none to
  /// try (the isolator). The contract tries it first (sim/time/target.hpp).
  std::function<SimulationResult(const SimulationSpec& spec, int refinement, const std::function<void(double)>& progress)>
      run_default;
  std::string default_integrator;   ///< the integrator the scene's run uses (chosen when it names none)
};

/// A problem's common part: the scene's name and simulation settings, with `duration`
/// > 0 overriding the scene's (s). The caller adds what it scores and how it runs.
TradeProblem tradeProblemBase(const std::string& scene_name, SimulationSpec simulation, double duration);

/// The article's trade problem; `duration` > 0 overrides the scene's.
TradeProblem articleTradeProblem(const ArticleScene& scene, double duration = 0);

/// The points a trade or the contract scores: `options.points`, else the scene's
/// `score_points` (empty: every one), each checked (SceneError at the scene's key,
/// OptionError for --points).
std::vector<std::string> scoredPoints(const TradeProblem& problem, const TradeOptions& options);

/// Throws, before running anything, when a scored point is not one the problem
/// scores: SceneError at simulation.score_points for the scene's, UsageError for
/// options.points (the message lists the known ones).
TradeStudy runTrade(const TradeProblem& problem, const TradeOptions& options);

}  // namespace mmv
