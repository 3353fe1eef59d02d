#pragma once
/// `mmvlab place-sensors` on an article: candidate stations along every link, the
/// target modes' shapes there, and the choice of sensor_placement.hpp.
///
/// Candidates: stations every `spacing` along each link (from one spacing out to the
/// tip; the tip always), each measuring along the link (axial) and across it
/// (transverse) in the plane of motion. A uniaxial candidate is one direction at one
/// station; a triaxial block is both in-plane directions at a station, kept or removed
/// together (the planar model has no out-of-plane motion, so a block's third axis reads
/// nothing and is left out). The spatial model adds each station's normal axis (a
/// triaxial block is then all three; PointRef::localAxis). Each row's tributary mass is the link's mass per length
/// times the spacing. Shapes are the mass-normalised system modes about the static
/// equilibrium (sim/modes/system_modes.hpp), evaluated at stations with the beam's
/// shape functions (sim/model/stations.hpp), so the choice does not depend on the mesh.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/modes/modal.hpp"
#include "sim/core/mode_number.hpp"
#include "sim/modes/sensor_placement.hpp"
#include "sim/modes/tam.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

struct PlacementOptions {
  std::vector<ModeNumber> modes;  ///< target modes; empty: every mode below `below_hz`.
  double below_hz = 50;       ///< Hz (the report's 0.1-50 Hz band).
  double spacing_m = 0.1;     ///< m between candidate stations.
  bool triaxial = false;
  PlacementMethod method = PlacementMethod::EffectiveIndependence;
  std::vector<TamMethod> tam;  ///< test-analysis models to build on the chosen sensors (the article's)
  double sensor_mass_kg = 0;   ///< > 0: each chosen sensor's mass, welded on and the modes solved again (the article's)
  double min_separation_m = 0;  ///< > 0: no two chosen stations closer (a station's directions excepted)
  /// Stretches of a link no sensor may go on (torquer housings, clamps): link, from, to (m from its root).
  struct KeepOut {
    std::string link;
    double from_m = 0, to_m = 0;
  };
  std::vector<KeepOut> keep_out;
  int count = 8;              ///< sensors (uniaxial) or blocks (triaxial) to keep.
  /// The scene's own accelerometers (at stations, or links' roots and tips) kept, each
  /// counted in `count`, the others chosen around them (uniaxial placement).
  bool keep_scene_sensors = false;
  /// The sensor placed (its range and resolution for the exciter's levels); its mass is
  /// `sensor_mass_kg`'s business (the front end sets it from this one's).
  InstrumentSpec instrument = reportInstrument("accelerometer");
  /// With `sensor_mass_kg` > 0: placed again on the model that carries the chosen set
  /// until a set carries itself (at most kMaxLoadedIterations passes).
  bool iterate_loaded = false;
  /// Blocks ("station axis", as PlacementCandidate names them) chosen in advance, the
  /// count's whole: the placement evaluates that set (its scores, AutoMAC, TAMs) on the
  /// model. placeOnLoadedModel's, to keep a set that carries itself.
  std::vector<std::string> keep_set;
  /// > 0: the candidates are strain gauges or piezo films of this length (m) instead of
  /// accelerometers: spans along every flexible link, from its root every `spacing_m`,
  /// each reading the mean in-plane bending strain at the section's face (planar model;
  /// effective independence only; massless). A candidate's station is "A:B", its axis
  /// "strain", its node and position the span's middle.
  double strain_span_m = 0;
};

/// Passes of PlacementOptions::iterate_loaded before it stops unsettled.
inline constexpr int kMaxLoadedIterations = 8;

/// One pass of placement on the loaded model (PlacementOptions::iterate_loaded).
struct LoadedIteration {
  int pass = 0;
  int changed = 0;       ///< chosen blocks not in the set the pass's model carried
  /// The pass chose another set exactly as informative as the one its model carried
  /// (Fisher determinants on that model within kTiedInformation): a tie between
  /// equivalent points (a symmetric article's mirror points), broken by round-off.
  bool tie = false;
  bool settled = false;  ///< none changed, or a tie: the set carries itself
  bool repeats = false;  ///< a set seen before, not the last: the passes cycle
};

/// Relative difference of two sets' Fisher determinants on one model within which
/// they are a tie (LoadedIteration::tie): round-off, far below what a sensor's mass does
/// (a 0.1 kg sensor on HAM-SAS changes a determinant by 1e-4 and more).
inline constexpr double kTiedInformation = 1e-6;

struct PlacementCandidate {
  std::string station;  ///< e.g. "link1@1.20m".
  std::string link;
  double x_m = 0;       ///< along the link from its root.
  std::string axis;     ///< "axial", "transverse", or "triaxial" (a block).
  double world_x = 0, world_y = 0, world_z = 0;  ///< m, at the equilibrium.
  /// kg: the station's tributary mass, the MKE weight: the link between the midpoints to
  /// its neighbours (from the root, to the tip), plus the tip mass and the torquers the
  /// link carries at the last station. A link's stations sum to all of it.
  double mass_kg = 0;
  /// The station's test-geometry node: (link's position in the scene + 1) x 100000 + its
  /// distance from the link's root in mm (link1@2.44m: 102440), the same in every run.
  int node = 0;
  /// Its world translation in each target mode (m per unit modal coordinate; z = 0 on
  /// the planar model), for the test geometry's predicted shapes.
  std::vector<std::array<double, 3>> shape;
  bool fixed = false;  ///< a scene accelerometer kept in advance (keep_scene_sensors)
  /// A strain candidate's reading in each target mode: the mean surface strain over its
  /// span per unit modal coordinate (its placement row; empty for an accelerometer).
  std::vector<double> strain = {};
};

/// What the chosen sensors' own masses do to the article's modes: each sensor welded at
/// its station as a point mass, the loaded model solved again, each target mode followed
/// by MAC, and its frequency shift set beside first-order perturbation theory
/// (d omega / omega = -1/2 sum m_s |u_s|^2 for a mass-normalised shape u at the
/// sensors' stations).
struct SensorLoading {
  double sensor_mass_kg = 0;  ///< each sensor (a triaxial block counts one)
  int sensors = 0;
  double added_kg = 0;
  struct Mode {
    ModeNumber mode{1};           ///< the target, unloaded
    ModeNumber loaded_mode{1};    ///< the loaded model's mode it follows (largest MAC)
    double frequency_hz = 0, loaded_hz = 0;
    double shift = 0;             ///< loaded / unloaded - 1
    double first_order = 0;       ///< -1/2 sum m |u|^2
    double mac = 0;               ///< mass-weighted (the unloaded M), over the coordinates
    /// The exact shift differs from first order by more than a fifth of itself: the
    /// sensors are heavy against the mode's modal mass, their effect is not a small correction.
    bool beyond_first_order = false;
    bool shared = false;          ///< another target follows the same loaded mode: the shapes changed
    /// No loaded mode up to 1.5 times its frequency resembles it (best MAC below 0.5):
    /// the sensors made another article of it, and `loaded_hz` is only the nearest shape's.
    bool lost = false;
  };
  std::vector<Mode> modes;
  std::vector<LoadedIteration> iterations;  ///< empty: placed on the bare model only
  /// The isolator's loading: the springs carry the sensors' weight, so gravity's
  /// stiffness (pendulums, blades) changes with it and first order (the inertia's) is
  /// not the whole shift.
  bool weight_in_stiffness = false;
};

/// A candidate's measuring direction (a row of the placement problem).
struct PlacementDirection {
  int block = 0;            ///< its candidate
  std::string axis;         ///< axial, transverse, normal
  std::array<double, 3> world{};  ///< unit vector, world frame
};

struct PlacementStudy {
  std::string scene_name;
  std::string method;
  bool triaxial = false;
  std::vector<ModeNumber> target_modes;
  std::vector<double> target_frequencies_hz;
  std::vector<PlacementCandidate> candidates;  ///< one per block.
  PlacementResult result;
  std::vector<PlacementDirection> directions;  ///< every row, in order
  std::vector<std::string> channels;  ///< the chosen sensor directions, "station axis", in row order (the TAMs' and channels.csv's)
  std::vector<TamResult> tams;        ///< one per options.tam, on `channels`
  std::optional<SensorLoading> loading;  ///< options.sensor_mass_kg > 0
  InstrumentSpec instrument;             ///< what is placed (options.instrument)
  int requested = 0;                     ///< the count asked for (the separation may leave room for fewer)
  /// The set ("station axis", sorted) whose sensors' masses the study's model carries
  /// (options.iterate_loaded; empty: the bare model): its target modes are that model's.
  std::vector<std::string> carried;
  bool strain = false;                   ///< strain gauges or films (options.strain_span_m), not accelerometers
  double strain_span_m = 0;              ///< their length
};

/// Throws UsageError for target modes that do not exist or are not vibration modes
/// (rigid or unstable), or a count larger than the candidates; NumericalError as the
/// modes analysis or when the candidates cannot see every target mode.
PlacementStudy runPlacement(const ArticleScene& scene, const PlacementOptions& options);

/// What every kind of placement shares. The target modes: `options.modes`, or every
/// vibration mode below `options.below_hz` (UsageError as runPlacement).
std::vector<ModeNumber> placementTargets(const ModalSolution& modes, const PlacementOptions& options);
/// Checks the count against `study.candidates` (one per block; `directions` rows per
/// triaxial block; `where` says what the candidates are, for the message) and fills
/// `study.result` from `p`.
void choosePlacement(PlacementStudy& study, const PlacementProblem& p, const PlacementOptions& options, int directions,
                     const std::string& where);

/// Placement on the model that carries its own chosen set (PlacementOptions::iterate_loaded),
/// for the article and the isolator alike: `placeCarrying(set)` places on the model that
/// carries `set`'s sensors, starting from `bare`'s; the passes stop when a set carries
/// itself (the pass chose the set its model carried, or one tied with it:
/// LoadedIteration::tie), when a set repeats (the passes cycle), or after
/// kMaxLoadedIterations. Returns the last pass's placement; a record
/// per pass goes to `iterations`. `placeCarrying(set, keep)` with `keep` evaluates `set`
/// itself on the model carrying it (PlacementOptions::keep_set): after a tie the carried
/// set is kept, on its own model, so the study's modes are those of the model carrying it.
PlacementStudy placeOnLoadedModel(const PlacementStudy& bare,
                                  const std::function<PlacementStudy(const PlacementStudy&, bool)>& placeCarrying,
                                  std::vector<LoadedIteration>& iterations);

/// Marks `options.keep_set`'s blocks among `study`'s candidates fixed in `p` (each must
/// be a candidate: MMV_DEMAND).
void keepChosenSet(const PlacementOptions& options, const PlacementStudy& study, PlacementProblem& p);

/// "station axis" of each chosen block of `study`, sorted: a placement's set.
std::vector<std::string> chosenSet(const PlacementStudy& study);

/// `bare` with `chosen`'s set: the candidates of `bare` at the same stations and axes
/// (the candidates are the same physical points on the bare and the loaded model).
PlacementStudy withChosenSet(const PlacementStudy& bare, const PlacementStudy& chosen);
/// `s` with the set `names` ("station axis", each one of its candidates) chosen.
PlacementStudy withNamedSet(const PlacementStudy& s, const std::vector<std::string>& names);

}  // namespace mmv
