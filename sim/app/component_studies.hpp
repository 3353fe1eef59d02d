#pragma once
/// `converge` (frequencies against segments per link, sim/modes/converge.hpp) and
/// `compare` (component modes against system modes, sim/modes/compare.hpp) as studies.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/core/integrators.hpp"
#include "sim/modes/compare.hpp"
#include "sim/modes/converge.hpp"

namespace mmv::app {

/// `converge`'s options, declared once (sim/app/options.hpp).
struct ConvergeParams {
  int max_segments = 64;
  int modes = 6;

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.max_segments, Option("max_segments", "Finest segment count (a power of two is reached)").range(1, limits::kMaxSegments));
    v(s.modes, Option("modes", "Number of modes to tabulate").range(1, 1000));
  }
};

struct ConvergeRequest : ConvergeParams {
  Front front = Front::Cli;
};

struct ConvergeStudy {
  ConvergenceStudy study;
  nlohmann::ordered_json json;
  std::string text, csv;
};

ConvergeStudy runConvergeStudy(const Scene& scene, const ConvergeRequest& request);

/// The component boundary conditions `compare` and `sweep-config` take.
inline constexpr const char* kComponentBcs = "clamped-free,pinned-free,free-free,clamped-pinned,pinned-pinned";

/// `compare`'s options, declared once (sim/app/options.hpp).
struct CompareParams {
  std::string bc = "clamped-free";
  std::string tip_mass = "torquer";
  int component_modes = 4;
  int modes = 10;
  std::vector<std::string> topologies;  ///< open, closed; empty: the scene's.

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.bc, Option("bc", "Component boundary condition").choices(kComponentBcs));
    v(s.tip_mass, Option("tip_mass", "Component tip mass: torquer (the report's TREETOPS choice), outboard, none, or "
                                     "MASS_KG[,INERTIA_KG_M2]"));
    v(s.component_modes, Option("component_modes", "Modes per link in the synthesis").range(1, 200));
    v(s.modes, Option("modes", "System modes compared").range(1, 500));
    v(s.topologies, Option("topologies", "open, closed, or open,closed (side by side; default: the scene's)")
                        .flag("--topology")
                        .choices("open,closed")
                        .commaSeparated());
  }
};

struct CompareRequest : CompareParams {
  Front front = Front::Cli;
};

struct CompareStudy {
  CompareReport report;
  nlohmann::ordered_json json;
  std::string text, markdown;
};

CompareStudy runCompareStudy(const Scene& scene, const CompareRequest& request);

/// The component options (`--bc`, `--tip-mass`) into `o`; a UsageError naming the known values.
void parseComponentOptions(const std::string& bc, const std::string& tip_mass, Front front, ComponentOptions& o);

}  // namespace mmv::app
