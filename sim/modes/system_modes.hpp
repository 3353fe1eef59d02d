#pragma once
/// The `modes` analysis: build the scene's model, solve its static equilibrium with
/// the torquers holding, linearize there and solve the system modes; then describe
/// each mode the way a test engineer reads it. Results are plain data for the writers.
///
/// Per mode:
///  - kinetic and strain energy shares per part (link, torquer, tip mass): kinetic
///    from each body's mass centre velocity and spin in the shape, strain from the
///    springs (hinges of a link; a servo joint counts as its joint);
///  - the same shares per link, each link counted with the lumped masses it carries
///    (its tip mass, the torquers at its tip): "which link carries the mode";
///  - the preload's share of the modal stiffness, phi^T K_geometric phi / omega^2
///    (gravity, loads and closure forces; negative when the preload softens);
///  - effective modal masses for base translation in x and y, L^2 with
///    L = sum_b m_b (J_b phi) . e (the mass a base shaker "sees" in that mode; they add
///    up over all modes to the mass that moves relative to the base);
///  - the modal mass for the shape scaled to 1 m at its largest translation (kg);
///  - the shape at named points (translations, and rotations where meaningful);
///  - on the spatial model, the mode's family (in-plane, out-of-plane, torsion, mixed)
///    and the report's planarity section (sim/modes/planarity.hpp).

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sim/model/model.hpp"
#include "sim/modes/modal.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/modes/converge.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/link_stress.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {

struct PartShare {
  std::string part;
  double fraction = 0;  ///< 0..1.
};

struct PointMotion {
  std::string point;
  /// Translation per unit modal coordinate of the mass-normalised shape (phi^T M phi = 1):
  /// kg^-1/2, not metres.
  double ux = 0, uy = 0;
  double uz = 0;          ///< the same, out of the plane (spatial model only).
  double rz = 0;          ///< rad per unit modal coordinate (when has_rotation).
  bool has_rotation = false;
};

/// A strain gauge's or film's span (ModesOptions::strains): its two stations, the face's
/// distance c from the neutral axis and the span x_B - x_A (sim/scene/stations.hpp).
struct StrainGaugeSpec {
  std::string name;  ///< "A:B", as asked for
  std::string a, b;
  double surface_m = 0, span_m = 0;
  bool out_of_plane = false;  ///< the +z face's strain (spatial model), not the +y face's
};
/// A mode's mean surface strain over a span, -c (theta_B - theta_A) / span per unit modal
/// coordinate of the mass-normalised shape (kg^-1/2; frf's strain output, mode by mode).
struct ModalStrain {
  std::string span;
  double strain = 0;
};

/// A link's peak stress in a mode, per mm of the mode's peak translation.
struct ModalLinkStress {
  std::string link;
  bool recovered = false;  ///< else why_not (a rigid link, no fibre distance).
  std::string why_not;
  double x_m = 0;          ///< where on the link (m from its root).
  std::string face;
  double equivalent_pa_per_mm = 0, moment_nm_per_mm = 0;
};

struct ModeInfo {
  ModeNumber number;
  double omega2 = 0;  ///< rad^2/s^2.
  double frequency_hz = 0;  ///< meaningful when stable; 0 for a rigid-body mode.
  bool stable = true;
  bool rigid_body = false;  ///< zero frequency up to round-off (a mechanism).
  double modal_mass_kg = 0;  ///< for the shape scaled to 1 m at peak_point.
  std::string peak_point;
  double effective_mass_x_kg = 0, effective_mass_y_kg = 0;
  double effective_mass_z_kg = 0;  ///< spatial model only.
  /// Spatial model: the strain energy's split over in-plane, out-of-plane and torsion
  /// (sim/modes/planarity.hpp); empty label in the planar model.
  ModeFamily family;
  double geometric_stiffness_share = 0;
  /// Under the scene's damping (ModesReport::damped): the ratio to critical (1:
  /// overdamped) and |lambda| / 2 pi of the damped mode (sim/modes/damping.hpp).
  double damping_ratio = 0, damped_natural_hz = 0;
  bool has_damping = false;  ///< the ratio was computed (the lowest kMaxDampingBasis / 2 modes at most).
  std::vector<PartShare> kinetic, strain;  ///< per part, sorted, largest first.
  std::vector<PartShare> kinetic_by_link, strain_by_link;  ///< per carrying link, sorted.
  std::string dominant_link_kinetic, dominant_link_strain;  ///< first of the *_by_link lists.
  std::vector<PointMotion> shape;
  /// The shape at the points and stations of ModesOptions::points, in that order.
  std::vector<PointMotion> at_points;
  std::vector<ModalStrain> strains;  ///< ModesOptions::strains'
  /// Each link's peak bending stress in this mode per mm of its peak translation (at
  /// peak_point): the stress a test level of that amplitude puts in the link (Pa/mm,
  /// scene link order; docs/strength.md).
  std::vector<ModalLinkStress> stress_per_mm;
};

struct JointReport {
  std::string name;
  std::string hold;  ///< locked, free, servo.
  double commanded_rad = 0, equilibrium_rad = 0;
  double torque_nm = 0;  ///< torque the torquer applies to its child (ccw +).
};

struct ClosureReport {
  std::string name;
  double fx = 0, fy = 0;  ///< N, force the closure applies to the article's point, world frame.
  double fz = 0;          ///< N, out of the plane (0 in the planar model).
  double error_m = 0;     ///< largest |Phi| of its rows at the equilibrium.
};

struct PointReport {
  std::string name;
  double x = 0, y = 0;    ///< m, deflected equilibrium, world frame.
  double dx = 0, dy = 0;  ///< m, deflection: equilibrium minus the unbent shape.
  double z = 0, dz = 0;   ///< m, out of the plane (0 in the planar model).
};

struct ModelSummary {
  int num_links = 0, num_bodies = 0, num_coordinates = 0, num_dofs = 0;
  double total_mass_kg = 0, moving_mass_kg = 0;
  std::vector<std::pair<std::string, int>> link_segments;  ///< 0 for rigid.
  /// A spatial article's links that bend in their plane only (`model: planar` of their own).
  std::set<std::string> planar_links;
};

struct ModesReport {
  std::string scene_name, scene_source;
  std::array<double, 3> gravity{};
  ModelSummary model;
  bool equilibrium_converged = false;
  int equilibrium_iterations = 0;
  double equilibrium_residual_nm = 0, force_scale_nm = 0;
  std::vector<JointReport> joints;
  std::vector<ClosureReport> closures;
  std::vector<PointReport> points;
  std::vector<ModeInfo> modes;
  /// The static stress at the equilibrium, per link in scene order (docs/strength.md),
  /// judged with `strength`.
  std::vector<LinkStaticStress> static_stress;
  StrengthFactors strength;
  /// The scene's damping (ModesOptions::damping): its description, and the real modes
  /// the damped eigenproblem was solved over (all of them: exact).
  bool damped = false;
  std::string damping_model = "none";
  int damping_basis_modes = 0;
  bool damping_exact = false;
  /// Over the modes reported: max relative residual ||K v - w^2 M v|| / (||K v|| + w^2 ||M v||)
  /// and max |V^T M V - I|.
  double eigen_residual = 0, orthogonality_error = 0, stiffness_asymmetry = 0;
  /// Checks that failed (an eigen residual above 1e-6 of a reported mode), for the user.
  std::vector<std::string> warnings;
  double seconds_build = 0, seconds_equilibrium = 0, seconds_linearize = 0, seconds_eigen = 0;
  /// Each mode's discretization error (estimateDiscretization, sim/modes/converge.hpp),
  /// when asked for; `modes` by default.
  DiscretizationEstimate discretization;
  /// `modes --target-error`: how the segments per link were chosen (segmentsForTarget).
  std::optional<SegmentsChoice> segments_choice;
  /// The spatial model (`model: spatial`): the planarity report over the 0.1-50 Hz band.
  bool spatial = false;
  std::optional<PlanarityReport> planarity;
};

/// The frequencies of a report's modes as solveSceneModes gives them (negative: unstable).
std::vector<double> reportFrequencies(const ModesReport& r);

struct ModesOptions {
  int max_modes = 0;        ///< 0: all.
  bool with_shapes = true;  ///< fill ModeInfo::shape.
  /// Named points or stations (sim/scene/stations.hpp) whose translation each mode
  /// reports in ModeInfo::at_points; each must name a point of the scene (the CLI
  /// checks them first; here an unknown one is a SceneError).
  std::vector<std::string> points;
  EquilibriumOptions equilibrium;
  /// The damping each mode's ratio is computed under (none: undamped, no ratios). On a
  /// model large enough for the partial eigen solver, twice the modes reported (at
  /// least 20 more) are solved for, the basis of the damped eigenproblem.
  std::optional<DampingSpec> damping;
  /// Strain spans (checked: sim/scene/stations.hpp strainSpan) whose modal strain each
  /// mode reports in ModeInfo::strains.
  std::vector<StrainGaugeSpec> strains;
};

/// Runs the analysis. Throws NumericalError if the equilibrium does not converge or
/// the eigenproblem is ill-posed.
ModesReport runModes(const ArticleScene& scene, const ModesOptions& options = {});

/// The solved full model: model, equilibrium, linearization and modes.
struct SolvedScene {
  std::unique_ptr<Model> model;
  EquilibriumResult equilibrium;
  LinearizedModel linearized;
  ModalSolution modes;
  double seconds_build = 0, seconds_equilibrium = 0, seconds_linearize = 0, seconds_eigen = 0;
};
/// num_modes = 0: every mode; > 0: at least the lowest num_modes (solveModes: on large
/// models only those, by shift-invert Lanczos).
/// `operators`: a large open tree keeps M and K as O(n) operators (linearizeOperators,
/// sim/statics/linearize.hpp), for callers that read them only through massTimes,
/// stiffnessTimes and springDiagonal.
/// Throws NumericalError if the equilibrium fails or the eigenproblem is ill-posed.
SolvedScene solveScene(const ArticleScene& scene, const EquilibriumOptions& eq = {}, int num_modes = 0,
                       bool operators = false);

/// solveModes on whichever form `lin` holds (dense matrices with their closure basis,
/// or an open tree's operators).
ModalSolution solveModes(const LinearizedModel& lin, int count);

/// Flags the rigid-body modes of `sol` (shapes over lin.dofs) from the model's
/// structure: the admissible motions that bend no hinge and stretch no servo spring
/// (free joints) on which gravity, loads and closure forces exert no stiffness
/// (modal.hpp, markRigidBodyModes, with the scale |g| / L of the scene's pendulums).
void markRigidBodyModes(ModalSolution& sol, const LinearizedModel& lin, const ArticleScene& scene);

/// Translations of every named point per unit DOF motion at state s, d rows per point
/// (x, y; and z on the spatial model: d = 3), columns over `dofs`. P * phi is a shape
/// as a test sees it.
Eigen::MatrixXd pointTranslationMatrix(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

/// The link with the largest share of the strain energy of shape phi (over the
/// model's DOFs), with lumped parts counted with their link; "" if none strains.
std::string dominantStrainLink(const Model& model, const std::vector<int>& dofs, const Eigen::VectorXd& phi);

/// Frequencies only (Hz, negative for unstable shapes), the cheap path for sweeps.
struct ModesSolve {
  Eigen::VectorXd frequencies_hz;
  int num_dofs = 0;
};
/// num_modes as in solveScene: at least that many frequencies (0: all).
ModesSolve solveSceneModes(const ArticleScene& scene, const EquilibriumOptions& eq = {}, int num_modes = 0);

}  // namespace mmv
