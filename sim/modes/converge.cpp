#include "sim/modes/converge.hpp"

#include <chrono>
#include <cmath>

#include "sim/modes/system_modes.hpp"

namespace mmv {

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
  const std::size_t nr = study.runs.size();
  for (int i = 0; i < num_modes; ++i) {
    ConvergenceMode m;
    m.number = i + 1;
    for (const auto& run : study.runs)
      m.frequency_hz.push_back(i < static_cast<int>(run.frequency_hz.size()) ? run.frequency_hz[i] : NAN);
    if (nr >= 2 && std::isfinite(m.frequency_hz[nr - 1]) && std::isfinite(m.frequency_hz[nr - 2])) {
      const double f1 = m.frequency_hz[nr - 1], f2 = m.frequency_hz[nr - 2];
      m.has_estimate = true;
      m.extrapolated_hz = f1 + (f1 - f2) / 3.0;
      m.estimated_relative_error = std::abs(f1 - m.extrapolated_hz) / std::abs(m.extrapolated_hz);
      if (nr >= 3 && std::isfinite(m.frequency_hz[nr - 3])) {
        const double f3 = m.frequency_hz[nr - 3];
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
      }
    }
    study.modes.push_back(std::move(m));
  }
  return study;
}

}  // namespace mmv
