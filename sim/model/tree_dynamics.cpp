#include "sim/model/tree_dynamics.hpp"

#include "sim/core/errors.hpp"

namespace mmv {

namespace {

/// The model's coordinate on each mobilized body (-1: none).
std::vector<int> coordinateOfBody(const Model& model) {
  std::vector<int> of(static_cast<std::size_t>(model.getMatter().getNumBodies()), -1);
  for (int i = 0; i < model.getNumCoordinates(); ++i) of[model.getCoordinates()[i].mobod] = i;
  return of;
}

}  // namespace

bool TreeDynamics::supports(const Model& model, std::string* why) {
  const auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (!model.hasClosedFormForces()) return no("its forces are not the declared inventory");
  if (!model.getRotationSprings().empty()) return no("its hinges have rotation springs (the spatial article)");
  if (!model.getClosures().empty()) return no("it has closures");
  const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
  const std::vector<int> coordinate = coordinateOfBody(model);
  for (int b = 1; b < matter.getNumBodies(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(SimTK::MobilizedBodyIndex(b));
    const bool one = coordinate[b] >= 0 && model.getCoordinates()[coordinate[b]].mobilizer_q == 0;
    if (SimTK::MobilizedBody::Weld::isInstanceOf(mb) && coordinate[b] < 0) continue;
    if ((SimTK::MobilizedBody::Pin::isInstanceOf(mb) || SimTK::MobilizedBody::Slider::isInstanceOf(mb)) && one) continue;
    return no("body " + std::to_string(b) + "'s mobilizer is not a pin, a slider or a weld");
  }
  return true;
}

TreeDynamics::TreeDynamics(const Model& model, const SimTK::State& s) : model_(model), gravity_(model.getGravity(s)) {
  std::string why;
  if (!supports(model, &why)) throw InternalError("TreeDynamics: the model is not one it writes out: " + why);
  const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
  const std::vector<int> coordinate = coordinateOfBody(model);
  bodies_.resize(static_cast<std::size_t>(matter.getNumBodies()));
  Body& ground = bodies_[0];  // at rest (SimTK's vectors start as NaN in a debug build)
  ground.w = ground.alpha = ground.v = ground.a = ground.force = ground.moment = SimTK::Vec3(0);
  for (int b = 1; b < matter.getNumBodies(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(SimTK::MobilizedBodyIndex(b));
    Body& body = bodies_[static_cast<std::size_t>(b)];
    body.joint = SimTK::MobilizedBody::Pin::isInstanceOf(mb)      ? Joint::Pin
                 : SimTK::MobilizedBody::Slider::isInstanceOf(mb) ? Joint::Slider
                                                                  : Joint::Weld;
    body.parent = mb.getParentMobilizedBody().getMobilizedBodyIndex();
    body.coordinate = coordinate[b];
    body.X_PF = mb.getInboardFrame(s);
    body.X_MB = ~mb.getOutboardFrame(s);
    const SimTK::MassProperties& mp = mb.getBodyMassProperties(s);
    body.mass = mp.getMass();
    body.com_B = mp.getMassCenter();
    body.central = mp.calcCentralInertia();
  }
  for (const PointLoad& l : model.getPointLoads())
    bodies_[static_cast<std::size_t>(l.mobod)].loads.push_back({l.station_B, l.force_W});
}

void TreeDynamics::residual(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& u, const Eigen::VectorXd& udot,
                            Eigen::VectorXd& r) const {
  outward(q, u, udot);
  inward(r);
  // The coordinates' own forces: springs, dampers, torque programs, the damping matrix.
  for (int i = 0; i < model_.getNumCoordinates(); ++i) {
    const Coordinate& c = model_.getCoordinates()[i];
    if (c.stiffness > 0) r[i] += c.stiffness * (q[i] - c.reference);
    if (c.damping > 0) r[i] += c.damping * u[i];
    if (c.input) r[i] -= c.input->position(t);
  }
  const Eigen::MatrixXd& C = model_.getLinearDamping();
  if (C.size() > 0) {
    const std::vector<int>& coords = model_.getLinearDampingCoordinates();
    damped_u_.resize(static_cast<Eigen::Index>(coords.size()));
    for (std::size_t a = 0; a < coords.size(); ++a) damped_u_[static_cast<Eigen::Index>(a)] = u[coords[a]];
    damped_f_.noalias() = C * damped_u_;
    for (std::size_t a = 0; a < coords.size(); ++a) r[coords[a]] += damped_f_[static_cast<Eigen::Index>(a)];
  }
}

void TreeDynamics::outward(const Eigen::VectorXd& q, const Eigen::VectorXd& u, const Eigen::VectorXd& udot) const {
  for (int b = 1; b < numBodies(); ++b) {
    Body& B = bodies_[static_cast<std::size_t>(b)];
    const Body& P = bodies_[static_cast<std::size_t>(B.parent)];
    const SimTK::Transform X_GF = P.X_GB * B.X_PF;
    const int i = B.coordinate;
    B.joint_point = X_GF.p();
    B.w = P.w, B.alpha = P.alpha;
    if (B.joint == Joint::Pin) {
      B.axis = SimTK::Vec3(X_GF.z());
      B.X_GB = X_GF * SimTK::Transform(SimTK::Rotation(q[i], SimTK::ZAxis)) * B.X_MB;
      const SimTK::Vec3 e = B.joint_point - P.X_GB.p();  // the joint's point, fixed in the parent
      const SimTK::Vec3 v_o = P.v + P.w % e, a_o = P.a + P.alpha % e + P.w % (P.w % e);
      B.w += u[i] * B.axis;
      B.alpha += udot[i] * B.axis + P.w % (u[i] * B.axis);
      const SimTK::Vec3 rb = B.X_GB.p() - B.joint_point;  // fixed in the body
      B.v = v_o + B.w % rb;
      B.a = a_o + B.alpha % rb + B.w % (B.w % rb);
      continue;
    }
    SimTK::Transform X_GM = X_GF;
    if (B.joint == Joint::Slider) {
      B.axis = SimTK::Vec3(X_GF.x());
      X_GM.updP() += q[i] * B.axis;
    }
    B.X_GB = X_GM * B.X_MB;
    const SimTK::Vec3 e = B.X_GB.p() - P.X_GB.p();
    B.v = P.v + P.w % e;
    B.a = P.a + P.alpha % e + P.w % (P.w % e);
    if (B.joint == Joint::Slider) {
      B.v += u[i] * B.axis;
      B.a += udot[i] * B.axis + 2.0 * (P.w % (u[i] * B.axis));
    }
  }
}

void TreeDynamics::inward(Eigen::VectorXd& r) const {
  const int nb = numBodies();
  r.setZero(model_.getNumCoordinates());
  for (int b = nb - 1; b >= 1; --b) {
    Body& B = bodies_[static_cast<std::size_t>(b)];
    B.force = SimTK::Vec3(0);
    B.moment = SimTK::Vec3(0);
    if (B.mass > 0) {
      const SimTK::Rotation& R = B.X_GB.R();
      const SimTK::Vec3 rc = R * B.com_B, c = B.X_GB.p() + rc;
      const SimTK::Vec3 a_c = B.a + B.alpha % rc + B.w % (B.w % rc);
      const SimTK::Mat33 I = R * B.central.toMat33() * ~R;
      B.force = B.mass * (a_c - gravity_);
      B.moment = I * B.alpha + B.w % (I * B.w) + c % B.force;
    }
    for (const auto& [station, f] : B.loads) {
      B.force -= f;
      B.moment -= B.X_GB.shiftFrameStationToBase(station) % f;
    }
  }
  for (int b = nb - 1; b >= 1; --b) {
    Body& B = bodies_[static_cast<std::size_t>(b)];
    if (B.joint == Joint::Pin) r[B.coordinate] = ~B.axis * (B.moment - B.joint_point % B.force);
    if (B.joint == Joint::Slider) r[B.coordinate] = ~B.axis * B.force;
    if (B.parent > 0) {
      bodies_[static_cast<std::size_t>(B.parent)].force += B.force;
      bodies_[static_cast<std::size_t>(B.parent)].moment += B.moment;
    }
  }
}

}  // namespace mmv
