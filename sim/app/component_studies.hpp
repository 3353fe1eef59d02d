#pragma once
/// `converge` (frequencies against segments per link, sim/modes/converge.hpp) and
/// `compare` (component modes against system modes, sim/modes/compare.hpp) as studies.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/modes/compare.hpp"
#include "sim/modes/converge.hpp"

namespace mmv::app {

struct ConvergeRequest {
  int max_segments = 64;  ///< 1 .. limits::kMaxSegments (a power of two is reached).
  int modes = 6;          ///< 1 .. 1000.
  Front front = Front::Cli;
};

struct ConvergeStudy {
  ConvergenceStudy study;
  nlohmann::ordered_json json;
  std::string text, csv;
};

ConvergeStudy runConvergeStudy(const Scene& scene, const ConvergeRequest& request);

struct CompareRequest {
  std::string bc = "clamped-free";  ///< clamped-free, pinned-free, free-free, clamped-pinned, pinned-pinned
  std::string tip_mass = "torquer"; ///< none, torquer, outboard, or MASS_KG[,INERTIA_KG_M2]
  int component_modes = 4;          ///< 1 .. 200 per link.
  int modes = 10;                   ///< 1 .. 500 system modes.
  std::vector<std::string> topologies;  ///< open, closed; empty: the scene's.
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
