#include "sim/time/verify.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/core/text.hpp"

namespace mmv {
namespace {

bool scored(const std::vector<std::string>& points, const std::string& name) {
  return points.empty() || std::find(points.begin(), points.end(), name) != points.end();
}

}  // namespace

ScoredDistance scoredDistance(const SimulationRecord& a, const SimulationRecord& b, const std::vector<std::string>& points) {
  ScoredDistance worst;
  const std::size_t rows = std::min(a.rows.size(), b.rows.size());
  for (const auto& [name, ca] : a.scored) {
    if (!scored(points, name)) continue;
    for (const auto& [other, cb] : b.scored) {
      if (other != name) continue;
      for (std::size_t k = 0; k < rows; ++k) {
        double d2 = 0;
        for (std::size_t c = 0; c < ca.size(); ++c) d2 += std::pow(a.rows[k][ca[c]] - b.rows[k][cb[c]], 2);
        if (std::sqrt(d2) > worst.distance_m) worst = {std::sqrt(d2), a.rows[k][0], name};
      }
    }
  }
  return worst;
}

double scoredAmplitude(const SimulationRecord& a, const std::vector<std::string>& points) {
  double worst = 0;
  for (const auto& [name, ca] : a.scored) {
    if (!scored(points, name)) continue;
    for (std::size_t k = 1; k < a.rows.size(); ++k) {
      double d2 = 0;
      for (std::size_t c = 0; c < ca.size(); ++c) d2 += std::pow(a.rows[k][ca[c]] - a.rows[0][ca[c]], 2);
      worst = std::max(worst, std::sqrt(d2));
    }
  }
  return worst;
}

double scoredScale(const SimulationRecord& a, const std::vector<std::string>& points) {
  std::vector<const std::vector<int>*> cols;
  for (const auto& [name, c] : a.scored)
    if (scored(points, name)) cols.push_back(&c);
  double worst = 0;
  for (const auto& row : a.rows)
    for (std::size_t i = 0; i < cols.size(); ++i)
      for (std::size_t j = i + 1; j < cols.size(); ++j) {
        double d2 = 0;
        for (std::size_t c = 0; c < cols[i]->size() && c < cols[j]->size(); ++c)
          d2 += std::pow(row[(*cols[i])[c]] - row[(*cols[j])[c]], 2);
        worst = std::max(worst, std::sqrt(d2));
      }
  return worst;
}

double defaultErrorTarget(double amplitude_m, double scale_m) {
  const double motion = std::max(amplitude_m, kMotionFloor * scale_m);
  return motion > 0 ? 0.01 * motion : 1e-4;
}

RunVerification verifyRun(const SimulationResult& run, const SimulationSpec& spec,
                          const std::function<SimulationResult(const SimulationSpec&)>& rerun, double target_m) {
  SimulationSpec tight = spec;
  tight.accuracy = spec.accuracy / 10;
  tight.absolute_tolerance = spec.absolute_tolerance / 10;
  tight.modal_refinement = spec.modal_refinement + 1;  // links in modal coordinates: the next octave of modes
  tight.scored_only = true;  // compared on the scored points only
  const auto start = std::chrono::steady_clock::now();
  const SimulationResult companion = rerun(tight);
  RunVerification v;
  v.done = true;
  v.companion_accuracy = tight.accuracy;
  v.companion_more_modes = !run.modal_links.empty();
  v.companion_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ScoredDistance d = scoredDistance(run.record, companion.record, spec.score_points);
  v.estimated_error_m = d.distance_m;
  v.at_s = d.at_s;
  v.point = d.point;
  v.amplitude_m = scoredAmplitude(companion.record, spec.score_points);
  v.target_m = target_m > 0 ? target_m : defaultErrorTarget(v.amplitude_m, scoredScale(companion.record, spec.score_points));
  v.target_is_default = !(target_m > 0);
  return v;
}

bool verificationMet(const RunVerification& v) { return v.done && kVerifySafetyFactor * v.estimated_error_m <= v.target_m; }

std::string verificationWarning(const RunVerification& v) {
  if (!v.done || verificationMet(v)) return {};
  return strf("the run's estimated error %.3g m (at %s, t = %.4g s, against the same run at accuracy %.1e%s) times the "
              "safety factor %g exceeds the %s %.3g m%s: tighten the accuracy%s",
              v.estimated_error_m, v.point.c_str(), v.at_s, v.companion_accuracy,
              v.companion_more_modes ? " with each link's modes up to twice the frequency" : "", kVerifySafetyFactor,
              v.target_is_default ? "target (1 % of the scored motion)" : "target", v.target_m,
              v.estimated_error_m <= v.target_m ? " (the estimate alone is within it, its uncertainty is not)" : "",
              v.companion_more_modes ? ", or keep more modes (links[].modes) or every hinge (simulation.fidelity: segments)"
                                     : "");
}

}  // namespace mmv
