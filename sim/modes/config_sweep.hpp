#pragma once
/// Configuration maps: the system modes, and how well component-mode synthesis
/// predicts them, over a grid of joint angles (one or two joints). At every grid
/// point the scene's commanded angles are replaced, the equilibrium, linearization
/// and modes are solved again, and the synthesis (sim/modes/cms.hpp) is compared with the
/// full model. Modes are tracked from point to point by the MAC of their shapes at
/// the named points (sim/modes/tracking.hpp), so a track follows one shape through
/// crossings and veerings; a 2-D grid is walked back and forth (boustrophedon) so
/// that consecutive points are neighbours.
///
/// Tracking holds across the range: modes are paired by an optimal assignment on the
/// MAC matrix, and where a track's MAC between consecutive points falls below
/// kRefineMac the step is halved (up to kMaxRefinements times: a 15 deg step down to
/// 0.94 deg), the points in between solved and reported as refined points. A track
/// whose MAC is still below kLostMac at the finest step is marked lost at that point
/// (its shape changed beyond recognition: a veering or crossing finer than the finest
/// step), and one that follows a point without an equilibrium (a limit point of the
/// equilibrium path) restarts by frequency rank, marked so: neither is drawn as a
/// continuation. Unstable modes (negative stiffness) are kept and marked.

#include <optional>
#include <string>
#include <vector>

#include "sim/modes/cms.hpp"
#include "sim/scene/scene.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

struct GridAxis {
  std::string joint;
  double from_deg = 0, to_deg = 0, step_deg = 1;
  static constexpr double kMaxValues = 2000;  ///< per axis (docs/reliability.md, bounds).
  /// How many values values() holds, computed without making them (a step of 1e-10 deg
  /// over 20 deg is 2e11 values: refused before anything is allocated).
  double count() const;
  std::vector<double> values() const;  ///< from, from+step, ..., up to to (inclusive within 1e-9 step).
};

struct ConfigSweepOptions {
  std::vector<GridAxis> axes;  ///< one or two.
  int modes = 6;               ///< tracks.
  SynthesisOptions synthesis;  ///< compare_modes is set to modes + 4 (the tracking window).
};

constexpr double kRefineMac = 0.8;
constexpr double kLostMac = 0.5;
constexpr int kMaxRefinements = 4;

struct TrackPoint {
  ModeNumber sorted_mode;  ///< rank of the tracked mode at this point.
  double frequency_hz = 0;
  bool stable = true;
  double mac_to_previous = 1;  ///< with the same track at the previous point.
  double synth_hz = 0, synth_error = 0, synth_mac = 0;
  std::string verdict, strain_link;
  /// "" (followed), "lost: why" (MAC below kLostMac at the finest step), or
  /// "restarted: why" (after a point without an equilibrium: by rank, not by shape).
  std::string state;
};

struct ConfigSweepPoint {
  std::vector<double> angles_deg;  ///< one per axis.
  bool solved = true;
  std::string failure;             ///< why there is no result (e.g. a limit point of the equilibrium path).
  std::vector<TrackPoint> tracks;  ///< empty when !solved.
  bool refined = false;            ///< inserted between grid points to follow the shapes.
};

struct ConfigSweepResult {
  std::vector<GridAxis> axes;
  std::string synthesis_method;
  std::vector<ConfigSweepPoint> points;  ///< in walk order.
  double min_tracking_mac = 1;     ///< worst MAC between consecutive points of any track not lost.
  int failed_points = 0;
  int refined_points = 0, lost_tracks = 0;
};

/// Throws SceneError for an unknown joint. A grid point without an equilibrium (or
/// with an ill-posed eigenproblem) is kept with solved = false and its failure; the
/// tracks restart by frequency rank after it.
ConfigSweepResult runConfigSweep(const ArticleScene& scene, const ConfigSweepOptions& options);

}  // namespace mmv
