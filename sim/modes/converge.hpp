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
  /// At the finest run: |f_N - richardson| / richardson when the observed order is
  /// within 0.5 of 2; with an observed order p further off but above 0.5, the same with
  /// p (|f_N - f_N/2| / (2^p - 1)); otherwise |f_N - f_N/2| / f_N, a lower bound.
  double estimated_relative_error = 0;
  /// "ok": the observed order is within 0.5 of 2, so the O(1/N^2) Richardson value and
  /// estimate hold; "order": converging at another order (the estimate uses it);
  /// "unconverged": order below 0.5 or non-monotone (the modes may swap between runs,
  /// or the mesh is far from the asymptotic range): the estimate is a lower bound;
  /// "": fewer than three runs, not checked.
  std::string check;
};

struct ConvergenceStudy {
  std::string scene_name, scene_source;
  std::vector<ConvergenceRun> runs;
  std::vector<ConvergenceMode> modes;
};

/// One mode's frequencies over a ladder of meshes, each with twice the segments of the
/// one before (NaN where a run lacks the mode): the Richardson value and estimate from
/// the two finest, the observed order and its check from the three finest.
ConvergenceMode assessLadder(int number, const std::vector<double>& frequency_hz);

/// The discretization error of a `modes` run: the scene again with every flexible
/// link's segments halved and, when they divide by 4, quartered; each mode matched by
/// index. Not available (`reason` says why) without flexible links or when a link's
/// segments are odd.
struct DiscretizationEstimate {
  bool available = false;
  std::string reason;
  std::vector<int> divisors;  ///< the coarser runs, e.g. {4, 2}: segments / 4 and / 2
  std::vector<ConvergenceMode> modes;  ///< one per finest frequency; check "rigid" for a zero-frequency mode
  double seconds = 0;
};
/// `finest_hz`: the scene's own modes (negative: unstable, 0: rigid).
DiscretizationEstimate estimateDiscretization(const ArticleScene& scene, const std::vector<double>& finest_hz);

/// Runs N = 1, 2, 4, ..., up to max_segments (>= 1), reporting `num_modes` modes.
/// Throws NumericalError if a run fails.
ConvergenceStudy runConvergence(const ArticleScene& scene, int max_segments, int num_modes);

}  // namespace mmv
