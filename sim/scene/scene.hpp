#pragma once
/// A scene: what is tested and its environment as plain data in SI units (angles in
/// radians), read from YAML (docs/scene-format.md). No Simbody here.
///
/// Scene is a variant of the two kinds of test article mmvlab analyses: the planar MMV
/// article (ArticleScene, the default) and the HAM-SAS isolator (HamsasScene, a file
/// with a top-level `hamsas:` key). The CLI dispatches on the kind once; every
/// analysis takes the kind it understands.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <variant>
#include <vector>
#include <stdexcept>
#include <string>

#include "article/article_spec.hpp"
#include "article/hamsas.hpp"
#include "facility/lab.hpp"
#include "facility/sensors.hpp"
#include "facility/shaker.hpp"
#include "sim/core/errors.hpp"

namespace mmv {

/// Damping for linear models and time runs.
struct DampingSpec {
  enum class Kind {
    Modal,         ///< every mode gets `modal_ratio` (linear models only).
    Rayleigh,      ///< C = alpha M + beta K (linear models only).
    HingeViscous,  ///< a viscous damper c = hinge_beta * k on every bending hinge (both).
  } kind = Kind::Modal;
  double modal_ratio = 0.01;
  double alpha = 0, beta = 0;  ///< 1/s, s.
  double hinge_beta = 0;       ///< s.
};

/// Settings of a time run (`simulation:` in the scene; the command line overrides).
struct SimulationSpec {
  double duration = 10;         ///< s.
  /// Empty: the run chooses (sim/time/fidelity.hpp); a scene file that names none.
  std::string integrator = "rk_merson";
  double accuracy = 1e-6;       ///< integrator relative accuracy.
  double absolute_tolerance = 0;  ///< SUNDIALS integrators only (m, rad, m/s, rad/s); 0: the accuracy.
  double sample_rate_hz = 200;  ///< output rows per second.
  bool from_equilibrium = true; ///< start at the static equilibrium, else at the scene's angles at rest.
  /// The outputs `mmvlab trade` scores (link tips; HAM-SAS: optical_table, spring_box);
  /// empty: every one. `--points` overrides.
  std::vector<std::string> score_points;
  std::string score_where;  ///< file:line:col of score_points, for errors found later.
  /// `simulation.fidelity` (sim/time/fidelity.hpp): Auto lets an article's time run
  /// carry its links by the modes its programs excite; Segments keeps every hinge. A
  /// scene read from a file is Auto unless it says so; code-built specs keep the segments.
  enum class Fidelity { Segments, Auto };
  Fidelity fidelity = Fidelity::Segments;
  /// Links in modal coordinates also keep their modes up to 2^this times the highest
  /// frequency the scene's `modes:` or the default fidelity's rule keep, and at least one
  /// more (capped at the hinges): a verification companion's 1, so that its estimate sees
  /// the modes left out as well as the tolerance (the next octave: for a beam, whose
  /// frequencies grow as n^2, about 1.4 times the modes, where twice the modes cost four
  /// times the frequency to resolve).
  int modal_refinement = 0;
  /// A verification companion's run (sim/time/verify.hpp): only the time and the scored
  /// points are recorded (no torques, sensors, states, energies or Simpson midpoints),
  /// which is all its comparison reads. Never from a scene file.
  bool scored_only = false;
};

/// A sensor recorded in time runs (facility/sensors.hpp for the models).
struct SensorSceneSpec {
  std::string name;
  std::string type;    ///< encoder, rate_gyro, accelerometer.
  std::string target;  ///< joint (encoder), named point or station (gyro, accelerometer).
  /// The sensing axis in the point's local frame (PointRef::localAxis): 0 along the
  /// link (axial), 1 across it in its plane (transverse), 2 the normal. Accelerometers
  /// default to 0, gyros to 2 (the in-plane rotation); the accelerometer's normal and
  /// the gyro's other axes need model: spatial.
  int axis = 0;
  double noise_sigma = 0;  ///< in the measured unit; 0: none.
  std::uint64_t seed = 1;
  std::string where;   ///< file:line:col, for errors found later.
  std::string instrument;  ///< its model in the scene's catalogue (`instruments:`); empty: the type's own (the report's)
  /// A strain sensor's span (`span: [A, B]`, sim/scene/stations.hpp StrainSpan): `target`
  /// is station A, `span_end` station B; its mean surface strain is
  /// -surface_m (theta_B - theta_A) / span_m in the plane; with `bending: out` (spatial
  /// model) the +z face's, +surface_m (phi_B - phi_A) / span_m.
  std::string span_end;
  double surface_m = 0, span_m = 0;
  bool out_of_plane = false;
};

/// A sensor model of the scene's catalogue (`instruments:`, docs/scene-format.md). The
/// report's three, named by their types (`encoder`, `rate_gyro`, `accelerometer`), are
/// always there, any key of theirs overridable; a scene adds others by name and type.
struct InstrumentSpec {
  std::string name;
  /// What the sensor records through: its type (`kind`), range, resolution and band;
  /// the noise and seed are each sensor's own.
  facility::SensorSpec spec;
  /// kg: the housing (with its cable's share and mount), welded on the article at each
  /// sensor of it in every analysis; 0: massless. The report gives no sensor's mass.
  double mass_kg = 0;
  double size_m = 0;  ///< m: the housing's edge, for drawings (0: a glyph)
  int axes = 1;       ///< 3: a triaxial block, one housing for the three directions at a point
  std::string where;  ///< file:line:col of its entry ("" for the report's, as built in)
};

/// The report's instruments (facility/sensors.hpp), massless: the report states
/// ranges, resolutions and bands, not masses; the strain film's are assumed.
std::vector<InstrumentSpec> reportInstruments();
/// The report's instrument of a sensor type (as built in).
InstrumentSpec reportInstrument(const std::string& type);

/// A camera pose for renders (`views:`): looking from `eye` at `target`, `up` up.
struct CameraView {
  std::string name;
  std::array<double, 3> eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};  ///< m, world.
  double fov_deg = 30;  ///< vertical field of view.
};

/// The MMV article (or any planar article of links, joints and closures).
/// Where each key of a scene was read: "file:line:col" (or "--set KEY=VALUE") by key
/// path, as the reader's messages name keys ("base.motion", "joints[0].slew",
/// "hamsas.spherical_joints"). A check made after reading (a facility's stroke, a time
/// run's precondition) points at its key with `where` like the reader does.
struct SourceMap {
  std::string file;                          ///< the scene's source name.
  std::map<std::string, std::string> at;     ///< key path -> position.
  /// The key's position, else its nearest enclosing key's, else the file's start.
  std::string where(const std::string& key) const;
};

/// `shaker:`: the extra shaker (facility/shaker.hpp) where it is attached. A scene
/// without one builds none; `place-sensors` then plans no excitation.
struct ShakerSceneSpec {
  std::string at;  ///< a station of the article (sim/scene/stations.hpp), or "auto": the best-ranked candidate
  /// The force's direction (world, unit); `auto_direction`: the best-ranked candidate's.
  std::array<double, 3> direction{0, 1, 0};
  bool auto_direction = false;
  facility::ShakerSpec hardware;
  bool autoAt() const { return at == "auto"; }
  /// `shaker.program`: the force it drives along `direction` in time runs (N over time;
  /// sine, sweep, random or csv, as `base.motion`), through its armature
  /// (sim/model/attachments.hpp). None: the shaker is attached and idle in no run (it is
  /// built for time runs only when it has a program).
  std::optional<TableMotion> program;
};

struct ArticleScene {
  std::string name;
  std::string source;  ///< file the scene came from, or "<default scene>".
  std::string text;    ///< the YAML as read (a run's output directory keeps a copy).
  std::vector<std::string> overrides;  ///< the --set KEY=VALUE it was read with.
  std::array<double, 3> gravity{0, -9.80665, 0};  ///< m/s^2 in the world frame, z = 0.
  ArticleSpec article;
  std::optional<DampingSpec> damping;  ///< from the scene's `damping:`; commands choose otherwise.
  SimulationSpec simulation;
  std::vector<SensorSceneSpec> sensors;
  std::vector<InstrumentSpec> instruments;  ///< the catalogue: the report's three (as the scene sets them), then the scene's own
  std::vector<CameraView> views;  ///< named camera poses for `mmvlab render --view NAME`.
  std::optional<facility::LabSpec> lab;  ///< `lab:`: the room, drawn by renders (none: the article alone).
  std::optional<ShakerSceneSpec> shaker;  ///< `shaker:`: the extra shaker (none: the table is the only exciter).
  SourceMap positions;  ///< where each key was read.
};

/// The HAM-SAS seismic isolator (article/hamsas.hpp), gravity along -z.
struct HamsasScene {
  std::string name;
  std::string source;
  std::string text;  ///< the YAML as read.
  std::vector<std::string> overrides;  ///< the --set KEY=VALUE it was read with.
  HamsasSpec isolator;
  SimulationSpec simulation;
  /// Time runs: the ground's (base's) motion program along world x, y or z.
  std::optional<TableMotion> ground_motion;
  int ground_axis = 0;  ///< 0 x, 1 y, 2 z.
  SourceMap positions;  ///< where each key was read.
};

using Scene = std::variant<ArticleScene, HamsasScene>;

/// The instrument `name` of the scene's catalogue (the report's three in a scene built
/// without one), or nullptr.
const InstrumentSpec* findInstrument(const ArticleScene& scene, const std::string& name);
/// The instrument sensor `s` records through: its own, else its type's.
const InstrumentSpec& instrumentOf(const ArticleScene& scene, const SensorSceneSpec& s);
/// What sensor `s` records through (facility/sensors.hpp): its instrument's spec with
/// the sensor's noise and seed.
facility::SensorSpec sensorSpecOf(const ArticleScene& scene, const SensorSceneSpec& s);

/// The name and source of either kind.
const std::string& sceneName(const Scene& scene);
const std::string& sceneSource(const Scene& scene);
/// The scene file's text as read (before its --set patches), for a run's copy.
const std::string& sceneText(const Scene& scene);


/// Parses scene YAML text; `source_name` is used in error messages. `sets` are
/// `--set KEY=VALUE` overrides (KEY a dotted path: mapping keys, list items by name,
/// e.g. links.link1.length=2.5), applied to the document before it is read, so each
/// value is checked as if it were in the file; an error in one names it ("--set
/// KEY=VALUE: ..."). The scene's source then ends with the overrides. Throws
/// SceneError (UsageError for a malformed --set).
///
/// `flags` are a front end's dedicated options, made patches of the same document after
/// the --set ones and checked by the same readers: an error in one is a UsageError
/// named by the option ("--segments 0: links[0].segments must be ..."). The notes they
/// make (a link's `modes:` lowered to its new hinge count) join `notes`.
struct SceneFlags {
  std::optional<int> segments;  ///< every flexible link's `segments` (a link's `modes` above it lowered)
  std::string segments_label;  ///< how the option and its value are named ("--segments 16", "segments=16")
  bool no_gravity = false;     ///< `gravity: [0, 0, 0]`
  std::string gravity_label;   ///< ("--no-gravity", "no_gravity=True")
};
Scene parseScene(const std::string& yaml_text, const std::string& source_name, const std::vector<std::string>& sets = {},
                 const SceneFlags& flags = {}, std::vector<std::string>* notes = nullptr);
/// A value of the scene document at a dotted key (as `--set` names it: mapping keys,
/// list items by name), after the `sets` patches: what `mmvlab update` varies and edits.
struct SceneValue {
  bool found = false;   ///< the key names a scalar
  bool number = false;  ///< a finite number
  double value = 0;
  std::string text;     ///< the scalar as written
  bool in_file = false; ///< written in the file's own text (not only by a --set patch)
  bool plain = false;   ///< in the file as a plain scalar: an edit can replace it in place
  int line = 0, column = 0;  ///< 1-based, in the file
  std::size_t offset = 0, length = 0;  ///< the scalar's bytes in the file
};
SceneValue sceneValueAt(const std::string& yaml_text, const std::vector<std::string>& sets, const std::string& key);

/// A scalar of the file replaced by `value`, `comment` appended to its line.
struct SceneEdit {
  std::size_t offset = 0, length = 0;
  std::string value, comment;
};
/// The file's text with the edits made; every other byte as it was.
std::string editedSceneText(const std::string& yaml_text, std::vector<SceneEdit> edits);

/// Reads and parses a scene file. Throws SceneFileError or SceneError.
Scene loadSceneFile(const std::string& path, const std::vector<std::string>& sets = {}, const SceneFlags& flags = {},
                    std::vector<std::string>* notes = nullptr);
/// " --set A=1 --set B=2": how a source names its overrides.
std::string overrideSuffix(const std::vector<std::string>& sets);
/// The same for a file that must hold an article (or an isolator): SceneError
/// naming the file and its kind otherwise.
ArticleScene loadArticleSceneFile(const std::string& path);
HamsasScene loadHamsasSceneFile(const std::string& path);
/// The MMV article scene embedded in the binary (the same text as scenes/mmv.yaml).
const char* defaultSceneYaml();
ArticleScene loadDefaultScene();

/// Replaces the segment count of every flexible (non-rigid) link; 1 <= n <= limits::kMaxSegments
/// (an internal re-discretization: a user's count reaches the model through SceneFlags).
/// A link in modal coordinates keeps min(modes, n) modes (one hinge per segment); each
/// such clamp is returned as a note for the user ("link link1 in 2 segments keeps 2 of
/// the 3 modes ...").
std::vector<std::string> overrideSegments(ArticleScene& scene, int n);

}  // namespace mmv
