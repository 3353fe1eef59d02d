#pragma once
/// The speed-accuracy trade of the discretization: the same scene solved with every
/// flexible link cut into N = 1, 2, 4, ... segments; each mode's frequency against N,
/// a Richardson extrapolation assuming the discretization's O(1/N^2) error, the
/// observed order from the three finest runs, and the wall time per solve
/// (build + equilibrium + linearization + eigen solution).
///
/// Modes are matched by their index in ascending frequency; a mode that a coarse
/// model does not have (too few DOF) is left out of that column.

#include <optional>
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

struct ConvergenceRun {
  int segments = 0;
  int num_dofs = 0;
  double seconds = 0;
  std::vector<double> frequency_hz;  ///< all modes (negative: unstable).
};

struct ConvergenceMode {
  ModeNumber number;
  std::vector<double> frequency_hz;  ///< one per run, NaN where the run has no such mode.
  bool has_estimate = false, has_observed_order = false;
  double extrapolated_hz = 0;
  double observed_order = 0;
  /// At the finest run: |f_N - richardson| / richardson when the observed order is
  /// within 0.5 of 2; with an observed order p further off but above 0.5, the same with
  /// p (|f_N - f_N/2| / (2^p - 1), p at most 2: a higher observed order is taken for
  /// a mesh short of the asymptotic range); otherwise |f_N - f_N/2| / f_N, a lower bound.
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
ConvergenceMode assessLadder(ModeNumber number, const std::vector<double>& frequency_hz);

/// The discretization error of a `modes` run: the scene again with every flexible
/// link's segments halved and, when they divide by 4, quartered; each mode matched by
/// index. Not available (`reason` says why) without flexible links or when a link's
/// segments are odd.
/// One link's static peak stress over the same meshes (docs/strength.md): the ladder's
/// values in Pa in `ladder.frequency_hz` (assessLadder's arithmetic is the frequencies'),
/// its Richardson value, observed order and estimate; check "mesh-independent" where the
/// meshes agree to 1e-9 (a link carrying axial load only; its estimate is then 0).
struct StressConvergence {
  std::string link;
  ConvergenceMode ladder;
};

struct DiscretizationEstimate {
  bool available = false;
  std::string reason;
  std::vector<int> divisors;  ///< the coarser runs, e.g. {4, 2}: segments / 4 and / 2
  std::vector<ConvergenceMode> modes;  ///< one per finest frequency; check "rigid" for a zero-frequency mode
  /// Each link whose static stress every run recovered, in scene order.
  std::vector<StressConvergence> stresses;
  double seconds = 0;
};
struct ModesReport;  // sim/modes/system_modes.hpp (which holds a DiscretizationEstimate)
struct ModeInfo;

/// `finest`: the scene's own modes (runModes). Each is followed down the coarser meshes
/// within its family, not by its place in the whole list: the k-th in-plane mode with the
/// k-th in-plane mode of the coarse mesh, and so for out-of-plane, torsion and mixed
/// modes (the spatial model's ModeFamily; the planar model has one family, where this is
/// pairing by index). Where bending and torsion families interleave differently on two
/// meshes, pairing by index compared unlike modes (a 20 x 5 mm strip: an estimate 26x too
/// low). A mode whose family has fewer modes on a coarse mesh gets check "unpaired" and
/// no estimate.
DiscretizationEstimate estimateDiscretization(const ArticleScene& scene, const ModesReport& finest);

/// `modes --target-error E`: the fewest segments per flexible link (1, 2, 4, ... up to
/// `max_segments`) at which each of the first `num_modes` vibration modes has an
/// estimated relative frequency error <= E from the three finest runs (Richardson,
/// assessLadder) with a sane observed order ("ok" or "order"; an "unconverged" mode is
/// not trusted whatever its estimate). Rigid-body modes (0 Hz) carry no relative error.
struct SegmentsLevel {
  int segments = 0;
  double seconds = 0;      ///< this solve
  double worst_error = 0;  ///< the largest estimated relative error (NaN: fewer than three runs)
  std::optional<ModeNumber> worst_mode;  ///< none: no mode assessed
  std::string worst_check; ///< its check; "unconverged" anywhere makes the level fail
  bool met = false;
};
struct SegmentsChoice {
  double target = 0;
  int segments = 0;  ///< 0: not met within max_segments or the budget
  std::vector<SegmentsLevel> ladder;
  double seconds = 0;
};
/// The finest mesh the commands' --target-error tries: 256 segments per link (the
/// default article at 1e-4 needs 128, chosen in 77 ms; docs/benchmarks.md).
constexpr int kMaxTargetSegments = 256;

/// Throws NumericalError when no count up to `max_segments` meets E, or the time budget
/// (> 0, s) is spent first; the message names the best level reached.
SegmentsChoice segmentsForTarget(const ArticleScene& scene, int num_modes, double target, int max_segments,
                                 double budget_s = 0);

/// Runs N = 1, 2, 4, ..., up to max_segments (>= 1), reporting `num_modes` modes.
/// Throws NumericalError if a run fails.
ConvergenceStudy runConvergence(const ArticleScene& scene, int max_segments, int num_modes);

}  // namespace mmv
