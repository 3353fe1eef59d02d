#pragma once
/// The speed-accuracy trade of the discretization: the same scene solved with every
/// flexible link cut into N = 1, 2, 4, ... segments; each mode's frequency against N,
/// a Richardson extrapolation assuming the discretization's O(1/N^2) error, the
/// observed order from the three finest runs, and the wall time per solve
/// (build + equilibrium + linearization + eigen solution).
///
/// Modes are matched by their index in ascending frequency; a mode that a coarse
/// model does not have (too few DOF) is left out of that column.

#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace mmv {

struct ConvergenceRun {
  int segments = 0;
  int num_dofs = 0;
  double seconds = 0;
  std::vector<double> frequency_hz;  ///< all modes (negative: unstable).
};

struct ConvergenceMode {
  int number = 0;
  std::vector<double> frequency_hz;  ///< one per run, NaN where the run has no such mode.
  bool has_estimate = false, has_observed_order = false;
  double extrapolated_hz = 0;
  double observed_order = 0;
  double estimated_relative_error = 0;  ///< at the finest run.
};

struct ConvergenceStudy {
  std::string scene_name, scene_source;
  std::vector<ConvergenceRun> runs;
  std::vector<ConvergenceMode> modes;
};

/// Runs N = 1, 2, 4, ..., up to max_segments (>= 1), reporting `num_modes` modes.
/// Throws NumericalError if a run fails.
ConvergenceStudy runConvergence(const ArticleScene& scene, int max_segments, int num_modes);

}  // namespace mmv
