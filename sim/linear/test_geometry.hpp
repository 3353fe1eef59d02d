#pragma once
/// The test geometry of a linear model, as plain data: what a modal-test package imports
/// (sim/io's UFF writer takes it; it queries no model). Nodes at the equilibrium's named
/// points (joints, roots, hinges, tips), then the stations the model's inputs and
/// outputs name, then the base; a trace line per link (root, hinges, tip); the first
/// modes' shapes at the mesh points, per unit modal coordinate (translations and the
/// points' body rotations).

#include <optional>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "sim/linear/state_space.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

struct TestNode {
  int id = 0;  ///< 1-based, in order
  std::string name;
  std::array<double, 3> xyz{};  ///< m, at the equilibrium
};

struct TestTrace {
  int id = 0;
  std::string name;       ///< the link
  std::vector<int> nodes;  ///< root, hinges, tip
};

struct TestModeShape {
  ModeNumber mode;
  double frequency_hz = 0, damping_ratio = 0;
  /// One entry per mesh point (nodes 1 .. mesh_points): translation (m) and body rotation (rad).
  std::vector<std::array<double, 3>> translation, rotation;
};

/// The base node's name: the table's top, where a base input is measured.
extern const char* const kBaseNode;

struct TestGeometry {
  std::vector<TestNode> nodes;
  std::map<std::string, int> id_of;  ///< node id by name
  int mesh_points = 0;               ///< the first nodes, those the shapes cover
  std::vector<TestTrace> traces;
  std::vector<TestModeShape> modes;
};

/// The geometry of `lm` (built from `scene`) with its first `modes` shapes (fewer when
/// the model has fewer).
TestGeometry linearTestGeometry(const LinearModel& lm, const ArticleScene& scene, int modes);

}  // namespace mmv
