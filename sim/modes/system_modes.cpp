#include "sim/modes/system_modes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "sim/model/article_builder.hpp"
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

SolvedScene solveScene(const ArticleScene& scene, const EquilibriumOptions& eq_opts) {
  SolvedScene s;
  auto t0 = Clock::now();
  s.model = buildArticleModel(scene);
  s.seconds_build = secondsSince(t0);
  t0 = Clock::now();
  s.equilibrium = solveEquilibrium(*s.model, eq_opts);
  s.seconds_equilibrium = secondsSince(t0);
  if (!s.equilibrium.converged) throw NumericalError("static equilibrium failed: " + s.equilibrium.failure);
  t0 = Clock::now();
  s.linearized = linearize(*s.model, s.equilibrium.state, s.equilibrium.closure_multipliers);
  s.seconds_linearize = secondsSince(t0);
  t0 = Clock::now();
  s.modes = solveModes(s.linearized.M, s.linearized.K, s.linearized.Z);
  s.seconds_eigen = secondsSince(t0);
  return s;
}

Eigen::MatrixXd pointTranslationMatrix(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  std::vector<SimTK::MobilizedBodyIndex> ix;
  std::vector<SimTK::Vec3> st;
  for (const auto& p : model.getPoints()) {
    ix.push_back(p.mobod);
    st.push_back(p.station_B);
  }
  const Eigen::MatrixXd J = model.calcFrameJacobians(s, ix, st, dofs);
  Eigen::MatrixXd P(2 * ix.size(), dofs.size());
  for (std::size_t p = 0; p < ix.size(); ++p) P.middleRows(2 * p, 2) = J.middleRows(6 * p + 3, 2);
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

ModesSolve solveSceneModes(const ArticleScene& scene, const EquilibriumOptions& eq) {
  const SolvedScene s = solveScene(scene, eq);
  ModesSolve out;
  out.num_dofs = static_cast<int>(s.linearized.dofs.size());
  out.frequencies_hz.resize(s.modes.omega2.size());
  for (Eigen::Index i = 0; i < s.modes.omega2.size(); ++i) out.frequencies_hz[i] = s.modes.frequencyHz(static_cast<int>(i));
  return out;
}

ModesReport runModes(const ArticleScene& scene, const ModesOptions& options) {
  ModesReport rep;
  rep.scene_name = scene.name;
  rep.scene_source = scene.source;
  rep.gravity = scene.gravity;
  const SolvedScene s = solveScene(scene, options.equilibrium);
  rep.seconds_build = s.seconds_build;
  rep.seconds_equilibrium = s.seconds_equilibrium;
  rep.seconds_linearize = s.seconds_linearize;
  rep.seconds_eigen = s.seconds_eigen;
  const Model& model = *s.model;
  const auto& coords = model.getCoordinates();
  const auto& dofs = s.linearized.dofs;

  // Model summary.
  rep.model.num_links = static_cast<int>(scene.article.links.size());
  rep.model.num_bodies = static_cast<int>(model.getBodies().size());
  rep.model.num_coordinates = model.getNumCoordinates();
  rep.model.num_dofs = static_cast<int>(dofs.size());
  rep.model.total_mass_kg = model.getTotalMass();
  rep.model.moving_mass_kg = model.getMovingMass();
  for (const auto& l : scene.article.links) rep.model.link_segments.push_back({l.name, l.rigid ? 0 : l.segments});

  // Equilibrium: joints, deflections.
  rep.equilibrium_converged = s.equilibrium.converged;
  rep.equilibrium_iterations = s.equilibrium.iterations;
  rep.equilibrium_residual_nm = s.equilibrium.residual;
  rep.force_scale_nm = s.equilibrium.force_scale;
  for (const auto& j : scene.article.joints) {
    JointReport jr;
    jr.name = j.name;
    jr.hold = holdName(j.hold);
    jr.commanded_rad = j.angle;
    for (std::size_t c = 0; c < coords.size(); ++c) {
      if (coords[c].kind != CoordinateKind::Joint || coords[c].name != j.name) continue;
      jr.equilibrium_rad = s.equilibrium.q[c];
      if (j.hold == JointHold::Locked) jr.torque_nm = -s.equilibrium.generalized_force[c];
      if (j.hold == JointHold::Servo) jr.torque_nm = -j.servo_stiffness * (s.equilibrium.q[c] - j.angle);
    }
    rep.joints.push_back(jr);
  }
  SimTK::State eqs = s.equilibrium.state;  // a copied State must be realized again before use
  model.getSystem().realize(eqs, SimTK::Stage::Position);
  {
    const Eigen::VectorXd phi = model.getNumClosureRows() ? calcClosureErrors(model, eqs) : Eigen::VectorXd();
    const auto forces = closureForces(model, s.equilibrium.closure_multipliers);
    int row = 0, f = 0;
    for (const auto& c : model.getClosures()) {
      ClosureReport cr;
      cr.name = c.name;
      cr.fx = forces[f].force_W[0];
      cr.fy = forces[f].force_W[1];
      for (std::size_t d = 0; d < c.directions.size(); ++d) cr.error_m = std::max(cr.error_m, std::abs(phi[row++]));
      f += c.to_ground ? 1 : 2;
      rep.closures.push_back(cr);
    }
  }
  SimTK::State unbent = s.equilibrium.state;
  {
    Eigen::VectorXd q = s.equilibrium.q;
    for (std::size_t c = 0; c < coords.size(); ++c)
      if (coords[c].kind == CoordinateKind::Hinge) q[c] = 0.0;
    model.setQ(unbent, q);
    model.getSystem().realize(unbent, SimTK::Stage::Position);
  }
  for (const auto& p : model.getPoints()) {
    const SimTK::Vec3 x = model.findPointLocation(eqs, p);
    const SimTK::Vec3 x0 = model.findPointLocation(unbent, p);
    rep.points.push_back({p.name, x[0], x[1], x[0] - x0[0], x[1] - x0[1]});
  }

  // Jacobians at the equilibrium: body mass centres and named points.
  std::vector<SimTK::MobilizedBodyIndex> body_ix, point_ix;
  std::vector<SimTK::Vec3> body_com, point_st;
  std::vector<double> body_mass, body_izz;
  for (const auto& b : model.getBodies()) {
    const SimTK::MassProperties mp = model.getMatter().getMobilizedBody(b.mobod).getBodyMassProperties(eqs);
    body_ix.push_back(b.mobod);
    body_com.push_back(mp.getMassCenter());
    body_mass.push_back(mp.getMass());
    body_izz.push_back(mp.calcCentralInertia().getMoments()[2]);
  }
  for (const auto& p : model.getPoints()) {
    point_ix.push_back(p.mobod);
    point_st.push_back(p.station_B);
  }
  const Eigen::MatrixXd Jb = model.calcFrameJacobians(eqs, body_ix, body_com, dofs);
  const Eigen::MatrixXd Jp = model.calcFrameJacobians(eqs, point_ix, point_st, dofs);

  rep.eigen_residual = s.modes.max_residual;
  rep.orthogonality_error = s.modes.orthogonality_error;
  rep.stiffness_asymmetry = s.linearized.asymmetry;
  const int n = static_cast<int>(s.modes.omega2.size());
  const int count = options.max_modes > 0 ? std::min(options.max_modes, n) : n;
  for (int i = 0; i < count; ++i) {
    const Eigen::VectorXd phi = s.modes.shapes.col(i);
    ModeInfo m;
    m.number = i + 1;
    m.omega2 = s.modes.omega2[i];
    m.stable = s.modes.isStable(i);
    m.rigid_body = s.modes.isRigidBody(i);
    m.frequency_hz = s.modes.frequencyHz(i);
    m.geometric_stiffness_share = m.rigid_body ? 0.0 : phi.dot(s.linearized.K_geometric * phi) / m.omega2;

    std::map<std::string, double> kinetic, strain;
    double Lx = 0, Ly = 0;
    for (std::size_t b = 0; b < body_ix.size(); ++b) {
      const Eigen::VectorXd v = Jb.middleRows(6 * b, 6) * phi;  // (w; v_com)
      const double ke = 0.5 * (body_mass[b] * v.tail<3>().squaredNorm() + body_izz[b] * v[2] * v[2]);
      kinetic[model.getParts()[model.getBodies()[b].part].name] += ke;
      Lx += body_mass[b] * v[3];
      Ly += body_mass[b] * v[4];
    }
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      const Coordinate& c = coords[dofs[k]];
      if (c.stiffness > 0) strain[c.part] += 0.5 * c.stiffness * phi[k] * phi[k];
    }
    m.effective_mass_x_kg = Lx * Lx;
    m.effective_mass_y_kg = Ly * Ly;
    m.kinetic = sortedShares(kinetic);
    m.strain = sortedShares(strain);
    m.kinetic_by_link = sortedShares(byCarrier(kinetic, model));
    m.strain_by_link = sortedShares(byCarrier(strain, model));
    m.dominant_link_kinetic = m.kinetic_by_link.empty() ? "" : m.kinetic_by_link.front().part;
    m.dominant_link_strain = m.strain_by_link.empty() ? "" : m.strain_by_link.front().part;

    const Eigen::VectorXd u = Jp * phi;
    double peak = 0;
    for (std::size_t p = 0; p < point_ix.size(); ++p) {
      const NamedPoint& np = model.getPoints()[p];
      PointMotion pm{np.name, u[6 * p + 3], u[6 * p + 4], u[6 * p + 2], np.report_rotation};
      const double mag = std::hypot(pm.ux, pm.uy);
      if (mag > peak) {
        peak = mag;
        m.peak_point = np.name;
      }
      if (options.with_shapes) m.shape.push_back(pm);
    }
    m.modal_mass_kg = peak > 0 ? 1.0 / (peak * peak) : 0.0;
    rep.modes.push_back(std::move(m));
  }
  return rep;
}

}  // namespace mmv
