#pragma once
/// A spatial (3-D) network of rigid bodies joined by point springs and angular
/// springs: the form the HAM-SAS isolator takes (article/hamsas.hpp), as plain data.
///
/// Conventions: SI units, world frame with z up, every body's axes aligned with the
/// world at the design configuration (so inertias are given in world axes). Body 0 is
/// the base: its motion is prescribed (the ground excitation), it has no coordinates.
/// Each other body has six coordinates at its mass centre: translation (x, y, z) and a
/// small rotation vector (rx, ry, rz), world axes.

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace mmv {

struct SpatialBody {
  std::string name;
  std::string group;  ///< for reports: "base", "ot", "sb", "ip_leg", "lp" ...
  double mass = 0;    ///< kg.
  Eigen::Vector3d com = Eigen::Vector3d::Zero();              ///< m, world.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();          ///< kg*m^2 about the mass centre, world axes.
};

/// A zero-length 3-D linear spring (and viscous damper) between a point of body a and
/// a point of body b that coincide at the design configuration: force on b
/// -K (p_b - p_a - d0), K = diag(stiffness) in world axes. The offset d0 is chosen so
/// that the design configuration is the static equilibrium (the element's preload).
/// `joint`: an effective spherical joint (the authors' 1e8 N/m springs); these may be
/// replaced by ideal ball joints (constraints).
struct PointSpring {
  std::string name;
  std::string group;  ///< element class in reports: "joint", "mgas" ...
  int a = 0, b = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< m, world (the same point on both bodies).
  Eigen::Vector3d stiffness = Eigen::Vector3d::Zero();  ///< N/m along x, y, z.
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();    ///< N*s/m.
  bool joint = false;
};

/// An angular spring (and damper) between bodies a and b: moment on b
/// -K (phi - phi0), phi the relative rotation vector, K = diag(stiffness) in world axes.
struct AngularSpring {
  std::string name;
  std::string group;  ///< "flex_joint", "lp_torsion" ...
  int a = 0, b = 0;
  Eigen::Vector3d stiffness = Eigen::Vector3d::Zero();  ///< N*m/rad about x, y, z.
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();    ///< N*m*s/rad.
};

/// A displacement sensor measuring body b's point relative to body a's coincident point
/// along a unit direction (and a co-located force actuator pushing b along it, a back).
struct RelativeSensor {
  std::string name;
  int a = 0, b = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

struct SpatialSpec {
  std::vector<SpatialBody> bodies;  ///< [0] is the base.
  std::vector<PointSpring> springs;
  std::vector<AngularSpring> angular;
  std::vector<RelativeSensor> sensors;
  Eigen::Vector3d gravity{0, 0, -9.80665};
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  ///< the base point whose motion is the ground input.
  int output_body = 1;  ///< the body whose motion is the transmissibility output (the optical table).
  int bodyIndex(const std::string& name) const;
};

/// The sides (m, world axes) of the uniform box with the body's mass and principal
/// moments, s_k^2 = 6 (I_1 + I_2 + I_3 - 2 I_k) / m, at least 2 cm: how renders draw
/// the body, and where sensor candidates sit on it (its centre and corners).
inline Eigen::Vector3d equivalentBox(const SpatialBody& b) {
  const Eigen::Vector3d I = b.inertia.diagonal();
  Eigen::Vector3d side;
  for (int k = 0; k < 3; ++k) {
    const double s2 = b.mass > 0 ? 6 * (I.sum() - 2 * I[k]) / b.mass : 0.0;
    side[k] = std::max(std::sqrt(std::max(s2, 0.0)), 0.02);
  }
  return side;
}

}  // namespace mmv
