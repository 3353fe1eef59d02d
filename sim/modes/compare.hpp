#pragma once
/// The report's question as one analysis: component modes of every flexible link
/// (report Table 2), system modes of the assembled article at its equilibrium each
/// attributed to the link that dominates it (Table 3) with the nearest component mode
/// of that link beside it, the synthesis from component modes (assumed modes and
/// Craig-Bampton) with frequency errors, MAC and verdicts, the effect of the tip-mass
/// rule, and optionally open against closed topology. Plain data for the writers.

#include <optional>
#include <string>
#include <vector>

#include "sim/modes/system_modes.hpp"
#include "sim/modes/cms.hpp"
#include "sim/modes/components.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

struct CompareOptions {
  ComponentOptions component;  ///< boundary condition and tip-mass rule for Table 2 and assumed modes.
  int modes_per_link = 4;
  int system_modes = 10;
  /// Topologies, in order: "open" (closures removed) and/or "closed" (the scene's
  /// closures, which it must have). Empty: the scene as it is. The main tables use
  /// the first; with two, a side-by-side table of system modes is added.
  std::vector<std::string> topologies;
};

struct SystemModeRow {
  ModeNumber mode;
  double frequency_hz = 0;
  bool stable = true;
  std::string strain_link, kinetic_link;
  double strain_share = 0, kinetic_share = 0;
  std::string family;             ///< spatial model: in-plane, out-of-plane, torsion, mixed; else empty.
  std::optional<ModeNumber> component_mode;  ///< nearest component mode of strain_link, none: none; on the
                                  ///< spatial model of the same family (any family for a mixed mode).
  double component_hz = 0;
  double component_difference = 0;  ///< system / component - 1.
};

struct TipRuleEffect {
  std::string rule;
  std::vector<std::pair<std::string, double>> first_component_hz;  ///< per link.
  double max_abs_error = 0;  ///< assumed-mode synthesis over the compared modes.
  int predicted = 0;
};

struct TopologyColumn {
  std::string topology;  ///< "open" or "closed".
  std::vector<SystemModeRow> modes;
};

struct CompareReport {
  std::string scene_name, scene_source;
  bool spatial = false;  ///< model: spatial (components and modes carry their families).
  std::vector<std::pair<std::string, double>> joint_angles_deg;
  double gravity = 0;
  std::string topology;  ///< of the main tables.
  ComponentOptions component;
  std::vector<ComponentResult> components;  ///< Table 2.
  std::vector<SystemModeRow> system;        ///< Table 3.
  SynthesisResult assumed, craig_bampton;
  std::vector<TipRuleEffect> tip_rules;
  std::vector<TopologyColumn> topologies;  ///< filled when both were asked for.
};

/// Runs everything for the scene. Throws SceneError (e.g. closed topology asked for a
/// scene without closures) or NumericalError.
CompareReport runCompare(const ArticleScene& scene, const CompareOptions& options);

/// The scene without its closures (the open tree).
ArticleScene openTopology(const ArticleScene& scene);

}  // namespace mmv
