#pragma once
/// `mmvlab check`: can this article be tested in this facility with these torquers,
/// table, gimbal and sensors? One line per requirement: what the test demands, what the
/// equipment gives, the margin and a verdict (docs/planning.md).
///
/// What each group computes (all in SI; angles in rad):
///  - torquers: the holding torque of each locked joint and each gimbal axis, worst over
///    the configuration range. A rigid-link model of the article is searched over every
///    held angle within its range (a grid, then a pattern search from the worst grid
///    point to 1e-4 rad); the worst configuration is then solved with the scene's
///    flexible model (deflected shape with gravity) and that torque is the demand.
///    Closed trees and scenes with free or servo joints are checked at the scene's
///    configuration only (the closure or the free joints fix the others), and say so.
///    Slews: the peak torque of a time run of the rigid-link article through the
///    scene's programs (gravity and the slews' inertial torque; flexible dynamic
///    amplification needs `mmvlab simulate`).
///  - table (scene on the table): payload weight (article, torquers, gimbal) against
///    the table's load capacity; the program's peak displacement against the stroke;
///    its highest frequency against the servo bandwidth; the modes in the band above
///    the bandwidth, which the table cannot excite.
///  - modes: the system modes in the band (report: 0.1-50 Hz), their closest pair
///    against the half-power bandwidth 2 zeta f (zeta the scene's modal damping, else
///    1 %): closer than that, one response peak hides the other.
///  - sensors: each sensor's peak signal against its range, with its
///    signal-to-resolution ratio in dB: during the rigid-link run (slews and table,
///    through the sensor model) and, for accelerometers on the table, the steady-state
///    response of the flexible linear model to the table's program (sine: at its
///    frequency; sweep: the worst over its band; random: 3 sigma).
///  - planarity (model: spatial): the modes in the band that leave the plane, each
///    against its nearest in-plane mode's half-power bandwidth (closer, frequency alone
///    cannot tell them apart); under each program the scene runs (table x, slews), the
///    out-of-plane over in-plane resonant response at the link tips against
///    max_out_of_plane_ratio (sim/modes/planarity.hpp). Above it: warn.
///  - shaker (scene with `shaker:`): the extra shaker planned on the scene's own
///    accelerometers (sim/linear/exciter.hpp): its armature's largest shift of a mode in
///    the band against 2 % (above it: warn), and per mode in the band the sine dwell's
///    signal-to-noise at the best sensor against 20 dB (under it: warn), at the force the
///    shaker's force and stroke and the sensors' range allow. Not checked (with the
///    reason): no accelerometer, one at a point of the mesh, an undamped article.
///  - lab (scene with `lab:`): the envelope of the article's points at rest and during
///    the rigid-link run against the floor, the ceiling and the platform's hole.
///  - plausibility: masses, lengths, moduli, deflections and frequencies outside what a
///    lab article can have, each naming the likely unit mistake.

#include <string>
#include <vector>

#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// Advisory: a line that is not a requirement of the test (the table's bandwidth against
/// the modes, the closest pair, planarity) whose demand exceeds its capacity (a negative
/// margin); its note says how the test goes on. It raises the overall verdict to warn.
enum class Verdict { Pass, Warn, Fail, NotChecked, Info, Advisory };
const char* verdictName(Verdict v);  ///< "pass", "warn", "FAIL", "n/a", "info", "advisory".

struct CheckLine;
/// Marks `l` advisory: a negative margin becomes Verdict::Advisory, never FAIL nor a
/// mislabelled warn.
void makeAdvisory(CheckLine& l);

struct CheckLine {
  std::string id;           ///< stable across runs of one scene, e.g. "torque.joint1.hold", "table.stroke" (sweep columns).
  std::string group;        ///< torquers, gimbal, table, modes, planarity, sensors, shaker, lab, plausibility.
  std::string requirement;  ///< what is checked, e.g. "joint1 holding torque over +-45 deg".
  double demand = 0;        ///< what the test needs (unit below).
  double capacity = 0;      ///< what the equipment gives; 0 with has_capacity false: unknown.
  bool has_capacity = false;
  std::string unit;
  /// (capacity - demand) / capacity * 100; meaningful when has_capacity.
  double margin_pct = 0;
  Verdict verdict = Verdict::Info;
  std::string note;  ///< where the worst case is, what is assumed, what to do.
};

struct CheckOptions {
  double required_margin_pct = 20;  ///< below it (but >= 0): warn.
  double band_min_hz = 0.1, band_max_hz = 50;  ///< the modes of interest (report).
  int grid_points = 0;  ///< per held angle in the torque search; 0: 5 (3 beyond 5 angles).
  /// Spatial model: the out-of-plane over in-plane response a planar test tolerates.
  double max_out_of_plane_ratio = 0.05;
};

struct CheckReport {
  std::string scene_name, scene_source;
  std::vector<std::string> overrides;
  int segments = 0;  ///< the largest segment count of a flexible link.
  std::vector<CheckLine> lines;
  Verdict overall = Verdict::Pass;
  int not_checked = 0;  ///< lines without a capacity to check against.
  double seconds = 0;
};

/// Runs every check that applies to the scene. Throws NumericalError when the
/// equilibrium or the modes cannot be found (nothing to check against).
/// `modes`, if given, is the scene's ModesReport already computed (a sweep reuses it).
CheckReport runCheck(const ArticleScene& scene, const CheckOptions& options = {}, const ModesReport* modes = nullptr);

/// margin and verdict of a line from demand and capacity (exposed for the tests).
void judge(CheckLine& line, double required_margin_pct);

/// Warnings that name a likely unit mistake (a density in g/cm^3, a length in mm, a
/// 500 kg link, a deflection of a tenth of the article, a first mode outside 0.01 Hz to
/// 10 kHz): the plausibility lines of `check`, also printed by `modes`.
std::vector<std::string> plausibilityWarnings(const ArticleScene& scene, const ModesReport& modes);

}  // namespace mmv
