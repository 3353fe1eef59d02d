#pragma once
/// A design sweep (`mmvlab sweep SPEC`, docs/planning.md): a base scene, the parameters
/// that vary (any `--set` key) with their ranges or values, the design that combines
/// them, and the outputs recorded at each point. Plain data, read from YAML with
/// file:line:col on every error.
///
///   scene: mmv.yaml               # relative to the spec's folder; none: the embedded scene
///   set: [simulation.duration=2]  # fixed overrides (optional)
///   segments: 8                   # optional, as --segments
///   parameters:
///     - key: sections.link3_rod.radius
///       range: {from: 0.001, to: 0.002, samples: 5, log: false}
///     - key: links.link3.length
///       values: [0.6, 0.762, 0.9]
///   design: grid                  # or {type: latin_hypercube, samples: 100, seed: 1}
///   outputs: [frequencies, mass, deflection, check, "json:modes/modes/0/effective_mass_x_kg"]
///   modes: 6                      # tracked modes (frequencies)

#include <cstdint>
#include <string>
#include <vector>

namespace mmv {

struct SweepParameter {
  std::string key;  ///< a --set key.
  /// A range: `samples` values from `from` to `to`, evenly or log-spaced; else `values`.
  bool is_range = false;
  double from = 0, to = 0;
  int samples = 0;
  bool log = false;
  std::vector<double> values;
  std::string where;  ///< file:line:col.
  /// The grid's values (the range's samples, or `values`).
  std::vector<double> gridValues() const;
  /// The value at u in [0, 1): a range mapped (log-)linearly, a list by its index.
  double at(double u) const;
};

struct DesignSweepSpec {
  std::string source;      ///< the spec file.
  std::string text;        ///< the spec as read (identifies the sweep: resumes and shards must match it).
  std::string scene_path;  ///< resolved against the spec's folder; empty: the embedded default scene.
  std::string scene_where;  ///< file:line:col of `scene:` (the spec's file when it has none).
  std::vector<std::string> sets;
  std::vector<std::string> set_where;  ///< file:line:col of each set entry.
  int segments = 0;
  std::vector<SweepParameter> parameters;
  enum class Design { Grid, LatinHypercube } design = Design::Grid;
  int lhs_samples = 0;
  std::uint64_t seed = 1;
  /// frequencies, mass, deflection, check, first_mode:LINK, json:modes/<pointer>, json:check/<pointer>.
  std::vector<std::string> outputs;
  std::vector<std::string> output_where;  ///< file:line:col of each output.
  int modes = 6;
};

/// Upper bound on a sweep's points.
constexpr long kMaxSweepPoints = 1000000;

/// Reads a sweep spec. Throws SceneFileError (missing) or SceneError (file:line:col).
DesignSweepSpec loadSweepSpec(const std::string& path);
DesignSweepSpec parseSweepSpec(const std::string& text, const std::string& source, const std::string& folder);
/// The design's points: one value per parameter each. Grid: every combination, the
/// last parameter varying fastest; Latin hypercube: `lhs_samples` points, each
/// parameter's range cut into that many strata, one point in each, strata paired by a
/// seeded shuffle (std::mt19937_64). Deterministic.
std::vector<std::vector<double>> sweepPoints(const DesignSweepSpec& spec);
/// "KEY=VALUE" for each parameter at a point (the shortest text that reads back exactly).
std::vector<std::string> pointOverrides(const DesignSweepSpec& spec, const std::vector<double>& point);

}  // namespace mmv
