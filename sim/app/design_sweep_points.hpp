#pragma once
/// The rows of `mmvlab sweep` (sim/scene/design_sweep_spec.hpp): what each point computes and
/// how it is written. A point's row depends on its index only (never on the order or
/// the thread it runs in), so parallel, sharded and resumed sweeps write the same rows.
///
/// Columns: point, each parameter, status ("ok", or what went wrong at that point:
/// the scene refused a value, the equilibrium failed), then per output:
///  - frequencies: mode<k>_hz and mode<k>_mac for the spec's `modes` modes of the
///    nominal scene, tracked to each point by an optimal MAC assignment on the shapes at
///    the named points (sim/modes/tracking.hpp); a MAC below 0.5 means the mode changed
///    character there; an empty cell, that no mode matched;
///  - first_mode:LINK: first_mode_LINK_hz, the lowest vibration mode whose strain
///    energy is mostly in LINK or one of its branches (link3: link3a or link3b);
///  - mass: mass_kg; deflection: max_deflection_m (largest static deflection of a point);
///  - check: check_overall, then <id>_demand and <id>_margin_pct for every line of the
///    nominal check (sim/plan/check.hpp), and plausibility_warnings;
///  - json:modes/POINTER, json:check/POINTER: that field of `modes --json` or
///    `check --json` (RFC 6901 pointer), e.g. json:modes/modes/0/effective_mass_x_kg.

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/design_sweep_spec.hpp"

namespace mmv {

struct SweepPointResult;  ///< one point's modes and check (private to the .cpp).

/// One column of sweep.csv, described once: the header, sweep.json's `fields` (and so
/// Python's) and each point's cell are all made from this, so they cannot disagree.
struct SweepColumn {
  std::string key;      ///< the CSV column's name.
  std::string unit;     ///< "Hz", "kg", "m", "%", "1" (a ratio); "" text, a count, or a scene key's own unit.
  std::string meaning;  ///< one line.
  bool number = true;   ///< its cells are numbers (else text).
  /// The cell of a point whose analysis succeeded (an output column; the point,
  /// parameter and status columns have none: the runner and the point write them).
  std::function<std::string(const SweepPointResult&)> cell;
};

struct DesignSweepContext {
  DesignSweepSpec spec;
  std::string scene_text, scene_source;  ///< the base scene.
  std::vector<std::vector<double>> points;
  std::vector<SweepColumn> columns;  ///< point, each parameter, status, then the outputs' columns.
  std::vector<std::string> header;   ///< the columns' keys.
  std::string fingerprint;  ///< of the spec, the scene, the header and the program's version.
  Eigen::MatrixXd reference_shapes;  ///< nominal modes tracked (columns), at the named points.
  std::vector<std::string> check_ids;
};

/// Reads the base scene, checks every parameter key and output on it (SceneError at
/// the spec's line:col), runs the nominal point, and lays out the columns.
DesignSweepContext prepareDesignSweep(const DesignSweepSpec& spec);
/// The cells of point `index` after its index column. Thread-safe.
std::vector<std::string> evaluateDesignSweepPoint(const DesignSweepContext& context, long index);
/// sweep.json's `fields`: a record {key, unit, number, meaning} per column.
nlohmann::ordered_json sweepFieldsJson(const std::vector<SweepColumn>& columns);

}  // namespace mmv
