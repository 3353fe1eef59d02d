#pragma once
/// Linear models for control design, from the linearization at an equilibrium.
///
/// Second-order form over the admissible coordinates (closed loops: q = Z eta):
///     M q'' + C q' + K q = B_q u,    y = C_d q + C_v q' + C_a q'' + D_base u
/// First-order descriptor form with x = [q; q']:
///     E x' = A x + B u,   y = C x + D u,
///     E = [I 0; 0 M],  A = [0 I; -K -C],  B = [0; B_q],
/// acceleration outputs eliminated with q'' = M^-1 (B_q u - C q' - K q).
///
/// Inputs (units): base acceleration of the table in x or y (m/s^2), entering as the
/// inertial load -M_qb b'' with M_qb = sum_b J_b^T m_b e (the mass coupling of a rigid
/// base translation); torque at a joint that is a degree of freedom (N*m); force at a
/// named point along x, y or z (N); a moment at a named point about x, y or z (N*m:
/// J_w^T m). Outputs: displacement (m), velocity (m/s) or acceleration (m/s^2) of a
/// named point along x, y or z, or its rotation (rad, rad/s, rad/s^2) about x, y or z
/// (z and the rotations out of the plane on the spatial model), relative to the base or absolute
/// (absolute adds the base motion: for an acceleration output, D gains the base
/// acceleration input itself). Absolute acceleration over base acceleration is the
/// transmissibility.
///
/// Damping (DampingSpec, sim/scene/scene.hpp): modal ratios (C = M Phi diag(2 zeta omega)
/// Phi^T M), Rayleigh (C = alpha M + beta K), or the hinges' viscous dampers
/// (C = diag(hinge_beta * k) over the hinge coordinates), the last being the same
/// damping the Simbody model carries in time runs.

#include <Eigen/Dense>
#include <array>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "sim/modes/system_modes.hpp"

namespace mmv {

enum class InputKind { BaseAcceleration, JointTorque, PointForce, PointMoment };
enum class OutputKind { Displacement, Velocity, Acceleration };

struct InputSpec {
  std::string name;
  InputKind kind = InputKind::BaseAcceleration;
  std::string target;  ///< joint (torque) or point (force, moment); unused for the base.
  /// 0, 1, 2: along world x, y, z (base and force); 3, 4, 5: about world x, y, z (moment);
  /// -1: a force along `direction` (the scene's shaker, `--input shaker`).
  int axis = 0;
  std::array<double, 3> direction{};  ///< unit, world (axis -1)
  /// kg moving with the point along `direction` (the shaker's armature through its
  /// stinger): the model's mass gains m b b^T, b this input's generalized force.
  double armature_kg = 0;
};

/// Axes 3..5 of inputs and outputs are rotations about world x, y, z.
inline bool isRotationAxis(int axis) { return axis >= 3; }
/// The axes' names as the command line and the UFF mapping write them: x, y, z, rx, ry, rz.
inline const char* axisName(int axis) {
  static const char* const kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
  return kNames[axis];
}
/// Whether `axis` leaves the plane of motion: z, and the rotations about x and y.
inline bool leavesThePlane(int axis) { return axis == 2 || axis == 3 || axis == 4; }

struct OutputSpec {
  std::string name;
  OutputKind kind = OutputKind::Displacement;
  std::string point;
  /// 0, 1, 2: translation along world x, y, z (m, m/s, m/s^2); 3, 4, 5: rotation about
  /// world x, y, z (rad, rad/s, rad/s^2: the point's body's, or a station's interpolated).
  int axis = 0;
  bool absolute = false;  ///< add the base's own motion (the base translates only).
  /// A bending strain gauge or piezo film over a span of one link (`strain:A:B[:in|out]`):
  /// its mean surface strain (m/m) on the section's +y face (local y, in the plane),
  ///     eps = -c (theta_B - theta_A) / (x_B - x_A),
  /// the mean curvature between two stations times the distance c of the face from the
  /// neutral axis (compression where the link bends towards +y); out of the plane (the
  /// spatial model) on the +z face, eps = +c (phi_B - phi_A) / (x_B - x_A), phi about
  /// local y (sim/model/stations.hpp strainRow). `point` is station A, `span_end`
  /// station B; kind Displacement, axis 5.
  std::string span_end = {};
  double surface_m = 0;  ///< c: the section's half depth (in the plane) or half width (out of it), or its radius.
  double span_m = 0;     ///< x_B - x_A along the link (nonzero).
  bool out_of_plane = false;
  bool isStrain() const { return !span_end.empty(); }
  /// A bending stress at a station of a link (`stress:STATION[:face]`, Pa): the moment
  /// its hinges' springs carry there (interpolated, sim/statics/link_stress.hpp
  /// bendingStressRow) on `stress_face` (+y, the default, -y, +z, -z); `point` is the
  /// station, `stress_link` and `stress_x_m` where it lies. Kind Displacement, axis 5.
  std::string stress_face = {};
  std::string stress_link = {};
  double stress_x_m = 0;
  bool isStress() const { return !stress_face.empty(); }
};


/// A descriptor state-space model with names and units.
struct StateSpace {
  Eigen::MatrixXd E, A, B, C, D;
  std::vector<std::string> input_names, input_units, output_names, output_units, state_names;
  /// Frequency response at s = i omega: C (s E - A)^-1 B + D (outputs x inputs).
  Eigen::MatrixXcd response(double omega) const;
  /// The same with E = I (A := E^-1 A, B := E^-1 B), for ss(A, B, C, D).
  StateSpace standardForm() const;
  /// Eigenvalues of the pencil (A, E), rad/s.
  Eigen::VectorXcd poles() const;
  int numStates() const { return static_cast<int>(A.rows()); }
};

/// A state-space model's responses at many frequencies for O(N^2) each, not the O(N^3)
/// of StateSpace::response's LU: E^-1 A balanced and reduced once to Hessenberg form
/// (Q H Q^T, Householder), each frequency solving (i w I - H) z = Q^T D^-1 E^-1 B by
/// elimination between adjacent rows (sim/linear/hessenberg.hpp). Used only after it
/// reproduces the LU to 1e-10 of the largest response at the check frequencies given;
/// otherwise (or when E is singular to working precision) every frequency takes the LU.
/// It keeps a reference to `s`, which must outlive it.
class StateSpaceResponses {
 public:
  StateSpaceResponses(const StateSpace& s, const std::vector<double>& check_omegas);
  /// C (i w E - A)^-1 B + D, as StateSpace::response.
  Eigen::MatrixXcd at(double omega) const;
  bool hessenberg() const { return hessenberg_; }

 private:
  const StateSpace& s_;
  bool hessenberg_ = false;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> H_;
  Eigen::MatrixXd Bh_, Ch_;
};

/// First-order descriptor model of M q'' + C q' + K q = Bq u with outputs
/// y = Cd q + Cv q' + Ca q'' + Dextra u (acceleration rows eliminated with M^-1).
/// Any of Cd, Cv, Ca may be empty (zero). M must be invertible.
StateSpace secondOrderModel(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K,
                            const Eigen::MatrixXd& Bq, const Eigen::MatrixXd& Cd, const Eigen::MatrixXd& Cv,
                            const Eigen::MatrixXd& Ca, const Eigen::MatrixXd& Dextra);

/// The full model's frequency response, at a cost per frequency that grows as the
/// square of its size, not the cube. After prepare():
///  - proportional damping (the real modes Phi of K and M, Phi^T M Phi = I, also
///    diagonalise C to 1e-10: modal and Rayleigh damping): a sum over the modes,
///        H(w) = (Cd + i w Cv - w^2 Ca) Phi diag(1 / (w_k^2 - w^2 + i w c_k)) Phi^T Bq + D,
///    O(n) per input-output pair;
///  - any other damping (the hinge dampers under gravity's geometric stiffness are not
///    proportional): the first-order matrix A1 = [0 I; -M^-1 K  -M^-1 C] (N = 2n) is
///    reduced once to Hessenberg form, A1 = Q H Q^T (Householder, backward stable;
///    Laub, IEEE TAC 26(2), 1981), and each response solves (i w I - H) z = Q^T [0; M^-1 Bq]
///    by Gaussian elimination with partial pivoting between adjacent rows, O(N^2), then
///    q = Q_q z. No eigenvectors, so no ill-conditioned basis to check.
/// Before prepare() (or for an empty model) each response is an n x n complex LU.
struct SecondOrderResponse {
  Eigen::MatrixXd M, C, K, Bq, Cd, Cv, Ca, D;
  Eigen::MatrixXcd response(double omega) const;
  /// Chooses the path once (one symmetric eigen solution, or one Hessenberg
  /// reduction); call after filling.
  void prepare();
  /// Damping defined over the modes (C = M Phi diag(c) Phi^T M, Phi^T M Phi = I): the
  /// modal path is exact by construction, so prepare() takes this basis as it is rather
  /// than solving again and testing Phi^T C Phi for diagonality, a test whose round-off
  /// grows with the model (6e-9 of the diagonal at 64 segments per link, above the
  /// 1e-10 it needs) and sent the default scene's frf to the Hessenberg path.
  void setModalBasis(Eigen::VectorXd omega2, Eigen::MatrixXd shapes, Eigen::VectorXd c);
  bool modal() const { return modal_; }
  bool hessenberg() const { return hessenberg_; }

 private:
  void prepareHessenberg();
  Eigen::MatrixXcd hessenbergResponse(double w) const;
  bool modal_ = false, hessenberg_ = false;
  Eigen::VectorXd w2_, c_;                   ///< per mode: omega_k^2, Phi^T C Phi diagonal.
  Eigen::MatrixXd P_, Od_, Ov_, Oa_;         ///< Phi^T Bq; Cd Phi, Cv Phi, Ca Phi.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> H_;  ///< Hessenberg, rows contiguous.
  Eigen::MatrixXd Bh_;                       ///< Q^T D^-1 [0; M^-1 Bq].
  Eigen::MatrixXd Qq_, Rv_;                  ///< (D Q)_q; (Q^T D^-1)_v M^-1 (the refinement step).
  Eigen::MatrixXd C1q_, C1v_, D1_;           ///< outputs on the state (y = C1 [q; v] + D1).
  Eigen::MatrixXd C1qQq_, C1vQq_;            ///< C1_q (D Q)_q, C1_v (D Q)_q (the correction's outputs).
  bool c_diagonal_ = false;
  Eigen::MatrixXd basis_;  ///< setModalBasis' shapes, until prepare().
};

/// Undamped modes of a model's M and K that also diagonalise its C: Phi^T M Phi = I,
/// Phi^T K Phi = diag(omega2), Phi^T C Phi = diag(c) (modal and Rayleigh damping, whose
/// C is built from them). Each gives the state matrix's modes in closed form,
/// lambda^2 + c lambda + omega^2 = 0 with the right vector [phi; lambda phi].
struct ProportionalModes {
  Eigen::VectorXd omega2, c;
  Eigen::MatrixXd shapes;
};

/// How many undamped modes a linear model carries (LinearModel::solved.modes): the
/// shapes written with its responses.
inline constexpr int kLinearModelModes = 12;

/// A solved scene with its linear model.
struct LinearModel {
  SolvedScene solved;
  Eigen::MatrixXd Mz, Kz, Cz, Bq;  ///< second-order matrices over the admissible coordinates.
  Eigen::MatrixXd Z;               ///< coordinates = Z eta (identity for an open tree).
  StateSpace full;
  SecondOrderResponse second_order;  ///< the same model, for fast full-model FRFs.
  std::vector<InputSpec> inputs;
  std::vector<OutputSpec> outputs;
  DampingSpec damping;  ///< what Cz was built from.
  std::shared_ptr<const ProportionalModes> proportional;  ///< proportional damping only: Mz, Cz, Kz's modes.
};

/// Builds the linear model. Throws SceneError for an input or output naming an
/// unknown point or joint, or a torque on a locked joint (it has no DOF). Without
/// `prepare_responses` the caller runs second_order.prepare() (e.g. beside other work).
LinearModel buildLinearModel(const ArticleScene& scene, const std::vector<InputSpec>& inputs,
                             const std::vector<OutputSpec>& outputs, const DampingSpec& damping,
                             bool prepare_responses = true);

/// Defaults when a command names none: base acceleration in x and y; absolute
/// acceleration in x and y of every link tip.
std::vector<InputSpec> defaultInputs();
std::vector<OutputSpec> defaultOutputs(const ArticleScene& scene);

struct ReductionOptions {
  int modes = 0;  ///< keep the lowest `modes` oscillatory modes, plus any real (overdamped)
                 ///< root no faster than them (0: use the band).
  double band_min_hz = 0, band_max_hz = 0;  ///< keep modes with |lambda|/2pi in the band.
  bool residualize = true;           ///< add the discarded modes' static contribution to D.
  /// Skip modes no input-output pair sees (residue ||C v|| ||w B|| / |lambda| below 1e-9
  /// of the largest): symmetric structures have many (an isolator's leg torsion).
  bool drop_unseen = false;
  /// Automatic: only the lowest modes (shift-invert Arnoldi, O(n^2) per step) when a
  /// count is kept and nothing is dropped, falling back to every mode (the dense
  /// solver, O(n^3)) when that does not apply or a check fails. Dense and Lowest force
  /// one (Lowest throws NumericalError where it does not apply): for tests.
  enum class Solver { Automatic, Dense, Lowest } solver = Solver::Automatic;
  /// The model's proportional modes when its damping is (LinearModel::proportional):
  /// Automatic then takes the state matrix's modes from them, no eigen solution, after
  /// checking they solve the model's M, C and K (else as without).
  std::shared_ptr<const ProportionalModes> proportional = {};
};

struct ReducedModel {
  StateSpace model;
  int kept_modes = 0;
  int unseen_modes = 0;  ///< of the discarded, those no input-output pair sees (drop_unseen).
  bool residualized = false;
  bool every_mode_computed = true;  ///< false: only the lowest modes were (ReductionOptions::Solver).
  std::vector<double> kept_frequencies_hz;
  std::vector<double> kept_damping;  ///< damping ratio of each kept mode (-Re lambda / |lambda|; 1 for a real root)
};

/// Modal reduction of a first-order model (the HAM-SAS authors' method, docs/sources.md section 3): right and left
/// eigenvectors of (A, E), complex pairs split into real and imaginary parts, kept
/// modes projected (Petrov-Galerkin), giving descriptor form; with `residualize` the
/// discarded modes' static response H_full(0) - H_kept(0) is added to D, so every DC
/// gain is exact. Throws NumericalError when A is singular and residualization asked.
ReducedModel reduceModal(const StateSpace& full, const ReductionOptions& options);

/// Largest |H_a(i w) - H_b(i w)| over the grid, per input-output pair, relative to the
/// largest |H_a| of that pair (or to 1e-9 of the largest |H_a| of any pair in the same
/// units, for a pair that is zero up to round-off); and the overall maximum. Also the local error: the
/// largest |H_a - H_b| / |H_a| at one frequency (|H_a| no smaller than that 1e-9 floor),
/// with the frequency where it occurs: near an antiresonance or down a roll-off a model
/// within 0.3 % of the peak can be off by 100 % of the response there.
struct ModelError {
  Eigen::MatrixXd relative;  ///< outputs x inputs.
  /// outputs x inputs: the full response stays below the 1e-9 floor over the grid (zero
  /// up to round-off, e.g. an in-plane input to an out-of-plane output of the symmetric
  /// spatial article); such a pair counts no error.
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> zero;
  double max_relative = 0;
  /// The fewest kept modes whose reduced model's max_relative meets `target`
  /// (modesForTarget): `modes` and its error; reached = false when even `modes` (the
  /// most tried) does not.
  struct ModesNeeded {
    bool computed = false, reached = false;
    double target = 0, error = 0;
    int modes = 0;
  } needed;
  Eigen::MatrixXd local, local_hz;  ///< outputs x inputs: worst local error, and where (Hz).
  double max_local = 0, max_local_hz = 0;
  std::pair<Eigen::Index, Eigen::Index> max_local_pair{0, 0};  ///< (output, input).
};
ModelError compareResponses(const StateSpace& a, const StateSpace& b, const std::vector<double>& omegas);
/// The same with the full model in second-order form (the reduced one, b, in first order).
ModelError compareResponses(const SecondOrderResponse& a, const StateSpace& b, const std::vector<double>& omegas);
/// The same with the full model's responses at `omegas` already computed (fullResponses).
ModelError compareResponses(const std::vector<Eigen::MatrixXcd>& a, const StateSpace& b, const std::vector<double>& omegas);
/// The full model's response at each frequency (rad/s), computed once for every use.
std::vector<Eigen::MatrixXcd> fullResponses(const SecondOrderResponse& h, const std::vector<double>& omegas);

/// The fewest modes a reduced model of `full` needs for its largest FRF error relative
/// to each pair's peak (compareResponses' max_relative against `full_responses`, the
/// full model at `omegas`) to be at most `target`: reductions with `base`'s options and
/// 1..max_modes modes, searched from base.modes by doubling, then bisection (the error
/// falls as modes are added; the test checks the answer against a scan). Fills err.needed.
void modesForTarget(const StateSpace& full, const ReductionOptions& base,
                    const std::vector<Eigen::MatrixXcd>& full_responses, const std::vector<double>& omegas,
                    double target, int max_modes, ModelError& err);


/// The HAM-SAS authors' cross-check (docs/sources.md section 3): eigenvalues of an implicit integrator's Jacobian
/// J(c) = E - c A (F = E y' - A y, dCoef = c) from the pencil J(-c) v = Lambda J(c) v,
/// mapped back by lambda = (1/c) (Lambda - 1) / (Lambda + 1). Throws NumericalError if
/// J(c) is singular.
Eigen::VectorXcd polesFromIntegratorJacobian(const StateSpace& m, double dcoef);

/// Log-spaced frequencies (Hz) from f0 to f1, n points.
std::vector<double> logFrequencies(double f0_hz, double f1_hz, int n);

/// `grid` with points added around every lightly damped mode inside it (0 < zeta < 0.5),
/// so the grid resolves each resonance's half-power band f_n (1 +- zeta): 2 k + 1
/// points evenly over f_n (1 +- 2 zeta) (k = `per_half_band`), and the peak
/// f_n sqrt(1 - 2 zeta^2). A log grid of 400 points over 0.1-100 Hz is 1.7 % apart, wider
/// than the 1.6 % band of a mode at 0.8 % damping. Sorted, without near-duplicates
/// (1e-9 relative). An undamped mode (zeta = 0) gets no points: its response there is infinite.
std::vector<double> resolveResonances(const std::vector<double>& grid, const std::vector<double>& fn_hz,
                                      const std::vector<double>& zeta, int per_half_band = 4);

/// The peak of every |H(o, i)| (frequency in Hz, magnitude, outputs x inputs): the
/// largest grid point of f, refined between its neighbours by Brent's search (parabolic
/// and golden-section steps, to 1e-9 of the frequency) so a coarse grid does not
/// misplace a lightly damped peak. One response per grid point serves every pair; the
/// search costs one response per step (about 12 on a resonance), the pairs in parallel.
struct PeakTable {
  Eigen::MatrixXd hz, magnitude;
  /// The peak's half-power damping (f2 - f1) / (2 f_peak), f1 and f2 where |H| falls to
  /// peak / sqrt(2) on either side (found on the grid, then by bisection on the
  /// response); zeta to O(zeta^3) for a lightly damped, well-separated mode. -1 when
  /// either point is outside the grid (a peak at its edge, or a mode too heavily
  /// damped or too close to another to fall to half power between them).
  Eigen::MatrixXd half_power_damping;
};
/// `grid`: h's responses at f (fullResponses of 2 pi f), or empty to compute them.
PeakTable refinedPeaks(const SecondOrderResponse& h, const std::vector<double>& f,
                       const std::vector<Eigen::MatrixXcd>& grid = {});

}  // namespace mmv
