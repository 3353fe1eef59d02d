#include "sim/modes/converge.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>

#include "sim/modes/system_modes.hpp"

namespace mmv {

ConvergenceMode assessLadder(int number, const std::vector<double>& frequency_hz) {
  ConvergenceMode m;
  m.number = number;
  m.frequency_hz = frequency_hz;
  const std::size_t nr = frequency_hz.size();
  if (nr < 2 || !std::isfinite(frequency_hz[nr - 1]) || !std::isfinite(frequency_hz[nr - 2])) return m;
  const double f1 = frequency_hz[nr - 1], f2 = frequency_hz[nr - 2];
  m.has_estimate = true;
  m.extrapolated_hz = f1 + (f1 - f2) / 3.0;
  m.estimated_relative_error = std::abs(f1 - m.extrapolated_hz) / std::abs(m.extrapolated_hz);
  if (nr < 3 || !std::isfinite(frequency_hz[nr - 3])) return m;
  const double f3 = frequency_hz[nr - 3];
  const double ratio = (f3 - f2) / (f2 - f1);
  m.check = "unconverged";
  if (std::isfinite(ratio) && ratio > 0) {
    m.has_observed_order = true;
    m.observed_order = std::log2(ratio);
    if (std::abs(m.observed_order - 2.0) <= 0.5)
      m.check = "ok";
    else if (m.observed_order > 0.5)
      m.check = "order";
  }
  if (m.check == "order")
    m.estimated_relative_error = std::abs(f1 - f2) / (std::pow(2.0, m.observed_order) - 1) / std::abs(f1);
  else if (m.check == "unconverged")
    m.estimated_relative_error = std::abs(f1 - f2) / std::abs(f1);
  return m;
}

DiscretizationEstimate estimateDiscretization(const ArticleScene& scene, const std::vector<double>& finest_hz) {
  DiscretizationEstimate e;
  const auto t0 = std::chrono::steady_clock::now();
  bool flexible = false, by2 = true, by4 = true;
  for (const auto& l : scene.article.links) {
    if (l.rigid) continue;
    flexible = true;
    by2 = by2 && l.segments % 2 == 0;
    by4 = by4 && l.segments % 4 == 0;
  }
  if (!flexible) {
    e.reason = "no flexible link";
    return e;
  }
  if (!by2) {
    e.reason = "a flexible link has an odd number of segments (the estimate halves them)";
    return e;
  }
  e.divisors = by4 ? std::vector<int>{4, 2} : std::vector<int>{2};
  std::vector<std::vector<double>> runs;
  for (int d : e.divisors) {
    ArticleScene coarse = scene;
    for (auto& l : coarse.article.links)
      if (!l.rigid) l.segments /= d;
    const ModesSolve sol = solveSceneModes(coarse, {}, static_cast<int>(finest_hz.size()));
    runs.emplace_back(sol.frequencies_hz.data(), sol.frequencies_hz.data() + sol.frequencies_hz.size());
  }
  double scale = 0;
  for (double f : finest_hz) scale = std::max(scale, std::abs(f));
  for (std::size_t i = 0; i < finest_hz.size(); ++i) {
    std::vector<double> f;
    for (const auto& r : runs) f.push_back(i < r.size() ? r[i] : NAN);
    f.push_back(finest_hz[i]);
    ConvergenceMode m = assessLadder(static_cast<int>(i) + 1, f);
    if (!(std::abs(finest_hz[i]) > 1e-6 * scale)) {  // a rigid-body mode: no relative error
      m.has_estimate = m.has_observed_order = false;
      m.check = "rigid";
    }
    e.modes.push_back(std::move(m));
  }
  e.available = true;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

ConvergenceStudy runConvergence(const ArticleScene& scene, int max_segments, int num_modes) {
  ConvergenceStudy study;
  study.scene_name = scene.name;
  study.scene_source = scene.source;
  for (int n = 1; n <= max_segments; n *= 2) {
    ArticleScene s = scene;
    overrideSegments(s, n);
    const auto t0 = std::chrono::steady_clock::now();
    const ModesSolve sol = solveSceneModes(s, {}, num_modes);
    ConvergenceRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.segments = n;
    run.num_dofs = sol.num_dofs;
    run.frequency_hz.assign(sol.frequencies_hz.data(), sol.frequencies_hz.data() + sol.frequencies_hz.size());
    study.runs.push_back(std::move(run));
  }
  for (int i = 0; i < num_modes; ++i) {
    std::vector<double> f;
    for (const auto& run : study.runs) f.push_back(i < static_cast<int>(run.frequency_hz.size()) ? run.frequency_hz[i] : NAN);
    study.modes.push_back(assessLadder(i + 1, f));
  }
  return study;
}

}  // namespace mmv
