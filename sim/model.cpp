#include "sim/model.hpp"

#include <cassert>
#include <stdexcept>

namespace mmv {

Model::Model(const SimTK::Vec3& g_W) : matter_(system_), forces_(system_), gravity_W_(g_W) {
  SimTK::Force::Gravity(forces_, matter_, g_W);
}

int Model::addPart(const std::string& name, Part::Kind kind, const std::string& carrier) {
  parts_.push_back({name, kind, carrier});
  return static_cast<int>(parts_.size()) - 1;
}

void Model::addBody(SimTK::MobilizedBodyIndex mobod, int part, bool grounded) {
  bodies_.push_back({mobod, part, grounded});
}

void Model::addCoordinate(const Coordinate& c) {
  assert(!finalized_);
  coords_.push_back(c);
  if (c.stiffness > 0) {
    SimTK::Force::MobilityLinearSpring(forces_, matter_.getMobilizedBody(c.mobod),
                                       SimTK::MobilizerQIndex(0), c.stiffness, c.reference);
  }
}

void Model::addPoint(const NamedPoint& p) { points_.push_back(p); }

void Model::finalize() {
  assert(!finalized_);
  system_.realizeTopology();
  SimTK::State s = system_.getDefaultState();
  system_.realizeModel(s);
  for (std::size_t i = 0; i < coords_.size(); ++i) {
    const auto& mb = matter_.getMobilizedBody(coords_[i].mobod);
    if (mb.getNumQ(s) != 1 || mb.getNumU(s) != 1)
      throw std::logic_error("coordinate " + coords_[i].name + " is not a 1-DOF mobilizer");
    qindex_.push_back(mb.getFirstQIndex(s));
    uindex_.push_back(mb.getFirstUIndex(s));
    if (!coords_[i].held) dofs_.push_back(static_cast<int>(i));
  }
  if (static_cast<int>(coords_.size()) != s.getNQ() || s.getNQ() != s.getNU())
    throw std::logic_error("model has mobilities that are not registered coordinates");
  for (std::size_t i = 0; i < coords_.size(); ++i) s.updQ()[qindex_[i]] = coords_[i].reference;
  system_.realize(s, SimTK::Stage::Position);
  reference_state_ = s;
  // Ancestry: which coordinates move each body.
  std::vector<int> coord_of_mobod(matter_.getNumBodies(), -1);
  for (std::size_t i = 0; i < coords_.size(); ++i) coord_of_mobod[coords_[i].mobod] = static_cast<int>(i);
  coord_body_.assign(coords_.size(), -1);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    std::vector<int> anc;
    for (SimTK::MobilizedBodyIndex ix = bodies_[b].mobod; ix != SimTK::GroundIndex;
         ix = matter_.getMobilizedBody(ix).getParentMobilizedBody().getMobilizedBodyIndex()) {
      if (coord_of_mobod[ix] >= 0) anc.push_back(coord_of_mobod[ix]);
    }
    body_ancestors_.push_back(anc);
    if (coord_of_mobod[bodies_[b].mobod] >= 0) coord_body_[coord_of_mobod[bodies_[b].mobod]] = static_cast<int>(b);
  }
  for (std::size_t i = 0; i < coords_.size(); ++i)
    if (coord_body_[i] < 0) throw std::logic_error("coordinate " + coords_[i].name + " moves no registered body");
  for (const auto& b : bodies_) {
    const double m = matter_.getMobilizedBody(b.mobod).getBodyMass(s);
    total_mass_ += m;
    if (!b.grounded) moving_mass_ += m;
  }
  finalized_ = true;
}

const NamedPoint* Model::findPoint(const std::string& name) const {
  for (const auto& p : points_)
    if (p.name == name) return &p;
  return nullptr;
}

Eigen::VectorXd Model::getQ(const SimTK::State& s) const {
  Eigen::VectorXd q(coords_.size());
  for (std::size_t i = 0; i < coords_.size(); ++i) q[i] = s.getQ()[qindex_[i]];
  return q;
}

void Model::setQ(SimTK::State& s, const Eigen::VectorXd& q) const {
  assert(q.size() == static_cast<Eigen::Index>(coords_.size()));
  for (std::size_t i = 0; i < coords_.size(); ++i) {
    s.updQ()[qindex_[i]] = q[i];
    s.updU()[uindex_[i]] = 0.0;
  }
}

Eigen::VectorXd Model::calcAppliedForces(SimTK::State& s) const {
  system_.realize(s, SimTK::Stage::Dynamics);
  const SimTK::Vector_<SimTK::SpatialVec>& body_forces = system_.getRigidBodyForces(s, SimTK::Stage::Dynamics);
  const SimTK::Vector& mobility_forces = system_.getMobilityForces(s, SimTK::Stage::Dynamics);
  SimTK::Vector f;
  matter_.multiplyBySystemJacobianTranspose(s, body_forces, f);
  f += mobility_forces;
  Eigen::VectorXd out(coords_.size());
  for (std::size_t i = 0; i < coords_.size(); ++i) out[i] = f[uindex_[i]];
  return out;
}

Eigen::MatrixXd Model::calcFrameJacobians(const SimTK::State& s,
                                          const std::vector<SimTK::MobilizedBodyIndex>& bodies,
                                          const std::vector<SimTK::Vec3>& stations,
                                          const std::vector<int>& cols) const {
  assert(bodies.size() == stations.size());
  SimTK::Array_<SimTK::MobilizedBodyIndex> b(bodies.begin(), bodies.end());
  SimTK::Array_<SimTK::Vec3> p(stations.begin(), stations.end());
  SimTK::Matrix jf;
  matter_.calcFrameJacobian(s, b, p, jf);
  Eigen::MatrixXd out(jf.nrow(), cols.size());
  for (std::size_t j = 0; j < cols.size(); ++j) {
    const int u = uindex_[cols[j]];
    for (int i = 0; i < jf.nrow(); ++i) out(i, j) = jf(i, u);
  }
  return out;
}

SimTK::Vec3 Model::findPointLocation(const SimTK::State& s, const NamedPoint& p) const {
  return matter_.getMobilizedBody(p.mobod).findStationLocationInGround(s, p.station_B);
}

}  // namespace mmv
