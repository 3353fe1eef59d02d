#include "sim/model/model.hpp"
#include "sim/model/weighted_closure.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include <stdexcept>

namespace mmv {

Model::Model(const SimTK::Vec3& g_W)
    : matter_(system_), forces_(system_), gravity_W_(g_W), gravity_(forces_, matter_, g_W) {}

void Model::setGravityScale(SimTK::State& s, double scale) const { gravity_.setMagnitude(s, scale * gravity_W_.norm()); }

SimTK::Vec3 Model::getGravity(const SimTK::State& s) const {
  return gravity_W_.norm() > 0 ? gravity_.getMagnitude(s) * SimTK::Vec3(gravity_.getDownDirection(s)) : SimTK::Vec3(0);
}

int Model::addPart(const std::string& name, Part::Kind kind, const std::string& carrier) {
  parts_.push_back({name, kind, carrier});
  return static_cast<int>(parts_.size()) - 1;
}

void Model::addBody(SimTK::MobilizedBodyIndex mobod, int part, bool grounded) {
  bodies_.push_back({mobod, part, grounded});
}

namespace {

/// A commanded torque tau(t) on one mobility.
class ProgramMobilityForce : public SimTK::Force::Custom::Implementation {
 public:
  ProgramMobilityForce(const SimTK::MobilizedBody& mobod, int u, std::shared_ptr<const facility::TableProgram> p)
      : mobod_(mobod), u_(u), p_(std::move(p)) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobility_forces) const override {
    mobod_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(u_), p_->position(s.getTime()), mobility_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  bool dependsOnlyOnPositions() const override { return false; }

 private:
  const SimTK::MobilizedBody& mobod_;
  int u_;
  std::shared_ptr<const facility::TableProgram> p_;
};

}  // namespace

/// C over the speeds `u`, shared by the model and its Simbody force element.
struct Model::LinearDamping {
  std::vector<int> coords, u;
  Eigen::MatrixXd C;
  Eigen::VectorXd speeds(const SimTK::State& s) const {
    Eigen::VectorXd v(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) v[static_cast<Eigen::Index>(i)] = s.getU()[u[i]];
    return v;
  }
};

namespace {

/// f = -C u on the speeds of a Model::LinearDamping.
class LinearDamperForce : public SimTK::Force::Custom::Implementation {
 public:
  explicit LinearDamperForce(std::shared_ptr<const Model::LinearDamping> d) : d_(std::move(d)) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobility_forces) const override {
    if (d_->C.size() == 0) return;
    const Eigen::VectorXd f = d_->C * d_->speeds(s);
    for (std::size_t i = 0; i < d_->u.size(); ++i) mobility_forces[d_->u[i]] -= f[static_cast<Eigen::Index>(i)];
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
  bool dependsOnlyOnPositions() const override { return false; }

 private:
  std::shared_ptr<const Model::LinearDamping> d_;
};

}  // namespace

void Model::addLinearDamper() {
  MMV_DEMAND(!finalized_ && !linear_damper_);
  linear_damper_ = std::make_shared<LinearDamping>();
  SimTK::Force::Custom(forces_, new LinearDamperForce(linear_damper_));
}

void Model::setLinearDamping(const std::vector<int>& coords, const Eigen::MatrixXd& C) {
  MMV_DEMAND(linear_damper_ && finalized_);
  MMV_DEMAND(C.rows() == static_cast<Eigen::Index>(coords.size()) && C.cols() == C.rows());
  linear_damper_->coords = coords;
  linear_damper_->u.clear();
  for (int i : coords) linear_damper_->u.push_back(getUIndex(i));
  linear_damper_->C = C;
}

const Eigen::MatrixXd& Model::getLinearDamping() const {
  static const Eigen::MatrixXd none;
  return linear_damper_ ? linear_damper_->C : none;
}

const std::vector<int>& Model::getLinearDampingCoordinates() const {
  static const std::vector<int> none;
  return linear_damper_ ? linear_damper_->coords : none;
}

double Model::calcDissipation(const SimTK::State& s) const {
  double p = 0;
  for (std::size_t i = 0; i < coords_.size(); ++i)
    if (coords_[i].damping > 0) p += coords_[i].damping * std::pow(s.getU()[uindex_[i]], 2);
  if (linear_damper_ && linear_damper_->C.size() > 0) {
    const Eigen::VectorXd v = linear_damper_->speeds(s);
    p += v.dot(linear_damper_->C * v);
  }
  return p;
}

void Model::addCoordinate(const Coordinate& c) {
  registerCoordinate(c);
  if (c.stiffness > 0) {
    SimTK::Force::MobilityLinearSpring(forces_, matter_.getMobilizedBody(c.mobod),
                                       SimTK::MobilizerQIndex(c.mobilizer_q), c.stiffness, c.reference);
  }
}

namespace {

/// The rotation springs of sim/model/rotation_spring.hpp, on their gimbals' angles.
class RotationSpringForce : public SimTK::Force::Custom::Implementation {
 public:
  RotationSpringForce(const SimTK::SimbodyMatterSubsystem& matter, std::shared_ptr<const std::vector<RotationSpring>> springs)
      : matter_(matter), springs_(std::move(springs)) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobility_forces) const override {
    for (const RotationSpring& r : *springs_) {
      const SimTK::MobilizedBody& mb = matter_.getMobilizedBody(r.mobod);
      const SimTK::Vec3 f = rotationSpringForce(angles(s, mb), r.k);
      for (int i = 0; i < 3; ++i) mb.applyOneMobilityForce(s, SimTK::MobilizerUIndex(i), f[i], mobility_forces);
    }
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    double v = 0;
    for (const RotationSpring& r : *springs_) v += rotationSpringEnergy(angles(s, matter_.getMobilizedBody(r.mobod)), r.k);
    return v;
  }

 private:
  static SimTK::Vec3 angles(const SimTK::State& s, const SimTK::MobilizedBody& mb) {
    return {mb.getOneQ(s, SimTK::MobilizerQIndex(0)), mb.getOneQ(s, SimTK::MobilizerQIndex(1)),
            mb.getOneQ(s, SimTK::MobilizerQIndex(2))};
  }
  const SimTK::SimbodyMatterSubsystem& matter_;
  std::shared_ptr<const std::vector<RotationSpring>> springs_;
};

}  // namespace

void Model::addHingeRotation(const std::array<Coordinate, 3>& c) {
  RotationSpring r;
  r.mobod = c[0].mobod;
  for (int i = 0; i < 3; ++i) {
    // A gimbal's angles in order, with no reference: the spring's rest is the unbent hinge.
    MMV_DEMAND(c[i].mobod == r.mobod && c[i].mobilizer_q == i && c[i].reference == 0 && !c[i].input);
    r.coords[i] = static_cast<int>(coords_.size());
    r.k[i] = c[i].stiffness;
    registerCoordinate(c[i]);
  }
  if (rotation_springs_->empty()) SimTK::Force::Custom(forces_, new RotationSpringForce(matter_, rotation_springs_));
  rotation_springs_->push_back(r);
}

void Model::registerCoordinate(const Coordinate& c) {
  MMV_DEMAND(!finalized_);
  coords_.push_back(c);
  if (c.damping > 0) {
    SimTK::Force::MobilityLinearDamper(forces_, matter_.getMobilizedBody(c.mobod),
                                       SimTK::MobilizerUIndex(c.mobilizer_q), c.damping);
  }
  if (c.input)
    SimTK::Force::Custom(forces_, new ProgramMobilityForce(matter_.getMobilizedBody(c.mobod), c.mobilizer_q, c.input));
}

double Model::inputPower(const SimTK::State& s) const {
  double p = 0;
  for (const auto& c : coords_)
    if (c.input) p += c.input->position(s.getTime()) * matter_.getMobilizedBody(c.mobod).getOneU(s, SimTK::MobilizerUIndex(c.mobilizer_q));
  return p;
}

namespace {

/// A dead load F (world) at a station of a body, with its potential energy -F . p: it is
/// conservative, so a time run's energy balance counts its work (Simbody's ConstantForce
/// reports no potential energy, and a loaded point that moved showed as a balance error).
class PointLoadForce : public SimTK::Force::Custom::Implementation {
 public:
  PointLoadForce(const SimTK::MobilizedBody& mobod, const SimTK::Vec3& station_B, const SimTK::Vec3& force_W)
      : mobod_(mobod), station_B_(station_B), force_W_(force_W) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {
    mobod_.applyForceToBodyPoint(s, station_B_, force_W_, body_forces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    return -(~force_W_ * mobod_.findStationLocationInGround(s, station_B_));
  }
  bool dependsOnlyOnPositions() const override { return true; }

 private:
  const SimTK::MobilizedBody& mobod_;
  SimTK::Vec3 station_B_, force_W_;
};

}  // namespace

void Model::addPointLoad(const PointLoad& load) {
  MMV_DEMAND(!finalized_);
  SimTK::Force::Custom(forces_, new PointLoadForce(matter_.getMobilizedBody(load.mobod), load.station_B, load.force_W));
  loads_.push_back(load);
}

void Model::addClosure(const Closure& c) {
  MMV_DEMAND(!finalized_);
  closures_.push_back(c);
}

SimTK::State Model::addClosureConstraints(const SimTK::State& at) {
  system_.realize(at, SimTK::Stage::Position);
  const SimTK::Vector q = at.getQ();
  for (const auto& c : closures_) {
    if (!c.points_a.empty()) {  // point A interpolated between mesh nodes
      addWeightedClosure(matter_, c, at);
      continue;
    }
    SimTK::MobilizedBody& a = matter_.updMobilizedBody(c.mobod_a);
    for (const SimTK::Vec3& e : c.directions) {
      if (c.to_ground) {
        SimTK::Constraint::PointInPlane(matter_.updGround(), SimTK::UnitVec3(e), ~e * c.anchor_W, a, c.station_a);
      } else {
        SimTK::MobilizedBody& b = matter_.updMobilizedBody(c.mobod_b);
        const SimTK::Vec3 n_B = ~b.getBodyRotation(at) * e;
        SimTK::Constraint::PointInPlane(b, SimTK::UnitVec3(n_B), ~n_B * c.station_b, a, c.station_a);
      }
    }
  }
  system_.realizeTopology();
  SimTK::State s = system_.getDefaultState();
  s.updQ() = q;
  s.updU() = 0;
  system_.realize(s, SimTK::Stage::Position);
  reference_state_ = s;
  system_.realize(reference_state_, SimTK::Stage::Position);
  return s;
}

int Model::getNumClosureRows() const {
  int n = 0;
  for (const auto& c : closures_) n += static_cast<int>(c.directions.size());
  return n;
}

int Model::findBody(SimTK::MobilizedBodyIndex mobod) const {
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].mobod == mobod) return static_cast<int>(b);
  return -1;
}

void Model::addPoint(const NamedPoint& p) { points_.push_back(p); }

const LinkAxis* Model::findLinkAxis(const std::string& link) const {
  for (const auto& a : link_axes_)
    if (a.link == link) return &a;
  return nullptr;
}

void Model::addReducedMotions() {
  MMV_DEMAND(!finalized_ && reduced_motions_.empty());
  std::vector<SimTK::MobilizedBodyIndex> free;
  for (const auto& c : coords_) {
    const auto& mb = matter_.getMobilizedBody(c.mobod);
    if (!mb.hasMotion() && std::find(free.begin(), free.end(), c.mobod) == free.end()) free.push_back(c.mobod);
  }
  reduced_motions_.addTo(matter_, free, static_cast<int>(coords_.size()));  // one u per coordinate (finalize checks)
}

void Model::setPrescribedMotion(SimTK::MobilizedBodyIndex mobod, PrescribedMotion motion) {
  prescribed_[mobod] = std::move(motion);
}

const PrescribedMotion* Model::findPrescribedMotion(SimTK::MobilizedBodyIndex mobod) const {
  const auto it = prescribed_.find(mobod);
  return it == prescribed_.end() ? nullptr : &it->second;
}

void Model::finalize() {
  MMV_DEMAND(!finalized_);
  system_.realizeTopology();
  SimTK::State s = system_.getDefaultState();
  system_.realizeModel(s);
  for (std::size_t i = 0; i < coords_.size(); ++i) {
    const auto& mb = matter_.getMobilizedBody(coords_[i].mobod);
    if (mb.getNumQ(s) != mb.getNumU(s) || coords_[i].mobilizer_q >= mb.getNumQ(s))
      throw InternalError("coordinate " + coords_[i].name + " does not match its mobilizer");
    qindex_.push_back(SimTK::QIndex(mb.getFirstQIndex(s) + coords_[i].mobilizer_q));
    uindex_.push_back(SimTK::UIndex(mb.getFirstUIndex(s) + coords_[i].mobilizer_q));
    if (!coords_[i].held) dofs_.push_back(static_cast<int>(i));
  }
  if (static_cast<int>(coords_.size()) != s.getNQ() || s.getNQ() != s.getNU())
    throw InternalError("model has mobilities that are not registered coordinates");
  for (std::size_t i = 0; i < coords_.size(); ++i) s.updQ()[qindex_[i]] = coords_[i].reference;
  system_.realize(s, SimTK::Stage::Position);
  reference_state_ = s;
  system_.realize(reference_state_, SimTK::Stage::Position);  // a copy's cache is not valid
  fitClosureCoordinates(s);
  for (auto& c : closures_) {
    if (c.to_ground && !c.has_anchor) {
      c.anchor_W = matter_.getMobilizedBody(c.mobod_a).findStationLocationInGround(s, c.station_a);
      c.has_anchor = true;
    }
  }
  // Ancestry: which coordinates move each body.
  // A planar mobilizer carries three coordinates; list them all, outboard-most first.
  coords_of_mobod_.assign(matter_.getNumBodies(), {});
  for (std::size_t i = 0; i < coords_.size(); ++i) coords_of_mobod_[coords_[i].mobod].push_back(static_cast<int>(i));
  parent_mobod_.assign(matter_.getNumBodies(), 0);  // Simbody's lookups once
  for (SimTK::MobilizedBodyIndex ix(1); ix < matter_.getNumBodies(); ++ix)
    parent_mobod_[ix] = matter_.getMobilizedBody(ix).getParentMobilizedBody().getMobilizedBodyIndex();
  coord_body_.assign(coords_.size(), -1);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (int c : coords_of_mobod_[bodies_[b].mobod]) coord_body_[c] = static_cast<int>(b);
  for (std::size_t i = 0; i < coords_.size(); ++i)
    if (coord_body_[i] < 0) throw InternalError("coordinate " + coords_[i].name + " moves no registered body");
  for (const auto& b : bodies_) {
    const double m = matter_.getMobilizedBody(b.mobod).getBodyMass(s);
    total_mass_ += m;
    if (!b.grounded) moving_mass_ += m;
  }
  finalized_ = true;
  for (auto& c : closures_)
    if (c.hold_z_if_free && pointMovesAlongZ(c)) c.directions.push_back(SimTK::Vec3(0, 0, 1));
}

void Model::fitClosureCoordinates(SimTK::State& s) {
  bool moved = false;
  for (const auto& c : closures_) {
    if (c.fit_coordinate < 0) continue;
    MMV_DEMAND(!c.to_ground && c.directions.size() == 1 && coords_[c.fit_coordinate].motion == CoordinateMotion::Translation);
    const SimTK::Vec3 pa = findWeightedLocation(s, c.pointsA());
    const SimTK::Vec3 pb = matter_.getMobilizedBody(c.mobod_b).findStationLocationInGround(s, c.station_b);
    coords_[c.fit_coordinate].reference += ~c.directions[0] * (pa - pb);
    s.updQ()[qindex_[c.fit_coordinate]] = coords_[c.fit_coordinate].reference;
    moved = true;
  }
  if (!moved) return;
  system_.realize(s, SimTK::Stage::Position);
  reference_state_ = s;
  system_.realize(reference_state_, SimTK::Stage::Position);
}

SimTK::Vec3 Model::findWeightedLocation(const SimTK::State& s, const std::vector<WeightedPoint>& points) const {
  SimTK::Vec3 p(0);
  for (const WeightedPoint& w : points) p += w.weight * matter_.getMobilizedBody(w.mobod).findStationLocationInGround(s, w.station_B);
  return p;
}

SimTK::Vec3 Model::findWeightedVelocity(const SimTK::State& s, const std::vector<WeightedPoint>& points) const {
  SimTK::Vec3 v(0);
  for (const WeightedPoint& w : points) v += w.weight * matter_.getMobilizedBody(w.mobod).findStationVelocityInGround(s, w.station_B);
  return v;
}

void Model::startClosureSpeeds(SimTK::State& s) const {
  system_.realize(s, SimTK::Stage::Time);
  system_.prescribeQ(s);
  system_.realize(s, SimTK::Stage::Position);
  system_.prescribeU(s);
  system_.realize(s, SimTK::Stage::Velocity);
  bool moved = false;
  for (const auto& c : closures_) {
    if (c.fit_coordinate < 0) continue;
    const SimTK::Vec3 va = findWeightedVelocity(s, c.pointsA());
    const SimTK::Vec3 vb = matter_.getMobilizedBody(c.mobod_b).findStationVelocityInGround(s, c.station_b);
    s.updU()[uindex_[c.fit_coordinate]] += ~c.directions[0] * (va - vb);
    moved = true;
  }
  if (moved) system_.realize(s, SimTK::Stage::Velocity);
}

bool Model::pointMovesAlongZ(const Closure& c) const {
  const std::vector<WeightedPoint> pa = c.pointsA();
  std::vector<SimTK::MobilizedBodyIndex> b;
  std::vector<SimTK::Vec3> st;
  for (const WeightedPoint& p : pa) b.push_back(p.mobod), st.push_back(p.station_B);
  if (!c.to_ground) {
    b.push_back(c.mobod_b);
    st.push_back(c.station_b);
  }
  const Eigen::MatrixXd J = calcFrameJacobians(reference_state_, b, st, dofs_);
  Eigen::RowVectorXd z = Eigen::RowVectorXd::Zero(J.cols());
  for (std::size_t i = 0; i < pa.size(); ++i) z += pa[i].weight * J.row(6 * static_cast<Eigen::Index>(i) + 5);
  if (!c.to_ground) z -= J.row(6 * static_cast<Eigen::Index>(pa.size()) + 5);
  // Planar pins move a point along z by exactly 0; a bending hinge out of the plane by
  // its lever arm (m/rad).
  return z.size() > 0 && z.cwiseAbs().maxCoeff() > 1e-12;
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
  MMV_DEMAND(q.size() == static_cast<Eigen::Index>(coords_.size()));
  for (std::size_t i = 0; i < coords_.size(); ++i) {
    s.updQ()[qindex_[i]] = q[i];
    s.updU()[uindex_[i]] = 0.0;
  }
}

std::vector<int> Model::getAncestorCoordinates(int b) const {
  std::vector<int> out;
  forEachAncestorCoordinate(b, [&](int c) { out.push_back(c); });
  return out;
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

Eigen::VectorXd Model::calcFrameVelocities(const SimTK::State& s, const std::vector<SimTK::MobilizedBodyIndex>& bodies,
                                           const std::vector<SimTK::Vec3>& stations, const std::vector<int>& cols,
                                           const Eigen::VectorXd& rates) const {
  MMV_DEMAND(bodies.size() == stations.size() && rates.size() == static_cast<Eigen::Index>(cols.size()));
  SimTK::Vector u(s.getNU(), 0.0);
  for (std::size_t j = 0; j < cols.size(); ++j) u[uindex_[cols[j]]] = rates[static_cast<Eigen::Index>(j)];
  SimTK::Vector_<SimTK::SpatialVec> V;  // per mobilized body: (w, v of its origin), world frame
  matter_.multiplyBySystemJacobian(s, u, V);
  Eigen::VectorXd out(6 * bodies.size());
  for (std::size_t t = 0; t < bodies.size(); ++t) {
    const SimTK::SpatialVec& Vb = V[bodies[t]];
    const SimTK::Vec3 r = matter_.getMobilizedBody(bodies[t]).getBodyRotation(s) * stations[t];
    const SimTK::Vec3 v = Vb[1] + Vb[0] % r;
    for (int k = 0; k < 3; ++k) {
      out[6 * t + k] = Vb[0][k];
      out[6 * t + 3 + k] = v[k];
    }
  }
  return out;
}

SimTK::Vec3 Model::findPointLocation(const SimTK::State& s, const NamedPoint& p) const {
  return matter_.getMobilizedBody(p.mobod).findStationLocationInGround(s, p.station_B);
}

}  // namespace mmv
