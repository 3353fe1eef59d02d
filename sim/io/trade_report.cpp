#include "sim/io/trade_report.hpp"

#include <algorithm>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

const TradeRun* cheapestWithin(const TradeStudy& s, double target) {
  const TradeRun* best = nullptr;
  for (const auto& r : s.runs)
    if (r.ok && !r.segments && r.error_m <= target && r.energy_ok && (!best || r.seconds < best->seconds)) best = &r;
  return best;
}

/// A run within the target cheaper than `best` whose energy balance fails (the reason
/// it is not named), or null.
const TradeRun* cheaperButUnbalanced(const TradeStudy& s, double target, const TradeRun* best) {
  const TradeRun* r0 = nullptr;
  for (const auto& r : s.runs)
    if (r.ok && !r.segments && r.error_m <= target && !r.energy_ok && (!best || r.seconds < best->seconds) &&
        (!r0 || r.seconds < r0->seconds))
      r0 = &r;
  return r0;
}

}  // namespace

std::string tradeText(const TradeStudy& s, double target) {
  std::ostringstream os;
  os << s.scene_name << strf(": speed-accuracy trade of a %.4g s time run\n", s.duration);
  os << strf("Reference: %s at 1e-10 (%.2f s); its difference from %s at 1e-10 is %.2g m, below which errors "
             "cannot be told apart\n\n",
             s.reference_integrator.c_str(), s.reference_seconds, s.check_integrator.c_str(), s.reference_uncertainty_m);
  os << strf("The scored points move up to %.3g m in the reference run; the target is %.3g m (%.3g %% of that)\n\n",
             s.reference_amplitude_m, target, s.reference_amplitude_m > 0 ? 100 * target / s.reference_amplitude_m : 0.0);
  if (!s.points.empty()) {
    os << "Error scored at:";
    for (const auto& p : s.points) os << ' ' << p;
    os << "\n\n";
  }
  Table t({"integrator", "accuracy", "segments", "modes", "tip_error_m", "cpu_s", "evaluations", "pareto", "note"});
  for (const auto& r : s.runs) {
    const std::string segments = r.segments ? strf("%d", r.segments) : "scene";
    const std::string modes = r.modes ? strf("%d", r.modes) : "all";
    if (!r.ok) {  // why it has no numbers: the diagnostic, the cut, the skip
      t.add({r.integrator, strf("%.0e", r.accuracy), segments, modes, "-", "-", "-", "",
             r.status == "failed" ? "FAILED: " + r.failure : r.failure});
      continue;
    }
    t.add({r.integrator, strf("%.0e", r.accuracy), segments, modes, strf("%.3g", r.error_m), strf("%.3f", r.seconds),
           strf("%ld", r.evaluations), r.pareto ? "*" : "",
           r.energy_ok ? "" : "energy balance fails (over 1 % of the run's energy scale)"});
  }
  os << t.text();
  if (std::any_of(s.runs.begin(), s.runs.end(), [](const TradeRun& r) { return r.modes > 0; }))
    os << "(modes: per link, in modal coordinates (links[].modes); all: every hinge its own coordinate)\n";
  int costlier = 0, cut = 0, not_run = 0;
  for (const auto& r : s.runs) costlier += r.status == "costlier", cut += r.status == "over_budget", not_run += r.status == "not_run";
  os << strf("\nThe trade took %.3g s", s.total_seconds);
  if (costlier + cut + not_run > 0)
    os << strf(": %d runs skipped or cut as costlier (a looser run of their integrator, or the run itself so far, cost "
               "more than the cheapest run within the target; --all runs them), %d cut at the run budget, %d not run "
               "(budgets)",
               costlier, cut, not_run);
  os << '\n';
  const TradeRun* best = cheapestWithin(s, target);
  if (best)
    os << strf("\nCheapest run within %.3g m: %s at accuracy %.0e%s (%.3f s, error %.3g m)\n", target, best->integrator.c_str(),
               best->accuracy, best->modes ? strf(" with %d modes per link", best->modes).c_str() : "", best->seconds,
               best->error_m);
  else
    os << strf("\nNo run reached %.3g m with its energy balance held: tighten the accuracies\n", target);
  if (const TradeRun* u = cheaperButUnbalanced(s, target, best))
    os << strf("(%s at accuracy %.0e is cheaper within %.3g m, %.3f s, but its energy balance fails)\n", u->integrator.c_str(),
               u->accuracy, target, u->seconds);
  return os.str();
}

nlohmann::ordered_json tradeJson(const TradeStudy& s, double target) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "trade";
  j["duration_s"] = s.duration;
  j["reference"] = {{"integrator", s.reference_integrator},
                    {"check_integrator", s.check_integrator},
                    {"accuracy", 1e-10},
                    {"uncertainty_m", s.reference_uncertainty_m}};
  j["points"] = s.points;  // empty: every link tip
  auto runs = nlohmann::ordered_json::array();
  for (const auto& r : s.runs) runs.push_back(fieldsJson(tradeRunFields(), r, [](const auto&) { return true; }));
  j["runs"] = runs;
  j["total_seconds"] = s.total_seconds;
  const TradeRun* best = cheapestWithin(s, target);
  j["target_error_m"] = target;
  j["reference_amplitude_m"] = s.reference_amplitude_m;
  j["cheapest_within_target"] = best ? nlohmann::ordered_json{{"integrator", best->integrator}, {"accuracy", best->accuracy},
                                                              {"modes", best->modes}}
                                     : nlohmann::ordered_json(nullptr);
  return j;
}

std::string tradeCsv(const TradeStudy& s) {
  return fieldsCsv(tradeRunFields(), s.runs, [](const auto&) { return true; });
}

const std::vector<Field<TradeRun>>& tradeRunFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  // clang-format off
  static const std::vector<Field<TradeRun>> fields{
      {"integrator", "", "%s", "the integrator (the integrator table's name)",
       [](const TradeRun& r) -> Opt { return json(r.integrator); }},
      {"accuracy", "1", "%.3g", "its relative accuracy (tolerance)",
       [](const TradeRun& r) -> Opt { return json(r.accuracy); }},
      {"segments", "", "%d", "segments per flexible link (0: the scene's)",
       [](const TradeRun& r) -> Opt { return json(r.segments); }},
      {"modes", "", "%d", "modes per link in modal coordinates (0: every hinge)",
       [](const TradeRun& r) -> Opt { return json(r.modes); }},
      {"ok", "", "%d", "the run has numbers (status ok)",
       [](const TradeRun& r) -> Opt { return json(r.ok); }},
      {"status", "", "%s", "ok, failed, over_budget, costlier or not_run",
       [](const TradeRun& r) -> Opt { return json(r.status); }},
      {"tip_error_m", "m", "%.6g", "largest position error of the scored points against the reference",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt(json(r.error_m)) : Opt(); }},
      {"cpu_s", "s", "%.6g", "the run's CPU time",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt(json(r.seconds)) : Opt(); }},
      {"evaluations", "", "%d", "right-hand sides or realizations the integrator asked for",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt(json(r.evaluations)) : Opt(); }},
      {"pareto", "", "%d", "on the error-cost Pareto front",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt(json(r.pareto)) : Opt(); }},
      {"energy_balance_ok", "", "%d", "the energy balance held within 1 % of the run's energy scale",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt(json(r.energy_ok)) : Opt(); }},
      {"failure", "", "%s", "why a run has no numbers (the diagnostic, the cut, the skip)",
       [](const TradeRun& r) -> Opt { return r.ok ? Opt() : Opt(json(r.failure)); }},
  };
  // clang-format on
  return fields;
}

}  // namespace mmv
