#include "sim/modes/planarity.hpp"

#include <cmath>

namespace mmv {

ModeFamily classifyMode(const Model& model, const std::vector<int>& dofs, const Eigen::VectorXd& phi) {
  ModeFamily f;
  double total = 0;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const Coordinate& c = model.getCoordinates()[dofs[i]];
    const double e = c.stiffness * phi[static_cast<Eigen::Index>(i)] * phi[static_cast<Eigen::Index>(i)];
    total += e;
    (c.axis == HingeAxis::OutOfPlane ? f.out_of_plane : c.axis == HingeAxis::Torsion ? f.torsion : f.in_plane) += e;
  }
  if (!(total > 0)) {
    f.in_plane = f.out_of_plane = f.torsion = 0;
    f.label = "rigid";
    return f;
  }
  f.in_plane /= total;
  f.out_of_plane /= total;
  f.torsion /= total;
  f.label = f.in_plane >= kFamilyShare       ? "in-plane"
            : f.out_of_plane >= kFamilyShare ? "out-of-plane"
            : f.torsion >= kFamilyShare      ? "torsion"
                                             : "mixed";
  return f;
}

void separateDegenerateFamilies(const Model& model, const std::vector<int>& dofs, ModalSolution& modes,
                                double tolerance) {
  const Eigen::Index n = modes.omega2.size();
  Eigen::VectorXd weight(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const Coordinate& c = model.getCoordinates()[dofs[i]];
    weight[static_cast<Eigen::Index>(i)] =
        c.stiffness * (c.axis == HingeAxis::OutOfPlane ? 2.0 : c.axis == HingeAxis::Torsion ? 3.0 : 1.0);
  }
  for (Eigen::Index first = 0; first < n;) {
    Eigen::Index last = first + 1;
    while (last < n && std::abs(modes.omega2[last] - modes.omega2[first]) <= tolerance * std::abs(modes.omega2[first]))
      ++last;
    if (last - first > 1 && modes.omega2[first] > 0) {
      const Eigen::MatrixXd V = modes.shapes.middleCols(first, last - first);
      const Eigen::MatrixXd E = V.transpose() * weight.asDiagonal() * V;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (E + E.transpose()));
      modes.shapes.middleCols(first, last - first) = V * es.eigenvectors();
    }
    first = last;
  }
}

namespace {

Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

/// The participation phi^T M r of every solved mode in each excitation: base
/// translation along world x and y (the inertia force of every body's mass centre),
/// and each held coordinate's mass-matrix column.
struct Excitations {
  std::vector<std::string> names;
  std::vector<Eigen::VectorXd> participation;  ///< per excitation, per mode.
};

Excitations excitations(const Model& model, const SimTK::State& s, const std::vector<int>& dofs,
                        const Eigen::MatrixXd& shapes) {
  Excitations out;
  const auto& matter = model.getMatter();
  auto project = [&](const std::string& name, const SimTK::Vector& g) {
    Eigen::VectorXd gd(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) gd[static_cast<Eigen::Index>(i)] = g[model.getUIndex(dofs[i])];
    out.names.push_back(name);
    out.participation.push_back(shapes.transpose() * gd);
  };
  for (int axis = 0; axis < 2; ++axis) {
    SimTK::Vector_<SimTK::SpatialVec> F(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
    SimTK::Vec3 e(0);
    e[axis] = 1;
    for (const auto& b : model.getBodies()) {
      const SimTK::MobilizedBody& mb = matter.getMobilizedBody(b.mobod);
      const SimTK::Vec3 f = mb.getBodyMass(s) * e;
      F[b.mobod] = SimTK::SpatialVec(mb.getBodyRotation(s) * mb.getBodyMassCenterStation(s) % f, f);
    }
    SimTK::Vector g;
    matter.multiplyBySystemJacobianTranspose(s, F, g);
    project(axis == 0 ? "base x" : "base y", g);
  }
  const auto& coords = model.getCoordinates();
  for (std::size_t c = 0; c < coords.size(); ++c) {
    // In-plane excitations only: the table's stage across the plane drives out of it by design.
    if (!coords[c].held || coords[c].kind != CoordinateKind::Joint || coords[c].axis != HingeAxis::InPlane) continue;
    SimTK::Vector unit(s.getNU(), 0.0), column;
    unit[model.getUIndex(static_cast<int>(c))] = 1;
    matter.multiplyByM(s, unit, column);
    project(coords[c].name, column);
  }
  return out;
}

/// The article plane's normal: the axis of the first joint (every joint turns about it).
Eigen::Vector3d planeNormal(const Model& model, const SimTK::State& s) {
  for (const auto& c : model.getCoordinates()) {
    if (c.kind != CoordinateKind::Joint || c.motion != CoordinateMotion::Rotation || c.part.rfind("gimbal", 0) == 0)
      continue;
    const SimTK::Vec3 a = model.getMatter().getMobilizedBody(c.mobod).getHCol(s, SimTK::MobilizerUIndex(c.mobilizer_q))[0];
    return toEigen(a).normalized();
  }
  return Eigen::Vector3d::UnitZ();
}

}  // namespace

PlanarityReport planarityReport(const Model& model, const SimTK::State& eqs, const std::vector<int>& dofs,
                                const ModalSolution& modes) {
  PlanarityReport rep;
  rep.normal = planeNormal(model, eqs);
  const int n = static_cast<int>(modes.omega2.size());
  std::vector<int> band;
  std::vector<ModeFamily> family(n);
  for (int i = 0; i < n; ++i) {
    if (modes.isStable(i)) rep.solved_up_to_hz = std::max(rep.solved_up_to_hz, modes.frequencyHz(i));
    const double f = modes.frequencyHz(i);
    if (!modes.isStable(i) || modes.isRigidBody(i) || f < rep.band_low_hz || f > rep.band_high_hz) continue;
    band.push_back(i);
    family[i] = classifyMode(model, dofs, modes.shapes.col(i));
    if (family[i].label == "in-plane") ++rep.in_plane_in_band;
  }
  rep.covers_band = rep.solved_up_to_hz >= rep.band_high_hz || n == static_cast<int>(dofs.size());
  for (int i : band) {
    if (family[i].label == "in-plane") continue;
    PlanarityMode pm{ModeNumber::atIndex(i), modes.frequencyHz(i), family[i], std::nullopt, 0, 0};
    for (int j : band) {
      if (family[j].label != "in-plane") continue;
      const double fj = modes.frequencyHz(j);
      if (!pm.nearest_in_plane || std::abs(fj - pm.frequency_hz) < std::abs(pm.nearest_hz - pm.frequency_hz)) {
        pm.nearest_in_plane = ModeNumber::atIndex(j);
        pm.nearest_hz = fj;
      }
    }
    if (pm.nearest_in_plane) pm.separation_pct = 100 * (pm.frequency_hz - pm.nearest_hz) / pm.nearest_hz;
    rep.others.push_back(pm);
  }
  // Each link tip's motion in every mode of the band (v rows of its frame velocity).
  std::vector<const NamedPoint*> tips;
  for (const auto& p : model.getPoints())
    if (p.name.size() > 4 && p.name.compare(p.name.size() - 4, 4, ".tip") == 0) tips.push_back(&p);
  std::vector<SimTK::MobilizedBodyIndex> ix;
  std::vector<SimTK::Vec3> st;
  for (const NamedPoint* p : tips) ix.push_back(p->mobod), st.push_back(p->station_B);
  std::vector<Eigen::VectorXd> motion(n);
  for (int i : band) motion[i] = model.calcFrameVelocities(eqs, ix, st, dofs, modes.shapes.col(i));
  const Excitations ex = excitations(model, eqs, dofs, modes.shapes.leftCols(n));
  for (std::size_t e = 0; e < ex.names.size(); ++e) {
    for (std::size_t p = 0; p < tips.size(); ++p) {
      PlanarityResponse r{ex.names[e], tips[p]->name, 0, false, {}, {}};
      double out_peak = 0, in_peak = 0;
      for (int i : band) {
        const Eigen::Vector3d d = motion[i].segment<3>(6 * static_cast<Eigen::Index>(p) + 3);
        const double w = std::abs(ex.participation[e][i]) / modes.omega2[i];
        const double out = w * std::abs(rep.normal.dot(d)), in = w * (d - rep.normal.dot(d) * rep.normal).norm();
        if (out > out_peak) out_peak = out, r.out_mode = ModeNumber::atIndex(i);
        if (in > in_peak) in_peak = in, r.in_mode = ModeNumber::atIndex(i);
      }
      if (!(in_peak > 0)) continue;  // the excitation does not move this tip in the band
      r.ratio = out_peak / in_peak;
      r.decoupled = r.ratio < kDecoupledRatio;
      rep.responses.push_back(r);
    }
  }
  return rep;
}

}  // namespace mmv
