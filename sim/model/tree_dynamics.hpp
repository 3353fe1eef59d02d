#pragma once
/// The inverse dynamics of a Model whose mobilizers are pins, sliders and welds (the
/// planar article on its base, table or gimbal), written out for the time runs in
/// reduced coordinates (sim/time/modal_links.hpp): one pass outward for the bodies'
/// positions, velocities and accelerations, one inward for the forces, O(bodies), with
/// the Model's force inventory (uniform gravity, point loads, the coordinates' springs,
/// dampers and torque programs, the linear damping matrix). It computes what Simbody's
/// SimbodyMatterSubsystem::calcResidualForceIgnoringConstraints computes from a State
/// realized to Dynamics, M udot + c - f, without the State's stage machinery, cached
/// values and force elements, which were most of a reduced run's cost (issue 37, item
/// 5). Tests hold the two to 1e-10 on every shipped scene the class takes.
///
/// Each pin turns about its inboard frame's z axis, each slider moves along its inboard
/// frame's x axis (Simbody's conventions); a Model with any other mobilizer (the floating
/// root's planar joint, the spatial article's gimbals and bushings), rotation springs,
/// closures or forces beyond its declared inventory is refused with the reason.

#include <Simbody.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "sim/model/model.hpp"

namespace mmv {

class TreeDynamics {
 public:
  /// Whether `model` holds only what this class writes out; else false with `why` set.
  static bool supports(const Model& model, std::string* why = nullptr);

  /// The bodies' frames, masses and inertias from `s` (realized to Instance at least)
  /// and gravity there. Throws InternalError for a model supports() refuses.
  TreeDynamics(const Model& model, const SimTK::State& s);

  /// r = M udot + c - f over the model's coordinates (index i: coordinate i, one q and
  /// one u each) at time t; the linear damping matrix as the model holds it now.
  void residual(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& u, const Eigen::VectorXd& udot,
                Eigen::VectorXd& r) const;

  /// After residual(): body b's (MobilizedBodyIndex) transform in ground.
  const SimTK::Transform& bodyTransform(int b) const { return bodies_[static_cast<std::size_t>(b)].X_GB; }
  int numBodies() const { return static_cast<int>(bodies_.size()); }

 private:
  /// Each body's frame, velocity and acceleration from its parent's, root to leaves.
  void outward(const Eigen::VectorXd& q, const Eigen::VectorXd& u, const Eigen::VectorXd& udot) const;
  /// Each subtree's inertial minus applied force and its moment about ground's origin,
  /// leaves to root: a pin's residual is the moment about its axis through its point, a
  /// slider's the force along it.
  void inward(Eigen::VectorXd& r) const;

  enum class Joint { Weld, Pin, Slider };
  struct Body {
    Joint joint = Joint::Weld;
    int parent = 0;
    int coordinate = -1;  ///< the model's coordinate for a pin or slider
    SimTK::Transform X_PF, X_MB;  ///< inboard frame on the parent; the body frame on the outboard frame (~X_BM)
    double mass = 0;
    SimTK::Vec3 com_B;
    SimTK::Inertia central;  ///< about the mass centre, body frame
    std::vector<std::pair<SimTK::Vec3, SimTK::Vec3>> loads;  ///< point loads: station (body), force (ground)
    // Per evaluation:
    SimTK::Transform X_GB;
    SimTK::Vec3 w, alpha, v, a;  ///< angular velocity and acceleration, the origin's velocity and acceleration
    SimTK::Vec3 axis, joint_point;  ///< ground: a pin's axis or a slider's direction, the inboard frame's origin
    SimTK::Vec3 force, moment;      ///< the subtree's inertial minus applied force, and its moment about ground's origin
  };
  const Model& model_;
  SimTK::Vec3 gravity_;
  mutable std::vector<Body> bodies_;
  mutable Eigen::VectorXd damped_u_, damped_f_;  ///< the damping matrix's speeds and forces (no allocation a call)
};

}  // namespace mmv
