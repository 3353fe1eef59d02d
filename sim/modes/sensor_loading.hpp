#pragma once
/// What the chosen sensors' own masses do to the article's modes (SensorLoading,
/// sim/modes/place_sensors.hpp).

#include <utility>
#include <vector>

#include "sim/core/mode_number.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

/// The column of `loaded` (shapes over the same coordinates) that follows `phi` (by
/// MAC weighted by the unloaded mass matrix `M`), and that MAC.
std::pair<ModeNumber, double> followMode(const Eigen::MatrixXd& M, const Eigen::VectorXd& phi, const Eigen::MatrixXd& loaded);

/// `scene` with each chosen block of `study` welded at its station with `mass`, except
/// the scene's own sensors (fixed), which carry their instruments' masses already.
ArticleScene sceneWithSensors(const ArticleScene& scene, const PlacementStudy& study, double mass);

/// The loading's first-order half: `out`'s sensor mass, count (the chosen blocks but
/// the scene's own) and added mass, and a mode per target with its first-order shift
/// -1/2 m sum |u|^2 over the chosen points (PlacementCandidate::shape, mass-normalised).
void firstOrderLoading(const PlacementStudy& study, double sensor_mass_kg, SensorLoading& out);

/// The other half: each target of `study` (its unloaded shapes `shapes`, over the
/// coordinates of the unloaded mass matrix `M`) followed into the `loaded` solution by
/// MAC among its modes up to 1.5 times the target's frequency, its exact shift, whether
/// first order holds, and which targets share or lost their loaded mode.
void followLoadedModes(const PlacementStudy& study, const Eigen::MatrixXd& M, const Eigen::MatrixXd& shapes,
                       const ModalSolution& loaded, SensorLoading& out);

/// The loading of `study`'s chosen sensors, each of `sensor_mass_kg`, on `scene` whose
/// unloaded solution is `s` (target shapes `shapes`, coordinates x targets). The
/// scene's own sensors (fixed) are on `scene` already: they add nothing.
SensorLoading sensorLoading(const ArticleScene& scene, const SolvedScene& s, const Eigen::MatrixXd& shapes,
                            const PlacementStudy& study, double sensor_mass_kg);

}  // namespace mmv
