#include "sim/modes/system_modes.hpp"
#include "sim/modes/damping.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/model/stations.hpp"
#include "sim/statics/closures.hpp"

namespace mmv {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const char* holdName(JointHold h) {
  switch (h) {
    case JointHold::Locked: return "locked";
    case JointHold::Free: return "free";
    case JointHold::Servo: return "servo";
  }
  return "?";
}

std::vector<PartShare> sortedShares(const std::map<std::string, double>& energy) {
  double total = 0;
  for (const auto& [p, e] : energy) total += e;
  std::vector<PartShare> out;
  for (const auto& [p, e] : energy) out.push_back({p, total > 0 ? e / total : 0.0});
  std::sort(out.begin(), out.end(), [](const PartShare& a, const PartShare& b) { return a.fraction > b.fraction; });
  return out;
}

/// Energies per part regrouped by the link that carries each part.
std::map<std::string, double> byCarrier(const std::map<std::string, double>& energy, const Model& model) {
  std::map<std::string, double> out;
  for (const auto& [name, e] : energy) {
    std::string carrier = name;  // a servo joint's strain stays under the joint's name
    for (const auto& p : model.getParts())
      if (p.name == name && !p.carrier.empty()) carrier = p.carrier;
    out[carrier] += e;
  }
  return out;
}

}  // namespace

ModalSolution solveModes(const LinearizedModel& lin, int count) {
  return lin.tree ? solveModes(*lin.tree, count) : solveModes(lin.M, lin.K, lin.Z, count);
}

SolvedScene solveScene(const ArticleScene& scene, const EquilibriumOptions& eq_opts, int num_modes, bool operators) {
  SolvedScene s;
  auto t0 = Clock::now();
  {
    const ProgressStage stage("assembling the model");
    s.model = buildArticleModel(scene);
  }
  s.seconds_build = secondsSince(t0);
  t0 = Clock::now();
  {
    const ProgressStage stage(strf("static equilibrium (%zu DOF)", s.model->getDofs().size()));
    s.equilibrium = solveEquilibrium(*s.model, eq_opts);
  }
  s.seconds_equilibrium = secondsSince(t0);
  if (!s.equilibrium.converged) throw NumericalError("static equilibrium failed: " + s.equilibrium.failure);
  t0 = Clock::now();
  {
    const ProgressStage stage(strf("linearizing: mass and stiffness matrices (%zu DOF)", s.model->getDofs().size()));
    s.linearized = operators ? linearizeOperators(*s.model, s.equilibrium.state, s.equilibrium.closure_multipliers)
                             : linearize(*s.model, s.equilibrium.state, s.equilibrium.closure_multipliers);
  }
  s.seconds_linearize = secondsSince(t0);
  t0 = Clock::now();
  const ProgressStage stage(strf("eigen-solution: %d modes of %zu DOF", num_modes, s.linearized.dofs.size()));
  s.modes = solveModes(s.linearized, num_modes);
  markRigidBodyModes(s.modes, s.linearized, scene);
  s.seconds_eigen = secondsSince(t0);
  return s;
}

void markRigidBodyModes(ModalSolution& sol, const LinearizedModel& lin, const ArticleScene& scene) {
  const Eigen::VectorXd springs = springDiagonal(lin);
  double length = 0;
  for (const auto& l : scene.article.links) length += l.length;
  const double g = std::hypot(std::hypot(scene.gravity[0], scene.gravity[1]), scene.gravity[2]);
  const double scale = length > 0 ? g / length : 0.0;
  std::vector<bool> strained(lin.dofs.size());
  for (std::size_t i = 0; i < lin.dofs.size(); ++i) strained[i] = springs[i] != 0.0;
  const Eigen::MatrixXd U = lin.tree ? unstrainedCoordinates(strained) : unstrainedMotions(lin.Z, strained);
  markRigidBodyModesOn(sol, U.transpose() * stiffnessTimes(lin, U), U.transpose() * massTimes(lin, U), scale);
}

Eigen::MatrixXd pointTranslationMatrix(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  std::vector<SimTK::MobilizedBodyIndex> ix;
  std::vector<SimTK::Vec3> st;
  for (const auto& p : model.getPoints()) {
    ix.push_back(p.mobod);
    st.push_back(p.station_B);
  }
  const Eigen::MatrixXd J = model.calcFrameJacobians(s, ix, st, dofs);
  const int d = model.isSpatial() ? 3 : 2;
  Eigen::MatrixXd P(d * ix.size(), dofs.size());
  for (std::size_t p = 0; p < ix.size(); ++p) P.middleRows(d * p, d) = J.middleRows(6 * p + 3, d);
  return P;
}

std::string dominantStrainLink(const Model& model, const std::vector<int>& dofs, const Eigen::VectorXd& phi) {
  std::map<std::string, double> strain;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const Coordinate& c = model.getCoordinates()[dofs[k]];
    if (c.stiffness > 0) strain[c.part] += 0.5 * c.stiffness * phi[k] * phi[k];
  }
  const auto shares = sortedShares(byCarrier(strain, model));
  return shares.empty() ? std::string() : shares.front().part;
}

ModesSolve solveSceneModes(const ArticleScene& scene, const EquilibriumOptions& eq, int num_modes) {
  const SolvedScene s = solveScene(scene, eq, num_modes, true);
  ModesSolve out;
  out.num_dofs = static_cast<int>(s.linearized.dofs.size());
  out.frequencies_hz.resize(s.modes.omega2.size());
  for (Eigen::Index i = 0; i < s.modes.omega2.size(); ++i) out.frequencies_hz[i] = s.modes.frequencyHz(static_cast<int>(i));
  return out;
}

namespace {

ModelSummary summarizeModel(const ArticleScene& scene, const Model& model, std::size_t num_dofs) {
  ModelSummary m;
  m.num_links = static_cast<int>(scene.article.links.size());
  m.num_bodies = static_cast<int>(model.getBodies().size());
  m.num_coordinates = model.getNumCoordinates();
  m.num_dofs = static_cast<int>(num_dofs);
  m.total_mass_kg = model.getTotalMass();
  m.moving_mass_kg = model.getMovingMass();
  for (const auto& l : scene.article.links) {
    m.link_segments.push_back({l.name, l.rigid ? 0 : l.segments});
    if (scene.article.model == ArticleModel::Spatial && !scene.article.bendsOutOfPlane(l)) m.planar_links.insert(l.name);
  }
  return m;
}

/// The torque each torquer holds at the equilibrium (ccw +, on the child).
std::vector<JointReport> jointReports(const ArticleScene& scene, const Model& model, const EquilibriumResult& eq) {
  const auto& coords = model.getCoordinates();
  std::vector<JointReport> out;
  for (const auto& j : scene.article.joints) {
    JointReport jr;
    jr.name = j.name;
    jr.hold = holdName(j.hold);
    jr.commanded_rad = j.angle;
    for (std::size_t c = 0; c < coords.size(); ++c) {
      if (coords[c].kind != CoordinateKind::Joint || coords[c].name != j.name) continue;
      jr.equilibrium_rad = eq.q[c];
      if (j.hold == JointHold::Locked) jr.torque_nm = -eq.generalized_force[c];
      if (j.hold == JointHold::Servo) jr.torque_nm = -j.servo_stiffness * (eq.q[c] - j.angle);
    }
    out.push_back(jr);
  }
  return out;
}

std::vector<ClosureReport> closureReports(const Model& model, const SimTK::State& eqs, const EquilibriumResult& eq) {
  const Eigen::VectorXd phi = model.getNumClosureRows() ? calcClosureErrors(model, eqs) : Eigen::VectorXd();
  const auto forces = closureForces(model, eq.closure_multipliers);
  std::vector<ClosureReport> out;
  int row = 0, f = 0;
  for (const auto& c : model.getClosures()) {
    ClosureReport cr;
    cr.name = c.name;
    cr.fx = forces[f].force_W[0];
    cr.fy = forces[f].force_W[1];
    cr.fz = forces[f].force_W[2];
    for (std::size_t d = 0; d < c.directions.size(); ++d) cr.error_m = std::max(cr.error_m, std::abs(phi[row++]));
    f += c.to_ground ? 1 : 2;
    out.push_back(cr);
  }
  return out;
}

/// Every named point at the equilibrium and its deflection from the unbent shape.
std::vector<PointReport> pointReports(const Model& model, const SimTK::State& eqs, const EquilibriumResult& eq) {
  const auto& coords = model.getCoordinates();
  SimTK::State unbent = eq.state;
  Eigen::VectorXd q = eq.q;
  for (std::size_t c = 0; c < coords.size(); ++c)
    if (coords[c].kind == CoordinateKind::Hinge) q[c] = 0.0;
  model.setQ(unbent, q);
  model.getSystem().realize(unbent, SimTK::Stage::Position);
  std::vector<PointReport> out;
  for (const auto& p : model.getPoints()) {
    const SimTK::Vec3 x = model.findPointLocation(eqs, p);
    const SimTK::Vec3 x0 = model.findPointLocation(unbent, p);
    out.push_back({p.name, x[0], x[1], x[0] - x0[0], x[1] - x0[1], x[2], x[2] - x0[2]});
  }
  return out;
}

/// Every body's mass centre and every named point at the equilibrium, with the bodies'
/// masses and spins: what a mode's energies and shapes need. Their velocities in a
/// shape cost one O(bodies) pass per mode (no Jacobian is formed).
struct ModeKinematics {
  const Model* model = nullptr;
  const SimTK::State* state = nullptr;
  const std::vector<int>* dofs = nullptr;
  std::vector<SimTK::MobilizedBodyIndex> body_ix, point_ix;
  std::vector<SimTK::Vec3> body_com, point_st;
  std::vector<double> body_mass, body_izz;
  std::vector<SimTK::Mat33> body_inertia_W;  ///< spatial model: central inertia, world axes.
  /// 6 rows (w; v) per body mass centre / named point for the shape phi over the DOFs.
  Eigen::VectorXd bodies(const Eigen::VectorXd& phi) const {
    return model->calcFrameVelocities(*state, body_ix, body_com, *dofs, phi);
  }
  Eigen::VectorXd points(const Eigen::VectorXd& phi) const {
    return model->calcFrameVelocities(*state, point_ix, point_st, *dofs, phi);
  }
};

ModeKinematics modeKinematics(const Model& model, const SimTK::State& eqs, const std::vector<int>& dofs) {
  ModeKinematics k{&model, &eqs, &dofs, {}, {}, {}, {}, {}, {}, {}};
  for (const auto& b : model.getBodies()) {
    const SimTK::MassProperties mp = model.getMatter().getMobilizedBody(b.mobod).getBodyMassProperties(eqs);
    k.body_ix.push_back(b.mobod);
    k.body_com.push_back(mp.getMassCenter());
    k.body_mass.push_back(mp.getMass());
    k.body_izz.push_back(mp.calcCentralInertia().getMoments()[2]);
    if (model.isSpatial()) {
      const SimTK::Rotation R = model.getMatter().getMobilizedBody(b.mobod).getBodyRotation(eqs);
      k.body_inertia_W.push_back(R * mp.calcCentralInertia().toMat33() * ~R);
    }
  }
  for (const auto& p : model.getPoints()) {
    k.point_ix.push_back(p.mobod);
    k.point_st.push_back(p.station_B);
  }
  return k;
}

/// Kinetic and strain energy shares per part and per carrying link, effective masses.
void describeEnergies(const Model& model, const std::vector<int>& dofs, const ModeKinematics& k, const Eigen::VectorXd& phi,
                      ModeInfo& m) {
  std::map<std::string, double> kinetic, strain;
  double Lx = 0, Ly = 0, Lz = 0;
  const Eigen::VectorXd vb = k.bodies(phi);
  for (std::size_t b = 0; b < k.body_mass.size(); ++b) {
    const Eigen::Matrix<double, 6, 1> v = vb.segment<6>(6 * b);  // (w; v_com)
    const SimTK::Vec3 w(v[0], v[1], v[2]);
    const double spin = k.body_inertia_W.empty() ? k.body_izz[b] * v[2] * v[2] : ~w * (k.body_inertia_W[b] * w);
    const double ke = 0.5 * (k.body_mass[b] * v.tail<3>().squaredNorm() + spin);
    kinetic[model.getParts()[model.getBodies()[b].part].name] += ke;
    Lx += k.body_mass[b] * v[3];
    Ly += k.body_mass[b] * v[4];
    Lz += k.body_mass[b] * v[5];
  }
  const auto& coords = model.getCoordinates();
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const Coordinate& c = coords[dofs[i]];
    if (c.stiffness > 0) strain[c.part] += 0.5 * c.stiffness * phi[i] * phi[i];
  }
  m.effective_mass_x_kg = Lx * Lx;
  m.effective_mass_y_kg = Ly * Ly;
  if (model.isSpatial()) {
    m.effective_mass_z_kg = Lz * Lz;
    m.family = classifyMode(model, dofs, phi);
  }
  m.kinetic = sortedShares(kinetic);
  m.strain = sortedShares(strain);
  m.kinetic_by_link = sortedShares(byCarrier(kinetic, model));
  m.strain_by_link = sortedShares(byCarrier(strain, model));
  m.dominant_link_kinetic = m.kinetic_by_link.empty() ? "" : m.kinetic_by_link.front().part;
  m.dominant_link_strain = m.strain_by_link.empty() ? "" : m.strain_by_link.front().part;
}

/// The shape at the named points, the point that moves most and the modal mass there.
void describeShape(const Model& model, const ModeKinematics& k, const Eigen::VectorXd& phi, bool with_shapes, ModeInfo& m) {
  const Eigen::VectorXd u = k.points(phi);
  double peak = 0;
  for (std::size_t p = 0; p < model.getPoints().size(); ++p) {
    const NamedPoint& np = model.getPoints()[p];
    PointMotion pm{np.name, u[6 * p + 3], u[6 * p + 4], 0.0, u[6 * p + 2], np.report_rotation};
    if (model.isSpatial()) pm.uz = u[6 * p + 5];
    const double mag = model.isSpatial() ? std::hypot(pm.ux, pm.uy, pm.uz) : std::hypot(pm.ux, pm.uy);
    if (mag > peak) {
      peak = mag;
      m.peak_point = np.name;
    }
    if (with_shapes) m.shape.push_back(pm);
  }
  m.modal_mass_kg = peak > 0 ? 1.0 / (peak * peak) : 0.0;
}

/// Solves more modes (doubling) until one lies above `hz` or all are solved: what the
/// planarity report's band needs on a model large enough for the partial solver.
void solveThroughBand(SolvedScene& s, const ArticleScene& scene, double hz) {
  const int n = static_cast<int>(s.linearized.dofs.size());
  auto highest = [&] { return s.modes.omega2.size() ? s.modes.frequencyHz(static_cast<int>(s.modes.omega2.size()) - 1) : 0.0; };
  while (static_cast<int>(s.modes.omega2.size()) < n && highest() <= hz) {
    const int more = std::min(n, std::max(20, 2 * static_cast<int>(s.modes.omega2.size())));
    s.modes = solveModes(s.linearized, more >= n ? 0 : more);
    markRigidBodyModes(s.modes, s.linearized, scene);
  }
}

/// The eigen checks over the `count` modes reported, and a warning when a residual is
/// too large to trust the printed digits.
void checkReportedModes(const SolvedScene& s, int count, ModesReport& rep) {
  const ModalSolution& m = s.modes;
  for (int i = 0; i < count; ++i) rep.eigen_residual = std::max(rep.eigen_residual, m.residuals[i]);
  const Eigen::MatrixXd V = m.shapes.leftCols(count);
  rep.orthogonality_error =
      count ? (V.transpose() * massTimes(s.linearized, V) - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff()
            : 0.0;
  constexpr double kTrusted = 1e-6;
  if (rep.eigen_residual > kTrusted) {
    std::ostringstream os;
    os << "eigen residual " << std::setprecision(2) << rep.eigen_residual << " of a reported mode exceeds " << kTrusted
       << ": the dense eigen solution has lost accuracy at " << m.omega2.size()
       << " DOF; trust fewer digits, or use fewer segments (mmvlab converge shows what they cost)";
    rep.warnings.push_back(os.str());
  }
}

}  // namespace

namespace {

/// phi^T K_geometric phi / omega^2 of the first `count` modes: phi^T K phi less the
/// springs' part, from products with K (no K_geometric is formed on a large tree).
Eigen::VectorXd geometricShares(const LinearizedModel& lin, const ModalSolution& modes, int count) {
  const Eigen::VectorXd springs = springDiagonal(lin);
  const Eigen::MatrixXd V = modes.shapes.leftCols(count), KV = stiffnessTimes(lin, V);
  Eigen::VectorXd share(count);
  for (int i = 0; i < count; ++i)
    share[i] = (V.col(i).dot(KV.col(i)) - V.col(i).cwiseAbs2().dot(springs)) / modes.omega2[i];
  return share;
}

/// Each span's strain per unit coordinate (strainRow: -c / span (theta_B - theta_A) in
/// the plane, +c / span (phi_B - phi_A) out of it): frf's strain output row.
std::vector<Eigen::RowVectorXd> strainRows(const ArticleScene& scene, const Model& model, const SimTK::State& eqs,
                                           const std::vector<int>& dofs, const std::vector<StrainGaugeSpec>& spans) {
  std::vector<Eigen::RowVectorXd> rows;
  for (const auto& g : spans) {
    std::string error;
    const std::optional<PointRef> a = PointRef::resolve(model, scene.article, g.a, error),
                                  b = PointRef::resolve(model, scene.article, g.b, error);
    MMV_DEMAND(a && b && g.span_m != 0 && g.surface_m > 0);  // checked by the front end
    rows.push_back(strainRow(*a, *b, eqs, dofs, g.surface_m / g.span_m, g.out_of_plane));
  }
  return rows;
}

/// What the equilibrium holds: torques, closure forces, points and the links' stress.
void describeEquilibrium(const ArticleScene& scene, const Model& model, const EquilibriumResult& eq, const SimTK::State& eqs,
                         ModesReport& rep) {
  rep.joints = jointReports(scene, model, eq);
  rep.closures = closureReports(model, eqs, eq);
  rep.points = pointReports(model, eqs, eq);
  rep.strength = scene.article.strength;
  rep.static_stress = staticLinkStress(model, scene.article, eqs, eq.q, closureForces(model, eq.closure_multipliers));
}

/// Each link's peak bending stress in mode `phi` (over `dofs`) per mm of its peak
/// translation, 1 / sqrt(modal mass) m per unit modal coordinate (describeShape).
std::vector<ModalLinkStress> modalStressPerMm(const Model& model, const ArticleSpec& article, const Eigen::VectorXd& q,
                                              const std::vector<int>& dofs, const Eigen::VectorXd& phi, const ModeInfo& m) {
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(model.getNumCoordinates());
  for (std::size_t i = 0; i < dofs.size(); ++i) dq[dofs[i]] = phi[static_cast<Eigen::Index>(i)];
  const double peak_mm = 1e3 / std::sqrt(m.modal_mass_kg);
  std::vector<ModalLinkStress> out;
  for (const LinkStressPeak& p : modalLinkStress(model, article, q, dq)) {
    ModalLinkStress r;
    r.link = p.link;
    r.recovered = p.recovered;
    r.why_not = p.why_not;
    if (p.recovered) {
      r.x_m = p.loads.x;
      r.face = p.stress.face;
      r.equivalent_pa_per_mm = p.stress.equivalent / peak_mm;
      r.moment_nm_per_mm = std::abs(p.loads.moment) / peak_mm;
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

ModesReport runModes(const ArticleScene& scene, const ModesOptions& options) {
  ModesReport rep;
  rep.scene_name = scene.name;
  rep.scene_source = scene.source;
  rep.gravity = scene.gravity;
  const int solved_modes = options.damping && options.max_modes > 0
                               ? std::min(std::max(2 * options.max_modes, options.max_modes + 20), kMaxDampingBasis)
                               : options.max_modes;
  SolvedScene s = solveScene(scene, options.equilibrium, solved_modes, true);  // damping reads the modes alone
  if (s.model->isSpatial()) solveThroughBand(s, scene, PlanarityReport().band_high_hz);
  rep.seconds_build = s.seconds_build;
  rep.seconds_equilibrium = s.seconds_equilibrium;
  rep.seconds_linearize = s.seconds_linearize;
  rep.seconds_eigen = s.seconds_eigen;
  const Model& model = *s.model;
  const auto& dofs = s.linearized.dofs;
  rep.model = summarizeModel(scene, model, dofs.size());
  rep.equilibrium_converged = s.equilibrium.converged;
  rep.equilibrium_iterations = s.equilibrium.iterations;
  rep.equilibrium_residual_nm = s.equilibrium.residual;
  rep.force_scale_nm = s.equilibrium.force_scale;
  SimTK::State eqs = s.equilibrium.state;  // a copied State must be realized again before use
  model.getSystem().realize(eqs, SimTK::Stage::Position);
  describeEquilibrium(scene, model, s.equilibrium, eqs, rep);
  const ModeKinematics kin = modeKinematics(model, eqs, dofs);
  std::vector<PointRef> at_points;
  std::vector<Eigen::MatrixXd> point_rows;
  for (const auto& name : options.points) {
    std::string error;
    std::optional<PointRef> p = PointRef::resolve(model, scene.article, name, error);
    if (!p) throw SceneError(scene.source + ": " + error);
    point_rows.push_back(p->translationJacobian(eqs, dofs, model.isSpatial() ? 3 : 2));
    at_points.push_back(*p);
  }
  const std::vector<Eigen::RowVectorXd> strain_rows = strainRows(scene, model, eqs, dofs, options.strains);
  rep.stiffness_asymmetry = s.linearized.asymmetry;
  const int n = static_cast<int>(s.modes.omega2.size());
  const int count = options.max_modes > 0 ? std::min(options.max_modes, n) : n;
  if (options.max_modes > n)
    rep.warnings.push_back(strf("%d modes asked for; the model has %d (one per degree of freedom): all %d shown",
                                options.max_modes, n, n));
  checkReportedModes(s, count, rep);
  ModalDamping damping;
  if (options.damping) {
    damping = modalDamping(model, s.linearized, s.modes, *options.damping, count);
    rep.damped = true;
    rep.damping_model = describeDamping(*options.damping);
    rep.damping_basis_modes = damping.basis_modes;
    rep.damping_exact = damping.exact;
  }
  const Eigen::VectorXd geometric = geometricShares(s.linearized, s.modes, count);
  for (int i = 0; i < count; ++i) {
    const Eigen::VectorXd phi = s.modes.shapes.col(i);
    ModeInfo m;
    m.number = ModeNumber::atIndex(i);
    m.omega2 = s.modes.omega2[i];
    m.stable = s.modes.isStable(i);
    m.rigid_body = s.modes.isRigidBody(i);
    m.frequency_hz = s.modes.frequencyHz(i);
    m.geometric_stiffness_share = m.rigid_body ? 0.0 : geometric[i];
    if (rep.damped && i < static_cast<int>(damping.ratio.size())) {
      m.has_damping = true;
      m.damping_ratio = damping.ratio[i];
      m.damped_natural_hz = damping.natural_hz[i];
    }
    describeEnergies(model, dofs, kin, phi, m);
    describeShape(model, kin, phi, options.with_shapes, m);
    for (std::size_t p = 0; p < at_points.size(); ++p) {
      const Eigen::VectorXd u = point_rows[p] * phi;
      m.at_points.push_back({at_points[p].name(), u[0], u[1], u.size() > 2 ? u[2] : 0.0, 0.0, false});
    }
    for (std::size_t g = 0; g < strain_rows.size(); ++g) m.strains.push_back({options.strains[g].name, strain_rows[g].dot(phi)});
    if (!m.rigid_body && m.modal_mass_kg > 0) m.stress_per_mm = modalStressPerMm(model, scene.article, s.equilibrium.q, dofs, phi, m);
    rep.modes.push_back(std::move(m));
  }
  rep.spatial = model.isSpatial();
  if (rep.spatial) rep.planarity = planarityReport(model, eqs, dofs, s.modes);
  return rep;
}

std::vector<double> reportFrequencies(const ModesReport& r) {
  std::vector<double> f;
  for (const auto& m : r.modes)
    f.push_back(m.rigid_body ? 0.0 : (m.omega2 >= 0 ? std::sqrt(m.omega2) : -std::sqrt(-m.omega2)) / (2 * M_PI));
  return f;
}

}  // namespace mmv
