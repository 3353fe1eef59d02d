#include "sim/time/target.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/time/verify.hpp"

namespace mmv {
namespace {

constexpr double kWindowFraction = 0.2;  ///< of the run, the pilot's window
constexpr double kMinWindowS = 1.0;
constexpr double kTightestAccuracy = 1e-12;
/// Step 0's ladder: when the scene's own run misses by at most this times E, its
/// companion (already paid for) becomes the run, at most kOwnLadderSteps times; further
/// off, the pilot looks for another integrator.
constexpr double kOwnLadderReach = 10;
constexpr int kOwnLadderSteps = 2;
/// A run meets E when its estimate is within E / 2: the companion's own error is not
/// always a tenth of the run's (CVODE Adams on the 170 deg pendulum at 1e-7: estimate
/// 6.9e-5 m against a true 1.07e-4 m), and the estimate is within a factor of two of the
/// true error for the integrators tested (tests/sim/time/verify_test.cpp).
constexpr double kEstimateMargin = 1 / kVerifySafetyFactor;  // the same safety as --verify

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// The fidelity of one run: integrator, tolerance, segments (0: the scene's) and modes
/// per link (0: every hinge).
struct Fidelity {
  std::string integrator;
  double accuracy = 0;
  int segments = 0;
  int modes = 0;
};

std::string describe(const Fidelity& f) {
  return strf("%s at %g", f.integrator.c_str(), f.accuracy) + (f.segments ? strf(", %d segments", f.segments) : "") +
         (f.modes ? strf(", %d modes per link", f.modes) : "");
}

class TargetRunner {
 public:
  TargetRunner(const TradeProblem& problem, const TargetOptions& o,
               const std::function<void(const std::string&, double)>& stage)
      : problem_(problem), o_(o), stage_(stage) {
    MMV_DEMAND(o.target_m > 0);
    out_.target_m = o.target_m;
    out_.has_segments = problem.has_segments;
  }

  TargetOutcome run() {
    if (sceneDefault()) return out_;
    const Fidelity first = pilot();
    chosen_accuracy_ = first.accuracy;
    Fidelity run = first;
    Fidelity companion = tighter(run);
    SimulationResult result = wholeRun(run, "run");
    SimulationResult tight;
    bool verified_by_tight = false;  // `tight` is the companion's run
    bool more_modes_tried = false;
    for (;;) {
      const bool reused = verified_by_tight;
      if (!verified_by_tight) tight = wholeRun(companion, "verification");
      verified_by_tight = true;
      TargetAttempt a = measure(run, result, tight, reused);
      if (a.met) {
        result.verification = verification(a, companion, tight);
        out_.result = std::move(result);
        out_.total_seconds = since(t0_);
        return out_;
      }
      // A modal run that missed: once, twice its modes at the same tolerance, held to the
      // same companion (the segment model at 10x tighter: the modes do not change it).
      if (run.modes > 0 && !more_modes_tried && run.modes + 1 < problem_.finest_segments) {
        more_modes_tried = true;
        run.modes = std::min(2 * run.modes, problem_.finest_segments - 1);
        result = wholeRun(run, "run");
        continue;
      }
      if (companion.accuracy / 10 < kTightestAccuracy * (1 - 1e-9))  // (the decades are products: a rounding margin)
        throw NumericalError(strf("--target-error %.3g m cannot be met: %s is %.3g m off at %s (t = %.4g s) and a tighter "
                                  "tolerance than %g cannot be verified",
                                  o_.target_m, describe(run).c_str(), a.estimated_error_m, a.point.c_str(), a.at_s,
                                  companion.accuracy));
      run = companion;  // the next tighter fidelity: the companion already ran it
      result = tight;
      companion = tighter(run);
      verified_by_tight = false;
    }
  }

 private:
  /// The same integrator at a 10x tighter tolerance, at the scene's segments with every
  /// hinge its own coordinate: what a reduced model leaves out is in the estimate.
  static Fidelity tighter(const Fidelity& f) { return {f.integrator, f.accuracy / 10, 0, 0}; }

  /// The attempt `result` at `f` makes against `companion` (its run reused when
  /// `reused`), recorded; `model` non-empty for the scene's own run.
  TargetAttempt measure(const Fidelity& f, const SimulationResult& result, const SimulationResult& companion, bool reused,
                        const std::string& model = {}) {
    TargetAttempt a;
    a.integrator = f.integrator;
    a.accuracy = f.accuracy;
    a.segments = f.segments;
    a.modes = f.modes;
    a.model = model;
    a.companion_more_modes = !model.empty() && !result.modal_links.empty();
    a.run_seconds = result.wall_seconds;
    a.companion_seconds = reused ? 0.0 : companion.wall_seconds;
    a.companion_reused = reused;
    const ScoredDistance d = scoredDistance(result.record, companion.record, points_);
    a.estimated_error_m = d.distance_m;
    a.at_s = d.at_s;
    a.point = d.point;
    a.energy_ok = energyBalanceWarning(result).empty();
    a.met = d.distance_m <= kEstimateMargin * o_.target_m && a.energy_ok;
    out_.attempts.push_back(a);
    return a;
  }

  /// Step 0: the scene's own model over the whole run, held to a companion with twice its
  /// modes at a 10x tighter tolerance; true when it meets E (out_ then holds it).
  bool sceneDefault() {
    if (!problem_.run_default || !o_.scene_run_first) return false;
    SimulationSpec spec = problem_.simulation;
    spec.integrator = o_.integrators.empty() ? problem_.default_integrator : o_.integrators.front();
    TradeOptions named;
    named.points = o_.points;
    points_ = scoredPoints(problem_, named);
    spec.score_points = points_;
    const auto run = [&](const SimulationSpec& sp, int refinement, const std::string& what) {
      checkBudget("the " + what);
      try {
        return problem_.run_default(sp, refinement, [&](double fraction) {
          if (stage_) stage_(what, fraction);
          if (o_.time_budget_s > 0 && since(t0_) > o_.time_budget_s) throw RunBudgetExceeded(fraction, since(t0_), true);
        });
      } catch (const RunBudgetExceeded&) {
        checkBudget("the " + what);
        throw;
      } catch (const NumericalError& e) {  // the integrator gave up: the pilot may find one that does not
        throw OwnRunFailed{e.what()};
      }
    };
    try {
      return ownLadder(spec, run);
    } catch (const OwnRunFailed& f) {
      TargetAttempt a;
      a.integrator = spec.integrator;
      a.accuracy = spec.accuracy;
      a.model = "the scene's own run failed: " + f.what;
      a.failed = true;
      out_.attempts.push_back(a);
      return false;
    }
  }

  struct OwnRunFailed {
    std::string what;
  };

  /// Step 0's runs: the scene's own, then its companions as runs (see kOwnLadderReach).
  template <class Run>
  bool ownLadder(SimulationSpec spec, const Run& run) {
    // The scene's own run, then (when it misses by less than kOwnLadderReach) its
    // companion as the run, already paid for, against one 10x tighter again.
    SimulationResult result = run(spec, 0, "run: the scene's own model");
    for (int refinement = 0; refinement <= kOwnLadderSteps; ++refinement) {
      SimulationSpec tight = spec;
      tight.accuracy /= 10;
      tight.absolute_tolerance /= 10;
      // The first companion is recorded in full: a scene's own run that misses narrowly
      // hands it the run. Later ones record the scored points only (all the comparison
      // reads) and are run again in full on the rare second miss.
      tight.scored_only = refinement > 0;
      SimulationResult companion = run(tight, refinement + 1, "verification: the scene's own model, 10x tighter");
      TargetAttempt a = measure({spec.integrator, spec.accuracy, 0, 0}, result, companion, false, result.fidelity);
      if (a.met) {
        result.verification = verification(a, {spec.integrator, tight.accuracy, 0, 0}, companion);
        result.verification.companion_more_modes = a.companion_more_modes;
        out_.result = std::move(result);
        out_.total_seconds = since(t0_);
        return true;
      }
      if (a.estimated_error_m > kOwnLadderReach * o_.target_m || tight.accuracy / 10 < kTightestAccuracy * (1 - 1e-9)) break;
      spec = tight;
      spec.scored_only = false;
      result = tight.scored_only ? run(spec, refinement + 1, "run: the scene's own model, recorded in full")
                                 : std::move(companion);
    }
    return false;
  }

  /// The window's trade, and its cheapest run within the window's target.
  Fidelity pilot() {
    const double duration = problem_.duration;
    out_.window_s = std::min(duration, std::max(kWindowFraction * duration, kMinWindowS));
    out_.window_target_m = o_.target_m * out_.window_s / duration;
    TradeProblem window = problem_;
    window.duration = out_.window_s;
    window.simulation.duration = out_.window_s;
    TradeOptions t;
    // Implicit methods first: on a stiff article one of them is cheap within the target
    // early, and the explicit ones are then cut at its cost (the choice does not depend
    // on the order: a run cut at that cost cannot be the cheapest).
    t.integrators = o_.integrators.empty()
                        ? std::vector<std::string>{"cvode_bdf", "cpodes", "arkode_dirk", "rk3", "rk_merson", "arkode_erk", "cvode_adams"}
                        : o_.integrators;
    t.accuracies = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
    t.segments.clear();
    for (int n = problem_.finest_segments / 2; n >= 2; n /= 2) t.segments.push_back(n);
    t.points = o_.points;
    t.target_m = out_.window_target_m;
    t.cut_costlier = true;
    t.ladder_at_cheapest = true;
    if (o_.time_budget_s > 0) t.total_budget_s = budgetLeft();
    window.run = [this, inner = problem_.run](const SimulationSpec& spec, const RunFidelity& f,
                                               const std::function<void(double)>& cut) {
      stage_ ? stage_("pilot: " + describe({spec.integrator, spec.accuracy, f.segments, f.modes}), 0.0) : void();
      return inner(spec, f, cut);
    };
    out_.pilot = runTrade(window, t);
    points_ = out_.pilot.points;
    const double floor = out_.pilot.reference_uncertainty_m;
    if (o_.target_m <= 3 * floor)
      throw NumericalError(strf("--target-error %.3g m cannot be verified: the two reference runs at 1e-10 differ by %.3g m "
                                "over the first %g s; ask for more than 3x that",
                                o_.target_m, floor, out_.window_s));
    // A modal run must come within half the window's target, the margin its whole run
    // is held to: what the modes leave out grows with what the run goes on to excite
    // (the slew scene's table sweep rises to 8 Hz), which the window does not see.
    const TradeRun* best = nullptr;
    for (const auto& r : out_.pilot.runs)
      if (r.ok && r.error_m <= (r.modes > 0 ? kEstimateMargin : 1.0) * out_.window_target_m && r.energy_ok &&
          (!best || r.seconds < best->seconds))
        best = &r;
    if (!best) {
      checkBudget("the pilot");
      throw NumericalError(strf("--target-error %.3g m cannot be met: no run of the pilot came within %.3g m over the first "
                                "%g s (the tightest tolerance tried is 1e-8)",
                                o_.target_m, out_.window_target_m, out_.window_s));
    }
    return {best->integrator, best->accuracy, best->segments, best->modes};
  }

  double budgetLeft() const { return std::max(o_.time_budget_s - since(t0_), 1e-3); }

  /// Throws when the time budget is spent, naming what was under way.
  void checkBudget(const std::string& what) const {
    if (!(o_.time_budget_s > 0) || since(t0_) <= o_.time_budget_s) return;
    std::string best;
    if (!out_.attempts.empty()) {
      const TargetAttempt& a = out_.attempts.back();
      best = strf("; the last run verified (%s) is %.3g m off", describe({a.integrator, a.accuracy, a.segments, a.modes}).c_str(),
                  a.estimated_error_m);
    }
    throw NumericalError(strf("--target-error %.3g m cannot be met within the %g s budget: it was spent during %s after "
                              "%.3g s%s",
                              o_.target_m, o_.time_budget_s, what.c_str(), since(t0_), best.c_str()));
  }

  /// The whole run at `f`, cut when the budget is spent.
  SimulationResult wholeRun(const Fidelity& f, const std::string& what) {
    checkBudget("the " + what);
    SimulationSpec spec = problem_.simulation;
    spec.score_points = points_;
    spec.integrator = f.integrator;
    spec.accuracy = f.accuracy;
    if (!isSundialsIntegrator(f.integrator)) spec.absolute_tolerance = 0;
    else spec.absolute_tolerance *= f.accuracy / chosen_accuracy_;  // tightened with the relative one
    const std::string label = what + ": " + describe(f);
    try {
      return problem_.run(spec, {f.segments, f.modes}, [&](double fraction) {
        if (stage_) stage_(label, fraction);
        if (o_.time_budget_s > 0 && since(t0_) > o_.time_budget_s) throw RunBudgetExceeded(fraction, since(t0_), true);
      });
    } catch (const RunBudgetExceeded&) {
      checkBudget("the " + label);
      throw;
    }
  }

  RunVerification verification(const TargetAttempt& a, const Fidelity& companion, const SimulationResult& tight) const {
    RunVerification v;
    v.done = true;
    v.companion_accuracy = companion.accuracy;
    v.companion_seconds = a.companion_seconds;
    v.estimated_error_m = a.estimated_error_m;
    v.at_s = a.at_s;
    v.point = a.point;
    v.amplitude_m = scoredAmplitude(tight.record, points_);
    v.target_m = o_.target_m;
    v.target_is_default = false;
    return v;
  }

  const TradeProblem& problem_;
  const TargetOptions& o_;
  const std::function<void(const std::string&, double)>& stage_;
  std::vector<std::string> points_;
  double chosen_accuracy_ = 1;  ///< the pilot's choice: the scene's absolute tolerance goes with it
  TargetOutcome out_;
  const Clock::time_point t0_ = Clock::now();
};

}  // namespace

TargetOutcome runToTarget(const TradeProblem& problem, const TargetOptions& options,
                          const std::function<void(const std::string& stage, double fraction)>& stage) {
  MMV_DEMAND(options.target_m > 0);  // checked by the study (sim/app/simulate_study.cpp)
  return TargetRunner(problem, options, stage).run();
}

}  // namespace mmv
