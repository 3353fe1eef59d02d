#pragma once
/// Time runs of the article (slews of locked joints, table programs, free motion),
/// integrated by one of Simbody's integrators, recorded at a fixed sample rate.
///
/// Recorded per sample: the table's position (when the scene has one), every joint's
/// angle and the torque its torquer applies (for a locked joint the motion force that
/// makes it follow its command; 0 for a free one), and every link tip's position.
/// Summarised: peak torques against each torquer's capacity, the energy balance
///     E(t) - E(0) = W_motion(t) - D(t)
/// (E = kinetic + potential energy, W_motion the work of the prescribed motions, D the
/// dampers' dissipation, both integrated by the trapezoidal rule at the sample rate: the
/// balance's error shrinks with the sample interval squared for smooth commands, but
/// only linearly where a command's acceleration jumps, as in a trapezoidal slew --
/// raise the sample rate there), steps, realizations, and wall time.
///
/// With a table, also its actuator's force along x (`table_force_n`).
///
/// Sensors (scene `sensors:`; facility/sensors.hpp) are sampled at the sample rate:
/// an encoder reads its joint's angle (rad), a rate gyro the angular rate about z of
/// the body carrying its point (rad/s), an accelerometer the specific force (a - g) at
/// its point along the carrying body's x (axial) or y (transverse) axis (m/s^2). Each
/// adds a column `<name>_<unit>` and a saturation count.
///
/// Integrators: every name in sim/core/integrators.hpp (Simbody's, and SUNDIALS'
/// CVODE, ARKODE and IDA through the plugin, sim/time/sundials_plugin.hpp); IDA holds a
/// closed tree's closures as algebraic equations.
/// For SUNDIALS "realizations" counts right-hand-side evaluations. The integrators take
/// their own steps and interpolate the state at the samples, so the step count does not
/// depend on the sample rate (sim/time/run_integrator.hpp).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Simbody.h>

#include "sim/scene/scene.hpp"
#include "sim/time/modal_links.hpp"
#include "sim/time/run_stress.hpp"

namespace mmv {

struct SimulationRecord {
  std::vector<std::string> columns;       ///< names with units, e.g. "joint2_angle_deg".
  std::vector<std::vector<double>> rows;  ///< one per sample, all finite.
  /// The points a trade scores (link tips; the isolator's table and spring box): name
  /// and the columns of its position components (m).
  std::vector<std::pair<std::string, std::vector<int>>> scored;
};

struct JointTorqueSummary {
  std::string joint;
  double peak_torque_nm = 0;
  double capacity_nm = 0;  ///< 0: not given.
  bool exceeded = false;
};

struct SensorSummary {
  std::string name, type, unit;
  int saturated_samples = 0, samples = 0;
  double range = 0;  ///< its instrument's full scale, +-, in `unit`
};

/// A run's error estimated by a companion at a 10x tighter tolerance (sim/time/verify.hpp).
struct RunVerification {
  bool done = false;
  double companion_accuracy = 0;
  double companion_seconds = 0;
  double estimated_error_m = 0;  ///< largest distance of a scored point from the companion's
  double at_s = 0;               ///< where
  std::string point;             ///< which point
  double amplitude_m = 0;        ///< the scored points' largest motion (companion run)
  double target_m = 0;           ///< what the estimate is held to
  bool target_is_default = true; ///< 1 % of amplitude_m (1e-4 m if nothing moved)
  /// The run carried links in modal coordinates and the companion their modes up to twice
  /// the frequency (at least one more), so the estimate sees the modes left out as well
  /// as the tolerance.
  bool companion_more_modes = false;
};

/// The extra shaker in a run with `shaker.program` (sim/model/attachments.hpp): the
/// program's peak force against the shaker's limit, the armature's travel from its start
/// against the stroke, and the largest force the stinger passes to the article (the
/// program's force less the armature's inertia, what a force gauge at the driving point
/// reads).
struct ShakerRunSummary {
  std::string at;
  double peak_force_n = 0, force_limit_n = 0;
  double peak_stroke_m = 0, stroke_m = 0;
  double peak_stinger_force_n = 0;
  bool stroke_exceeded = false;
};

struct SimulationResult {
  SimulationRecord record;
  /// Article runs: the time and every coordinate of the model at each sample (column
  /// `<coordinate>_rad`, or `_m` for the table), enough to redraw the run.
  SimulationRecord states;
  std::vector<SensorSummary> sensors;
  std::vector<JointTorqueSummary> torques;
  double initial_energy_j = 0, final_energy_j = 0;
  double motion_work_j = 0, dissipated_j = 0;
  double energy_balance_error_j = 0;  ///< (E_end - E_0) - (W - D).
  /// The balance (E_t - E_0) - (W_t - D_t) checked at every sample: its largest
  /// magnitude and when (an error that builds up and cancels by the end is seen here).
  double max_energy_balance_error_j = 0, max_energy_balance_error_at_s = 0;
  double peak_kinetic_energy_j = 0;   ///< largest kinetic energy at a sample.
  /// Closed trees: the largest closure error at a sample (m). Simbody's integrators
  /// project onto the closures to their accuracy and IDA holds them as algebraic
  /// equations; SUNDIALS' ODE methods do not, so their drift grows.
  double constraint_drift_m = 0;
  /// With a table: the peak force its actuator must give along x (the table's own
  /// moving mass included; column `table_force_n`), or along the y-axis stage across
  /// the plane when it is larger (`table_z_force_n`), and the weight it carries
  /// (everything but the table: article, torquers, gimbal), against its payload.
  double peak_table_force_n = 0;
  double carried_weight_n = 0;
  std::string integrator;
  double accuracy = 0;
  /// The damping the run carried, one line ("none: the scene has no damping:", or the
  /// model with where its matrix was formed).
  std::string damping;
  int steps = 0, realizations = 0;
  long rejected_steps = 0;  ///< error-test and Newton failures, retried with a smaller step
  long jacobians = 0;       ///< iteration matrices formed (implicit methods); -1: not reported (CPodes)
  double wall_seconds = 0;
  /// The wall time inside the integrator's steps and in sampling (the state interpolated
  /// to each sample and realized, outputs and energy computed); the rest of wall_seconds
  /// is building the model and the start.
  double stepping_seconds = 0, output_seconds = 0;
  /// What the user should know about the run's start: an equilibrium that is unstable
  /// (the run stays there only until round-off grows) or that moved a free joint away
  /// from its scene angle (assessEquilibrium, sim/statics/statics.hpp).
  std::vector<std::string> warnings;
  RunVerification verification;  ///< filled by verifyRun on request
  /// Links carried by their modes (`links[i].modes`; sim/time/modal_links.hpp).
  std::vector<ModalLinkSummary> modal_links;
  /// With `shaker.program`: columns shaker_force_n, shaker_stroke_m, shaker_stinger_force_n.
  std::optional<ShakerRunSummary> shaker;
  /// What the run integrated and why (article runs: sim/time/fidelity.hpp; HAM-SAS: its one model).
  std::string fidelity;
  /// Article runs: each link's stress over the run (sim/time/run_stress.hpp; columns
  /// `<link>_stress_pa`), scene order.
  std::vector<LinkRunStress> stresses;
};

/// Runs the scene's time run with its `simulation:` settings. `progress`, if given,
/// is called with the fraction done (0..1) at each sample. Throws SceneError (unknown
/// integrator) or NumericalError (the integrator gave up: step size too small, too many
/// steps, or a non-finite state; the message names it and the time).
/// (The isolator's runs: sim/hamsas/hamsas_simulation.hpp.)
SimulationResult simulate(const ArticleScene& scene, const std::function<void(double)>& progress = {});

/// The sampling loop every time run shares: steps `integrator` to each sample time of
/// `spec`, asks `sample` for the row (realized to Acceleration), refuses a non-finite
/// value (NumericalError), and keeps the energy books of `r` (work of the prescribed
/// motions plus `input_power`'s, and `dissipation` power, trapezoidal), its steps and
/// evaluations.
class RunIntegrator;
void recordRun(const SimTK::MultibodySystem& sys, RunIntegrator& integrator, const SimulationSpec& spec,
               SimulationResult& r, const std::function<void(double)>& progress,
               const std::function<double(const SimTK::State&)>& input_power,
               const std::function<double(const SimTK::State&)>& dissipation,
               const std::function<std::vector<double>(double, const SimTK::State&)>& sample);

/// A warning when a closed tree's constraint drift exceeds 1e-6 of the article's size
/// (`size_m`). Empty if fine or open.
std::string constraintDriftWarning(const SimulationResult& r, double size_m);

/// The energy scale a balance error is judged against: the largest of the peak kinetic
/// energy, |work of the motions| and the dissipation (potential energy has no natural
/// zero), and no less than the run's relative accuracy (at least 1e-8) times the stored
/// energy |E|: the integrator holds the coordinates to that relative accuracy, and so
/// the potential energy, so below it a balance is integration noise and round-off (a
/// run in which nothing moves is not flagged: the closed article held 10 s by CPodes at
/// 1e-6 drifts 8e-8 J of its 157 J). 0 only when E = 0 and nothing moved.
double energyScale(const SimulationResult& r);

/// A warning when the largest |energy balance error| at any sample exceeds 1 % of
/// energyScale(r): the run is not accurate enough to trust (loosen no further; tighten
/// the accuracy or, for a trapezoidal slew, raise the sample rate the balance is
/// integrated at). Empty if fine.
std::string energyBalanceWarning(const SimulationResult& r);

}  // namespace mmv
