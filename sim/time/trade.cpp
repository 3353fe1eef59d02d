#include "sim/time/trade.hpp"

#include "sim/time/fidelity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

#include "article/article_spec.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/scene/stations.hpp"
#include "sim/time/verify.hpp"

namespace mmv {

double defaultTradeTarget(const TradeStudy& s) {
  return defaultErrorTarget(s.reference_amplitude_m, s.reference_scale_m);
}

TradeProblem tradeProblemBase(const std::string& scene_name, SimulationSpec simulation, double duration) {
  TradeProblem p;
  if (duration > 0) simulation.duration = duration;
  if (simulation.duration * simulation.sample_rate_hz > limits::kMaxSamples)
    throw OptionError("--duration", strf(" %g s at the scene's %g Hz is %.3g samples, above the limit of %.0f a run",
                          simulation.duration, simulation.sample_rate_hz, simulation.duration * simulation.sample_rate_hz,
                          limits::kMaxSamples));
  p.scene_name = scene_name;
  p.duration = simulation.duration;
  p.simulation = simulation;
  return p;
}

TradeProblem articleTradeProblem(const ArticleScene& base, double duration) {
  TradeProblem p = tradeProblemBase(base.name, base.simulation, duration);
  ArticleScene scene = base;
  scene.simulation = p.simulation;
  for (const auto& name : articlePointNames(scene.article))
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tip") == 0) p.scorable.push_back(name);
  p.scorable_kind = "link tip";
  for (const auto& l : scene.article.links)
    if (!l.rigid) p.finest_segments = std::max(p.finest_segments, l.segments);
  p.has_segments = p.finest_segments > 0;
  // Links in modal coordinates need a planar open tree; a shaker's stinger closes it in
  // time runs (sim/model/attachments.hpp).
  p.has_modes = p.has_segments && modalLinksAllowed(scene);
  const ArticleSpec article = scene.article;
  p.also_scores = [article](const std::string& name, std::string& error) {
    return isStationName(name) && parseStation(name, article, error).has_value();
  };
  p.run = [scene](const SimulationSpec& spec, const RunFidelity& f, const std::function<void(double)>& progress) {
    ArticleScene s = scene;
    s.simulation = spec;
    s.simulation.fidelity = SimulationSpec::Fidelity::Segments;  // the run's fidelity is f's, as named
    if (f.segments > 0) overrideSegments(s, f.segments);
    for (auto& l : s.article.links) l.modes = l.rigid ? 0 : std::min(f.modes, l.segments);
    return simulate(s, progress);
  };
  ArticleScene probe = scene;
  resolveFidelity(probe);
  p.default_integrator = probe.simulation.integrator;
  p.run_default = [scene](const SimulationSpec& spec, int refinement, const std::function<void(double)>& progress) {
    ArticleScene s = scene;
    s.simulation = spec;
    s.simulation.fidelity = scene.simulation.fidelity;
    s.simulation.modal_refinement = refinement;
    return simulate(s, progress);
  };
  return p;
}

std::vector<std::string> scoredPoints(const TradeProblem& problem, const TradeOptions& options) {
  const SimulationSpec& spec0 = problem.simulation;
  const bool from_scene = options.points.empty() && !spec0.score_points.empty();
  const std::vector<std::string> points = from_scene ? spec0.score_points : options.points;
  for (const auto& p : points) {
    if (std::find(problem.scorable.begin(), problem.scorable.end(), p) != problem.scorable.end()) continue;
    std::string error;
    if (problem.also_scores && problem.also_scores(p, error)) continue;
    std::string known;
    for (const auto& t : problem.scorable) known += (known.empty() ? "" : ", ") + t;
    if (problem.also_scores) known += ", or a station <link>@<m>m or <link>@<fraction>";
    const std::string what = error.empty() ? "'" + p + "' is not a " + problem.scorable_kind + " of the scene (known: " + known + ")"
                                           : "'" + p + "': " + error;
    if (from_scene) throw SceneError(spec0.score_where + ": simulation.score_points: " + what);
    throw OptionError("--points", ": " + what);
  }
  return points;
}

namespace {

/// One trade: the references, then every run measured, skipped or cut (trade.hpp).
class TradeRunner {
 public:
  TradeRunner(const TradeProblem& problem, TradeOptions options) : problem_(problem), o_(std::move(options)) {
    study_.scene_name = problem.scene_name;
    study_.points = o_.points;
    study_.duration = problem.duration;
    study_.reference_integrator = problem.reference_integrator;
    study_.check_integrator = problem.check_integrator;
  }

  TradeStudy run() {
    // The references are compared on the scored points only: recorded there alone.
    reference_ = simulateWith({}, study_.reference_integrator, 1e-10, {}, true);
    const SimulationResult check = simulateWith({}, study_.check_integrator, 1e-10, {}, true);
    study_.reference_uncertainty_m = scoredDistance(reference_.record, check.record, o_.points).distance_m;
    study_.reference_amplitude_m = scoredAmplitude(reference_.record, o_.points);
    study_.reference_scale_m = scoredScale(reference_.record, o_.points);
    study_.reference_seconds = reference_.wall_seconds;
    study_.target_m = o_.target_m > 0 ? o_.target_m : defaultTradeTarget(study_);
    integratorGrid();
    if (problem_.has_segments) segmentLadder();  // rigid bodies: no segments
    markParetoFront();
    study_.total_seconds = elapsed();
    return study_;
  }

 private:
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }

  SimulationResult simulateWith(const RunFidelity& f, const std::string& integrator, double accuracy,
                                const std::function<void(double)>& progress, bool scored_only = false) const {
    SimulationSpec spec = problem_.simulation;
    spec.scored_only = scored_only;
    spec.score_points = o_.points;  // every run records the points scored (stations among them)
    spec.integrator = integrator;
    spec.accuracy = accuracy;
    // The scene's absolute tolerance applies to SUNDIALS' methods only.
    if (!isSundialsIntegrator(integrator)) spec.absolute_tolerance = 0;
    return problem_.run(spec, f, progress);
  }

  /// One scored run: its error against the reference and its cost, or why it has none.
  const TradeRun& measure(const RunFidelity& f, const std::string& integrator, double accuracy) {
    TradeRun r{integrator, accuracy, f.segments, f.modes};
    const auto started = std::chrono::steady_clock::now();
    auto cut = [&](double fraction) {  // the per-run and the total budget, checked at every sample
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (o_.run_budget_s > 0 && s > o_.run_budget_s) throw RunBudgetExceeded(fraction, s, false);
      if (o_.total_budget_s > 0 && elapsed() > o_.total_budget_s) throw RunBudgetExceeded(fraction, s, true);
      if (o_.cut_costlier && s > cheapestWithinTarget()) throw RunBudgetExceeded(fraction, s, false, true);
    };
    if (o_.total_budget_s > 0 && elapsed() > o_.total_budget_s)
      return skip(r, "not_run", strf("not run: the trade's %g s budget was spent", o_.total_budget_s));
    try {
      const SimulationResult res = simulateWith(f, integrator, accuracy, cut);
      r.error_m = scoredDistance(res.record, reference_.record, o_.points).distance_m;
      r.seconds = res.wall_seconds;
      r.evaluations = res.realizations;
      r.energy_ok = energyBalanceWarning(res).empty();
    } catch (const NumericalError& e) {
      return skip(r, "failed", e.what());
    } catch (const RunBudgetExceeded& e) {
      r.seconds = e.seconds;  // what it cost before the cut (a cut run's tighter tolerances cost more)
      if (e.costlier)
        return skip(r, "costlier", strf("cut after %.3g s at %.0f %% of the run: costlier than the cheapest run within the "
                                        "target (%.3g s)", e.seconds, 100 * e.fraction, cheapestWithinTarget()));
      if (e.total)
        return skip(r, "not_run", strf("cut after %.3g s at %.0f %% of the run: the trade's %g s budget was spent",
                                       e.seconds, 100 * e.fraction, o_.total_budget_s));
      return skip(r, "over_budget", strf("over its %g s budget: cut after %.3g s at %.0f %% of the run", o_.run_budget_s,
                                         e.seconds, 100 * e.fraction));
    }
    study_.runs.push_back(r);
    return study_.runs.back();
  }

  /// `r` listed without numbers, with its status and why.
  const TradeRun& skip(TradeRun r, const std::string& status, const std::string& why) {
    r.ok = false;
    r.status = status;
    r.failure = why;
    study_.runs.push_back(r);
    return study_.runs.back();
  }

  /// The cheapest run within the target so far (its cost in seconds, infinity if none).
  double cheapestWithinTarget() const {
    const TradeRun* best = cheapestRunWithinTarget();
    return best ? best->seconds : INFINITY;
  }
  const TradeRun* cheapestRunWithinTarget() const {
    const TradeRun* best = nullptr;
    for (const auto& r : study_.runs)
      if (r.ok && r.error_m <= study_.target_m && r.energy_ok && (!best || r.seconds < best->seconds))
        best = &r;
    return best;
  }

  /// The segments ladder: with the reference integrator at 1e-8, or with the cheapest
  /// run within the target (TradeOptions::ladder_at_cheapest), from the finest count
  /// down, stopping at the first count that misses the target (a coarser one would too).
  void segmentLadder() {
    if (!o_.ladder_at_cheapest) {
      for (int n : o_.segments) measure({n, 0}, "cpodes", 1e-8);
      return;
    }
    const TradeRun* best = cheapestRunWithinTarget();
    if (!best) return;
    const std::string integrator = best->integrator;
    const double accuracy = best->accuracy;
    std::vector<int> fine_to_coarse = o_.segments;
    std::sort(fine_to_coarse.begin(), fine_to_coarse.end(), std::greater<int>());
    for (int n : fine_to_coarse) {
      const TradeRun& r = measure({n, best->modes}, integrator, accuracy);
      if (!r.ok || r.error_m > study_.target_m) break;
    }
  }

  /// One integrator's tolerances, loosest first, and what its runs so far showed.
  struct Ladder {
    std::string name;
    int modes = 0;
    std::vector<double> loose_to_tight;
    double looser_cost = 0;  ///< the largest cost of its runs so far
    bool cut = false;        ///< a looser run was over the budget: a tighter one would be too
  };

  /// Every integrator from its loosest tolerance to its tightest, skipping what cannot
  /// pay; then each rung of the modes ladder the same way. The implicit methods run
  /// first: on a stiff scene one of them meets the target early and cheaply, and its
  /// cost is the bar that skips (or cuts) the explicit methods' runs, which stability
  /// caps to cost as much at 1e-3 as at 1e-7 (the slew's trade spent 51 of its 58 s in
  /// RK-Merson and RK3 before CPodes set a 0.37 s bar; the contract's pilot has always
  /// run them first). On a scene that is not stiff an explicit method is cheaper and
  /// lowers the bar when its turn comes. The order changes what is skipped, never which
  /// run is the cheapest within the target (a run skipped or cut at the bar cannot be).
  /// The runs are listed in the options' order.
  void integratorGrid() {
    const std::size_t first = study_.runs.size();
    std::vector<std::string> implicit_first = o_.integrators;
    std::stable_partition(implicit_first.begin(), implicit_first.end(),
                          [](const std::string& n) { return integratorInfo(n).implicit; });
    for (const auto& name : implicit_first) {
      Ladder l{name, 0, o_.accuracies};
      std::sort(l.loose_to_tight.begin(), l.loose_to_tight.end(), std::greater<double>());
      for (double acc : l.loose_to_tight) rung(l, acc);
    }
    inOptionsOrder(first);
    if (!problem_.has_modes) return;
    std::string integrator = o_.modes_integrator;
    std::vector<double> accuracies = o_.modes_accuracies;
    if (o_.ladder_at_cheapest) {  // the rungs at the cheapest run's tolerance, with its integrator if it can
      const TradeRun* best = cheapestRunWithinTarget();
      if (!best) return;
      accuracies = {best->accuracy};
      if (integratorInfo(best->integrator).runs_modal_links) integrator = best->integrator;
    }
    std::sort(accuracies.begin(), accuracies.end(), std::greater<double>());
    for (int k : o_.modes)
      if (k > 0 && k < problem_.finest_segments) {
        Ladder l{integrator, k, accuracies};
        for (double acc : l.loose_to_tight) rung(l, acc);
      }
  }

  /// One rung of a ladder: measured, or skipped when a looser run shows it cannot pay.
  const TradeRun& rung(Ladder& l, double acc) {
    TradeRun skipped{l.name, acc, 0, l.modes};
    if (l.cut) return skip(skipped, "not_run", strf("not run: a looser run was over the %g s budget", o_.run_budget_s));
    const double best = cheapestWithinTarget();
    if (o_.skip_costlier && l.looser_cost > best)
      return skip(skipped, "costlier",
                  strf("skipped: costlier (a looser run %.3g s, the cheapest within the target %.3g s)", l.looser_cost, best));
    const TradeRun& r = measure({0, l.modes}, l.name, acc);
    if (r.ok || r.status == "costlier") l.looser_cost = std::max(l.looser_cost, r.seconds);
    l.cut = r.status == "over_budget";
    return r;
  }

  /// The runs from `first` on listed by the options' integrator order, each integrator's
  /// loosest tolerance first (they ran implicit methods first, above).
  void inOptionsOrder(std::size_t first) {
    const auto rank = [&](const TradeRun& r) {
      return std::find(o_.integrators.begin(), o_.integrators.end(), r.integrator) - o_.integrators.begin();
    };
    std::stable_sort(study_.runs.begin() + static_cast<std::ptrdiff_t>(first), study_.runs.end(),
                     [&](const TradeRun& a, const TradeRun& b) {
                       return rank(a) != rank(b) ? rank(a) < rank(b) : a.accuracy > b.accuracy;
                     });
  }

  /// The Pareto front among the integrator runs at the scene's segments.
  void markParetoFront() {
    for (auto& a : study_.runs) {
      if (!a.ok || a.segments) continue;
      a.pareto = true;
      for (const auto& b : study_.runs)
        if (b.ok && !b.segments && &a != &b && b.seconds <= a.seconds && b.error_m <= a.error_m &&
            (b.seconds < a.seconds || b.error_m < a.error_m))
          a.pareto = false;
    }
  }

  const TradeProblem& problem_;
  TradeOptions o_;
  TradeStudy study_;
  SimulationResult reference_;
  const std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

}  // namespace

TradeStudy runTrade(const TradeProblem& problem, const TradeOptions& options) {
  TradeOptions o = options;
  o.points = scoredPoints(problem, options);
  return TradeRunner(problem, o).run();
}

}  // namespace mmv
