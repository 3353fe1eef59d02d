#include "sim/app/study.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/finite_check.hpp"
#include "sim/scene/plausibility.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::app {

std::string optionName(Front front, const std::string& cli_flag) {
  if (front == Front::Cli) return cli_flag;
  std::string name = cli_flag.substr(cli_flag.find_first_not_of('-'));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

SceneFlags sceneFlags(std::optional<int> segments, bool no_gravity, Front front) {
  SceneFlags f;
  f.segments = segments;
  f.no_gravity = no_gravity;
  const bool cli = front == Front::Cli;
  if (segments) f.segments_label = optionName(front, "--segments") + (cli ? " " : "=") + std::to_string(*segments);
  f.gravity_label = cli ? "--no-gravity" : "no_gravity=True";
  return f;
}

LoadedScene loadScene(const SceneRequest& r) {
  // A path holds no NUL: one would end it at the system call, and another file be read.
  if (r.path.find('\0') != std::string::npos)
    throw UsageError(std::string(r.front == Front::Cli ? "SCENE" : "path") + ": the path holds a NUL character (got '" +
                     printable(r.path.substr(0, r.path.find('\0'))) + "\\0...')");
  const SceneFlags flags = sceneFlags(r.segments, r.no_gravity, r.front);
  std::vector<std::string> notes;
  LoadedScene out{r.path.empty() ? parseScene(defaultSceneYaml(), "<default scene>", r.sets, flags, &notes)
                                 : loadSceneFile(r.path, r.sets, flags, &notes),
                  {}};
  out.request = r;
  for (const auto& note : notes) out.warnings.push_back("mmvlab: warning: " + note);
  auto* a = std::get_if<ArticleScene>(&out.scene);
  if (!a) return out;
  // Values no lab article has: warned in every command, refused with --strict.
  const std::vector<std::string> slips = scenePlausibility(*a);
  if (r.strict && !slips.empty())
    throw SceneError(slips.front() + " (" + optionName(r.front, "--strict") + ": implausible values are errors" +
                     (slips.size() > 1 ? strf("; %zu more", slips.size() - 1) : std::string()) + ")");
  for (const auto& w : slips) out.warnings.push_back("warning: " + w + " (likely a unit mistake)");
  return out;
}

LoadedScene withSegments(const LoadedScene& loaded, std::optional<int> segments) {
  SceneRequest r = loaded.request;
  r.segments = segments;
  const std::string& source = std::visit([](const auto& s) -> const std::string& { return s.positions.file; }, loaded.scene);
  std::vector<std::string> notes;
  LoadedScene out{parseScene(sceneText(loaded.scene), source, r.sets, sceneFlags(r.segments, r.no_gravity, r.front), &notes),
                  {}, r};
  for (const auto& note : notes) out.warnings.push_back("mmvlab: warning: " + note);
  return out;
}

std::vector<std::string> checkedPoints(const std::vector<std::string>& names, const ArticleSpec& article,
                                       const std::string& option) {
  const std::vector<std::string> points = articlePointNames(article);
  for (const auto& n : names) {
    std::string error;
    if (isStationName(n)) {
      if (!parseStation(n, article, error)) throw UsageError(option + ": " + error);
    } else if (std::find(points.begin(), points.end(), n) == points.end()) {
      throw UsageError(option + ": unknown point '" + n + "'" + didYouMean(n, points) +
                       " (points are <joint>, <link>.root, <link>.tip and <link>.h1 .. <link>.h<segments>; stations "
                       "<link>@<m>m or <link>@<fraction>)");
    }
  }
  return names;
}

void checkRange(Front front, const std::string& cli_flag, double v, double lo, double hi, bool open_low) {
  const bool ok = std::isfinite(v) && (open_low ? v > lo : v >= lo) && v <= hi;
  if (ok) return;
  const std::string low = strf("%s %g", open_low ? "above" : "of at least", lo);
  throw UsageError(strf("%s: must be a finite number %s%s (got %g)", optionName(front, cli_flag).c_str(), low.c_str(),
                        std::isfinite(hi) ? strf(" and at most %g", hi).c_str() : "", v));
}

std::optional<double> finiteNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

const ArticleScene& articleOf(const Scene& scene, const std::string& verb) {
  if (const auto* a = std::get_if<ArticleScene>(&scene)) return *a;
  throw UsageError(verb + ": " + sceneSource(scene) +
                   " is a HAM-SAS isolator scene; it supports modes, frf, rom, simulate and trade (docs/hamsas.md)");
}

void checkResultFinite(const std::string& text) {
  if (const std::string at = firstNonFiniteLine(text); !at.empty())
    throw NumericalError("a result is not finite (" + at + " of the report); nothing was printed. This is a bug or an "
                         "input beyond what the model resolves: please report it with the scene");
}

void checkResultFinite(const nlohmann::ordered_json& json) {
  if (const std::string at = firstNonFiniteJson(json); !at.empty())
    throw NumericalError("a result is not finite (JSON " + at + "); nothing was printed. This is a bug or an input "
                         "beyond what the model resolves: please report it with the scene");
}

}  // namespace mmv::app
