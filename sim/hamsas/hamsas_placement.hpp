#pragma once
/// `mmvlab place-sensors` on the HAM-SAS isolator: candidates on its rigid bodies and
/// the choice of sensor_placement.hpp for the target modes.
///
/// Candidates: on every moving body, its mass centre and the 8 corners of its
/// equivalent box (article/spatial_spec.hpp: the box renders draw), each measuring
/// along world x, y and z; a corner sees the body's rotation, u = t + theta x r. A
/// uniaxial candidate is one axis at one point; a triaxial block is the three. Each
/// row's tributary mass is the body's mass over its 9 points. Shapes are the
/// isolator's mass-normalised modes (sim/hamsas/hamsas_modes.hpp).

#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// A candidate point's test-geometry node, the same in every run: body (its index in the
/// isolator, 1 = the first moving body) x 100, plus 0 for its mass centre or 1..8 for its
/// box's corners (spring_box.corner3 of body 2: 203).
int hamsasNode(int body, int point);

/// The candidates (one per block, appended to `candidates`, with their nodes and target
/// shapes) and their rows of the
/// target modes' shapes; with `readings`, each row's reading per unit free coordinate
/// (the test-analysis models' observation rows). The points are the mass centres and box
/// corners of `points`' bodies (default: `h.model`'s); given the bare isolator while `h`
/// is the isolator loaded with sensors, they stay the same physical points while each
/// body's mass centre, the origin of its coordinates, moves.
PlacementProblem hamsasCandidates(const HamsasModes& h, const std::vector<ModeNumber>& targets, bool triaxial,
                                  std::vector<PlacementCandidate>& candidates,
                                  std::vector<Eigen::RowVectorXd>* readings = nullptr, const SpatialSpec* points = nullptr);

/// `model` with a point mass `mass` at each chosen point of `study` on its body: the
/// body's mass, mass centre and inertia about it (parallel axes).
SpatialSpec isolatorWithSensors(const SpatialSpec& model, const PlacementStudy& study, double mass);

/// What the chosen sensors' masses (each `sensor_mass_kg`, a triaxial block one sensor)
/// do to the isolator's target modes: the isolator rebuilt with them on its bodies
/// (isolatorWithSensors), linearized again at its design configuration (the springs'
/// preloads carry the added weight, so gravity's stiffness, the inverted pendulums' and
/// the blades', feels it as the inertia does), each target followed by MAC
/// (SensorLoading, sim/modes/place_sensors.hpp). The first-order shift printed beside it
/// counts the inertia only: a mode whose stiffness is gravity's (a pendulum's g / L)
/// hardly moves, and shows as beyond first order.
SensorLoading hamsasSensorLoading(const HamsasModes& h, const PlacementStudy& study, double sensor_mass_kg);

/// The isolator `h` with a point mass `mass` at each chosen point of `study`, linearized
/// again at its design configuration, solved and its modes described (its coordinates at
/// the loaded bodies' mass centres; no measured features).
HamsasModes isolatorCarrying(const HamsasModes& h, const PlacementStudy& study, double mass);

/// As runPlacement for an article; `options.spacing_m` does not apply (the points are
/// the bodies'). With `options.iterate_loaded` (and a sensor mass) placed again on the
/// isolator carrying the chosen set (isolatorCarrying) until a set carries itself, as
/// the article's (placeOnLoadedModel): the target modes, frequencies, shapes and TAMs are
/// then the loaded isolator's, the loading reported against the bare one. Throws
/// UsageError for modes that do not exist or are not vibration modes, or a count above
/// the candidates; NumericalError when the candidates cannot see every target mode.
PlacementStudy runHamsasPlacement(const HamsasScene& scene, const HamsasModes& h, const PlacementOptions& options);

}  // namespace mmv
