#pragma once
/// Linearization of a spatial rigid-body network (article/spatial_spec.hpp) about its
/// design configuration, which is made the static equilibrium under gravity by the
/// elements' preloads.
///
/// Coordinates: six per non-base body at its mass centre (x, y, z, rx, ry, rz), world
/// axes, rotations as a small rotation vector (orientation = exp([theta]) * design).
/// The stiffness is the Hessian of the potential energy in these coordinates, so it
/// carries the elements' preloads (the geometric stiffness that makes an inverted
/// pendulum soft and a hanging one stiff): for a point spring with force g (force on
/// body a, -g on b) at offset c from a body's mass centre, the rotation block gains
/// +-(1/2 (g c^T + c g^T) - (g.c) I); for an angular spring with moment m0 the
/// cross block gains -1/2 [m0]x.
///
/// Preloads: the design configuration is declared the equilibrium (the real isolator is
/// tuned to its working point). The force distribution among elements is the linear
/// elastic one: K_el u = f_gravity over the free coordinates, element forces from u.
/// With ideal ball joints the joints are constraints G q = 0 and their forces the
/// multipliers of the same problem; coordinates are then q = Z eta, Z = null(G).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "article/spatial_spec.hpp"
#include "sim/modes/modal.hpp"

namespace mmv {

struct SpatialElementStiffness {
  std::string name, group;
  Eigen::MatrixXd K;          ///< its elastic Hessian contribution over the free coordinates.
  Eigen::MatrixXd K_preload;  ///< the geometric contribution of its preload.
};

struct SpatialLinearization {
  int num_free = 0;                 ///< 6 x (bodies - 1).
  Eigen::MatrixXd M, K, C;          ///< over the free coordinates.
  Eigen::MatrixXd Kb, Cb;           ///< free x 6: coupling to the base's motion at the reference point.
  Eigen::MatrixXd Z;                ///< admissible coordinates q = Z eta (identity without constraints).
  Eigen::MatrixXd Mz, Kz, Cz;       ///< Z^T (.) Z.
  std::vector<SpatialElementStiffness> elements;
  std::vector<Eigen::Vector3d> spring_force;  ///< per point spring: the force it applies to body a (N).
  std::vector<Eigen::Vector3d> angular_moment;  ///< per angular spring: the moment on body a (N*m).
  double equilibrium_residual = 0;  ///< |sum of forces and moments| / total weight, at the design.
  bool ideal_joints = false;
  /// Ideal joints only: constraint equations implied by the others (a body on four rigid
  /// supports has one). Their forces are then statically indeterminate: the preload
  /// split is the least-norm one (the symmetric split for a symmetric structure).
  int redundant_constraints = 0;
  /// Rows of q (free coordinates) for a body's 6 coordinates start at 6 * (body - 1).
  static int row(int body) { return 6 * (body - 1); }
};

/// Throws NumericalError when gravity loads a mechanism (no equilibrium at the design).
SpatialLinearization linearizeSpatial(const SpatialSpec& spec, bool ideal_joints);

/// 3 x (6 n_bodies) Jacobian rows of a point fixed in body `body` at world position p,
/// over all bodies' coordinates (base included, at columns 0..5).
Eigen::MatrixXd spatialPointJacobian(const SpatialSpec& spec, int body, const Eigen::Vector3d& p);

/// Modes of the linearization (over eta), shapes mapped back to q.
ModalSolution spatialModes(const SpatialLinearization& lin);

/// Ground-to-body transmissibility at omega (rad/s): 6 x 6, columns the base's motion
/// (x, y, z at the reference point, rx, ry, rz), rows the output body's (x, y, z at its
/// mass centre, rx, ry, rz), displacement over displacement.
Eigen::MatrixXcd spatialTransmissibility(const SpatialSpec& spec, const SpatialLinearization& lin, double omega);

/// Sensor rows (sensors x free coordinates): the relative displacement along each
/// sensor's direction. The co-located actuators' input matrix is its transpose.
Eigen::MatrixXd spatialSensorMatrix(const SpatialSpec& spec);

}  // namespace mmv
