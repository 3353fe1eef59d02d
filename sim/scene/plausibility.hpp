#pragma once
/// Values no laboratory article has, each with the unit slip that likely made it: one
/// set of rules, evaluated when a scene is read (every command warns on stderr at the
/// key's position; `--strict` makes them errors, exit 65) and by `check` and `modes`,
/// which add the rules that need a solution (deflection, first frequency).
///
///   materials: density 100..25000 kg/m^3, Young's modulus 1e8..1.2e12 Pa;
///   links: length up to 20 m, section area up to 0.05 m^2, mass up to 500 kg, a tip
///          mass up to 100 times the link's own mass (a 20 kg mass on an 8 g branch);
///   gravity: 9.7..9.9 m/s^2 when not zero.
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace mmv {

/// The bounds above, for tests and docs.
namespace plausible {
inline constexpr double kMinDensity = 100, kMaxDensity = 25000;    ///< kg/m^3
inline constexpr double kMinModulus = 1e8, kMaxModulus = 1.2e12;  ///< Pa
inline constexpr double kMaxLength = 20;                          ///< m
inline constexpr double kMaxArea = 0.05;                          ///< m^2
inline constexpr double kMaxLinkMass = 500;                       ///< kg
inline constexpr double kMaxTipMassRatio = 100;                   ///< tip mass over the link's own
inline constexpr double kMinGravity = 9.7, kMaxGravity = 9.9;     ///< m/s^2
}  // namespace plausible

/// Each implausible value as "FILE:LINE:COL: KEY VALUE UNIT is ...: likely slip?" (the
/// position of its key when the scene was read from a file; without one, the text alone).
std::vector<std::string> scenePlausibility(const ArticleScene& scene);

}  // namespace mmv
