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

/// The loading of `study`'s chosen sensors, each of `sensor_mass_kg`, on `scene` whose
/// unloaded solution is `s` (target shapes `shapes`, coordinates x targets).
SensorLoading sensorLoading(const ArticleScene& scene, const SolvedScene& s, const Eigen::MatrixXd& shapes,
                            const PlacementStudy& study, double sensor_mass_kg);

}  // namespace mmv
