#include "sim/cli/commands.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "sim/analysis.hpp"
#include "sim/cli/output_dir.hpp"
#include "sim/converge.hpp"
#include "sim/report.hpp"
#include "sim/scene.hpp"

namespace mmv::cli {

/// Loads the scene and applies command-line overrides.
Scene loadScene(const SceneArgs& args) {
  Scene scene = args.scene_path.empty() ? loadDefaultScene() : loadSceneFile(args.scene_path);
  if (scene.hamsas && (args.segments > 0 || args.no_gravity))
    throw UsageError("--segments and --no-gravity do not apply to a HAM-SAS scene (rigid bodies; its preloads are gravity's)");
  if (args.segments > 0) overrideSegments(scene, args.segments);
  if (args.no_gravity) scene.gravity = {0, 0, 0};
  return scene;
}

void requireArticleScene(const Scene& scene, const std::string& command) {
  if (scene.hamsas)
    throw UsageError(command + ": " + scene.source +
                     " is a HAM-SAS isolator scene; it supports modes, frf, rom, simulate and trade (docs/hamsas.md)");
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
  } catch (const std::exception& e) {
    std::cerr << "mmvlab: internal error: " << e.what() << '\n';
    return kInternal;
  }
}

int runModesCommand(const ModesArgs& args) {
  return guarded([&]() -> int {
    const Scene scene = loadScene(args);
    if (scene.hamsas) return runHamsasModes(args, scene);
    ModesOptions opt;
    opt.max_modes = args.modes;
    opt.with_shapes = args.json;
    const ModesReport rep = runModes(scene, opt);
    const std::string out = args.json ? modesToJson(rep).dump(2) + "\n" : formatModesText(rep);
    std::cout << out << std::flush;
    return kOk;
  });
}

int runConvergeCommand(const ConvergeArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    requireArticleScene(scene, "converge");
    const ConvergenceStudy c = runConvergence(scene, args.max_segments, args.modes);
    const std::string out = args.json ? convergenceToJson(c).dump(2) + "\n" : formatConvergenceText(c);
    std::cout << out << std::flush;
    return kOk;
  });
}

int runSceneCommand() {
  std::cout << defaultSceneYaml() << std::flush;
  return kOk;
}

}  // namespace mmv::cli
