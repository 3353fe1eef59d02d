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

/// The loading of `study`'s chosen sensors, each of `sensor_mass_kg`, on `scene` whose
/// unloaded solution is `s` (target shapes `shapes`, coordinates x targets). The
/// scene's own sensors (fixed) are on `scene` already: they add nothing.
SensorLoading sensorLoading(const ArticleScene& scene, const SolvedScene& s, const Eigen::MatrixXd& shapes,
                            const PlacementStudy& study, double sensor_mass_kg);

}  // namespace mmv
