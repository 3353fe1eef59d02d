#include "sim/io/run_dir.hpp"

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <algorithm>

#include "sim/core/text.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

std::string readText(const std::string& path) {
  std::string text, why;
  if (!readInputFile(path, limits::kMaxProfileBytes, text, why))
    throw SceneFileError(printable(path) + ": " + why + " (is the directory a `mmvlab simulate --out` run of an article?)");
  return text;
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable parseNumericCsv(const std::string& text, const std::string& source) {
  std::istringstream is(text);
  std::string line;
  CsvTable t;
  if (!std::getline(is, line) || line.empty()) throw SceneError(source + ":1:1: empty (expected a header row)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  t.columns = splitCommas(line);
  if (t.columns.front() != "time_s") throw SceneError(source + ":1:1: the first column must be time_s (got " + t.columns.front() + ")");
  for (int n = 2; std::getline(is, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = splitCommas(line);
    if (cells.size() != t.columns.size())
      throw SceneError(strf("%s:%d:1: %zu values, the header has %zu columns", source.c_str(), n, cells.size(), t.columns.size()));
    std::vector<double> row;
    std::size_t col = 1;
    for (const auto& c : cells) {
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      if (c.empty() || *end != '\0' || !std::isfinite(v))
        throw SceneError(strf("%s:%d:%zu: %s is not a finite number", source.c_str(), n, col, c.c_str()));
      row.push_back(v);
      col += c.size() + 1;
    }
    if (!t.rows.empty() && !(row[0] > t.rows.back()[0]))
      throw SceneError(strf("%s:%d:1: time %g s does not increase", source.c_str(), n, row[0]));
    t.rows.push_back(std::move(row));
  }
  if (t.rows.size() < 2) throw SceneError(source + ": fewer than two rows");
  return t;
}

void checkRunModel(const RunDir& run, const Model& model) {
  std::vector<std::string> want{"time_s"};
  for (const auto& c : model.getCoordinates())
    want.push_back(csvColumnName(c.name + (c.motion == CoordinateMotion::Rotation ? "_rad" : "_m")));
  if (want == run.states.columns) return;
  throw SceneError(strf("%s/states.csv: the run has %zu coordinates, the model of %s has %zu (or other names): "
                        "render a run with the scene and segments it was made with (its scene.yaml and run.json)",
                        run.dir.c_str(), run.states.columns.size() - 1, run.scene.source.c_str(), want.size() - 1));
}

std::vector<double> rowAt(const CsvTable& table, double t) {
  const auto& rows = table.rows;
  auto it = std::upper_bound(rows.begin(), rows.end(), t, [](double v, const std::vector<double>& r) { return v < r[0]; });
  const std::size_t hi = std::clamp<std::size_t>(static_cast<std::size_t>(it - rows.begin()), 1, rows.size() - 1), lo = hi - 1;
  const double w = std::clamp((t - rows[lo][0]) / (rows[hi][0] - rows[lo][0]), 0.0, 1.0);
  std::vector<double> out(rows[lo].size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (1 - w) * rows[lo][i] + w * rows[hi][i];
  return out;
}


RunDir readRunDir(const std::string& dir, const std::string& scene_path) {
  RunDir r;
  r.dir = dir;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw SceneFileError(dir + ": not a directory (--history takes a `mmvlab simulate --out` directory)");
  const std::string run_json = dir + "/run.json";
  nlohmann::json run;
  bool no_gravity = false;
  try {
    run = nlohmann::json::parse(readText(run_json));
    r.segments_override = run.at("segments_override").get<int>();
    no_gravity = run.contains("no_gravity") && run.at("no_gravity").get<bool>();
    if (run.contains("overrides")) r.overrides = run.at("overrides").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(run_json + ": not a run record (" + e.what() + ")");
  }
  const std::string scene_file = scene_path.empty() ? dir + "/scene.yaml" : scene_path;
  // The run's --segments through the reader as the run's own option did: a record
  // edited to a count the reader refuses is named at run.json.
  SceneFlags flags;
  if (r.segments_override != 0) flags.segments = r.segments_override;  // 0: the scene's own
  flags.segments_label = run_json + ": segments_override " + std::to_string(r.segments_override);
  flags.no_gravity = no_gravity;
  flags.gravity_label = run_json + ": no_gravity";
  Scene scene;
  try {
    scene = scene_path.empty() ? parseScene(readText(scene_file), scene_file, r.overrides, flags)
                               : loadSceneFile(scene_file, r.overrides, flags);
  } catch (const UsageError& e) {
    throw SceneError(e.what());
  }
  if (auto* a = std::get_if<ArticleScene>(&scene)) {
    r.scene = std::move(*a);
  } else {
    r.isolator = std::get<HamsasScene>(std::move(scene));
  }
  r.history = parseNumericCsv(readText(dir + "/history.csv"), dir + "/history.csv");
  r.states = parseNumericCsv(readText(dir + "/states.csv"), dir + "/states.csv");
  if (r.history.rows.size() != r.states.rows.size())
    throw SceneError(strf("%s: history.csv has %zu rows, states.csv %zu: not one run", dir.c_str(), r.history.rows.size(),
                          r.states.rows.size()));
  return r;
}

}  // namespace mmv
