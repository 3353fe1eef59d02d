#include "sim/cli/commands.hpp"

#include "sim/core/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "sim/io/output_dir.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::cli {

Scene loadScene(const SceneArgs& args) {
  Scene scene = args.scene_path.empty() ? parseScene(defaultSceneYaml(), "<default scene>", args.sets)
                                         : loadSceneFile(args.scene_path, args.sets);
  if (auto* a = std::get_if<ArticleScene>(&scene)) {
    if (args.segments > 0) overrideSegments(*a, args.segments);
    if (args.no_gravity) a->gravity = {0, 0, 0};
  } else if (args.segments > 0 || args.no_gravity) {
    throw UsageError("--segments and --no-gravity do not apply to a HAM-SAS scene (rigid bodies; its preloads are gravity's)");
  }
  return scene;
}

ArticleScene loadArticleScene(const SceneArgs& args, const std::string& command) {
  Scene scene = loadScene(args);
  if (auto* a = std::get_if<ArticleScene>(&scene)) return std::move(*a);
  throw UsageError(command + ": " + sceneSource(scene) +
                   " is a HAM-SAS isolator scene; it supports modes, frf, rom, simulate and trade (docs/hamsas.md)");
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

void parseComponentArgs(const std::string& bc, const std::string& tip_mass, ComponentOptions& o) {
  if (!parseComponentBC(bc, o.bc))
    throw UsageError("--bc: unknown boundary condition '" + bc +
                     "' (known: clamped-free, pinned-free, free-free, clamped-pinned, pinned-pinned)");
  if (parseTipMassRule(tip_mass, o.rule)) return;
  // Explicit: "MASS" (kg) or "MASS,ROTARY_INERTIA" (kg, kg*m^2).
  const auto comma = tip_mass.find(',');
  const std::string ms = tip_mass.substr(0, comma), js = comma == std::string::npos ? "0" : tip_mass.substr(comma + 1);
  char *e1 = nullptr, *e2 = nullptr;
  const double m = std::strtod(ms.c_str(), &e1), j = std::strtod(js.c_str(), &e2);
  if (ms.empty() || js.empty() || *e1 != '\0' || *e2 != '\0' || !std::isfinite(m) || !std::isfinite(j) || m < 0 || j < 0)
    throw UsageError("--tip-mass: expected a rule (none, torquer, outboard) or MASS_KG[,ROTARY_INERTIA_KG_M2] >= 0 (got " +
                     tip_mass + ")");
  o.explicit_tip = LumpedMass{m, j};
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    std::cerr << "mmvlab: " << e.what() << '\n';
    return kUsage;
  } catch (const OutputError& e) {
    std::cerr << "mmvlab: " << e.what() << '\n';
    return kCannotCreate;
  } catch (const SceneFileError& e) {
    std::cerr << "mmvlab: " << e.what() << '\n';
    return kNoInput;
  } catch (const SceneError& e) {
    std::cerr << e.what() << '\n';
    return kDataError;
  } catch (const NumericalError& e) {
    std::cerr << "mmvlab: numerical failure: " << e.what() << '\n';
    return kNumericalFailure;
  } catch (const UnavailableError& e) {
    std::cerr << "mmvlab: not available in this installation: " << e.what() << '\n';
    return kUnavailable;
  } catch (const std::exception& e) {
    std::cerr << "mmvlab: internal error: " << e.what() << '\n';
    return kInternal;
  }
}

std::pair<double, double> parseBand(const std::string& band) {
  const auto colon = band.find(':');
  char *e1 = nullptr, *e2 = nullptr;
  if (colon == std::string::npos) throw UsageError("--band: expected F_MIN_HZ:F_MAX_HZ (got '" + band + "')");
  const std::string a = band.substr(0, colon), b = band.substr(colon + 1);
  const double lo = std::strtod(a.c_str(), &e1), hi = std::strtod(b.c_str(), &e2);
  if (a.empty() || b.empty() || *e1 || *e2 || !std::isfinite(hi) || !(hi > lo) || !(lo >= 0))
    throw UsageError("--band: expected 0 <= F_MIN_HZ < F_MAX_HZ (got '" + band + "')");
  return {lo, hi};
}

int runSceneCommand() {
  std::cout << defaultSceneYaml() << std::flush;
  return kOk;
}

}  // namespace mmv::cli
