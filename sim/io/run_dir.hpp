#pragma once
/// Reading back what `mmvlab simulate --out DIR` wrote (docs/outputs.md): the run's
/// scene copy, its overrides (run.json), its history (history.csv) and its coordinates
/// (states.csv), so that `mmvlab render --history DIR` can redraw the run. A missing
/// file is SceneFileError (exit 66); a malformed one SceneError (65) naming the file,
/// line and column.

#include <optional>
#include <string>
#include <vector>

#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// A CSV of one header row and rows of finite numbers, as simulate writes them.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// The column's index, or -1.
  int column(const std::string& name) const;
};

/// Parses `text` (from `source`, for messages). The first column must be time_s and
/// increase strictly.
CsvTable parseNumericCsv(const std::string& text, const std::string& source);

struct RunDir {
  std::string dir;
  ArticleScene scene;        ///< the scene copy, with the run's overrides applied (an article's run).
  std::optional<HamsasScene> isolator;  ///< a HAM-SAS run's scene instead.
  int segments_override = 0; ///< the run's --segments (0: the scene's own).
  std::vector<std::string> overrides;  ///< the run's --set KEY=VALUE, applied to its scene.
  CsvTable history, states;
};

/// Reads DIR. `scene_path` non-empty: that scene instead of DIR/scene.yaml (its model
/// must have the run's coordinates; the caller checks against the model it builds).
RunDir readRunDir(const std::string& dir, const std::string& scene_path = "");

/// SceneError unless the run's states.csv columns are `model`'s coordinates, in order
/// (the model is the one the run was made with).
void checkRunModel(const RunDir& run, const Model& model);

/// The row of `table` at time t: linear between the samples around it, held at the ends.
std::vector<double> rowAt(const CsvTable& table, double t);

}  // namespace mmv
