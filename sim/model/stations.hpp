#pragma once
/// Where a station (sim/scene/stations.hpp) is and how it moves: interpolated along its
/// link's mesh (Model::LinkAxis) with the beam's cubic Hermite shape functions,
///
///   p(xi) = H1 p_a + H2 l e_a + H3 p_b + H4 l e_b + offset y(xi) + offset_z n(xi),
///   H1 = 1 - 3 xi^2 + 2 xi^3, H2 = xi - 2 xi^2 + xi^3, H3 = 3 xi^2 - 2 xi^3, H4 = xi^3 - xi^2,
///
/// between the mesh nodes a and b around the station (root, hinges, tip; l their
/// distance along the undeformed link, xi = (x - x_a) / l), where p is a node's position
/// and e the link's direction there: a piece's body x axis, the mean of the two pieces
/// at a hinge; e(xi) = (1 - xi) e_a + xi e_b, and y(xi), n(xi) the pieces' body y (across
/// the section, in its plane) and z (the section's normal) axes interpolated alike, so an
/// offset point turns with the link's twist (on the planar model y = z x e). Velocity and acceleration are this
/// formula's exact time derivatives (e' = w x e, e'' = alpha x e + w x (w x e)), so a
/// station's energy and motion agree. A rigid link's two nodes carry one piece: the
/// station moves with it exactly. The interpolation error falls as O(h^2) with the
/// segment length h (tests/sim/model/stations_test.cpp).

#include <Eigen/Dense>
#include <Simbody.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/model/model.hpp"
#include "sim/scene/stations.hpp"

namespace mmv {

class StationPoint {
 public:
  /// `spec.link` must be a link of the model (the scene reader checked it).
  StationPoint(const Model& model, const StationSpec& spec);

  const StationSpec& spec() const { return spec_; }
  SimTK::Vec3 position(const SimTK::State& s) const;      ///< m, world; needs Stage::Position.
  SimTK::Vec3 velocity(const SimTK::State& s) const;      ///< m/s; needs Stage::Velocity.
  SimTK::Vec3 acceleration(const SimTK::State& s) const;  ///< m/s^2; needs Stage::Acceleration.
  /// The Hermite formula (above) as sum w_i p_i over body points (weights summing to 1): a
  /// node's point with H1 or H3, and each body axis term c e_k as c (p(e_k) - p(0)) on its
  /// piece (a body's axis is the difference of two of its points). A closure holds this
  /// sum (Closure::points_a): the shaker's stinger between mesh nodes.
  std::vector<WeightedPoint> weightedPoints() const;
  /// The unit direction along the link at the station (world).
  SimTK::Vec3 direction(const SimTK::State& s) const;
  /// The rotation rate about z (rad/s): the nodes' rates, interpolated linearly.
  double angularRate(const SimTK::State& s) const;
  /// The nodes' angular velocities (world), interpolated linearly.
  SimTK::Vec3 angularVelocity(const SimTK::State& s) const;
  /// The unit normal of the link's section plane: the nodes' pieces' z axes, averaged
  /// and interpolated like direction() (the plane's normal z on the planar model).
  SimTK::Vec3 normal(const SimTK::State& s) const;
  /// d p / d q for the coordinates `dofs`: rows x and y (m per unit coordinate), and z
  /// when rows = 3 (the spatial model).
  Eigen::MatrixXd translationJacobian(const SimTK::State& s, const std::vector<int>& dofs, int rows = 2) const;
  /// d w / d u for the coordinates `dofs` (3 rows: world x, y, z; rad per unit
  /// coordinate): angularVelocity()'s, the nodes' pieces' interpolated alike.
  Eigen::MatrixXd rotationJacobian(const SimTK::State& s, const std::vector<int>& dofs) const;

 private:
  struct Node {
    SimTK::MobilizedBodyIndex point_body, left, right;
    SimTK::Vec3 station_B;
  };
  using NodeVector = std::function<SimTK::Vec3(const Node&)>;
  /// A body's axis k (0 x, 1 y, 2 z) or its time derivative.
  using BodyVector = std::function<SimTK::Vec3(SimTK::MobilizedBodyIndex, int)>;
  /// The Hermite formula (above) for a node quantity (position, velocity or
  /// acceleration of its point) and the matching derivative of a piece's direction.
  SimTK::Vec3 interpolate(const NodeVector& point, const BodyVector& axis) const;
  const Model* model_;
  StationSpec spec_;
  Node a_, b_;
  double xi_ = 0, ell_ = 0;
};

/// A point an output, a sensor or a mode-shape table reads: a named point of the mesh
/// (`link1.tip`, `link1.h12`, `joint2`) or a station (`link1@0.75`).
class PointRef {
 public:
  /// Resolves `name`; on an unknown name returns nothing and sets `error` (one line
  /// that says how points and stations are named).
  static std::optional<PointRef> resolve(const Model& model, const ArticleSpec& article, const std::string& name,
                                         std::string& error);
  const std::string& name() const { return name_; }
  SimTK::Vec3 position(const SimTK::State& s) const;
  SimTK::Vec3 velocity(const SimTK::State& s) const;
  SimTK::Vec3 acceleration(const SimTK::State& s) const;
  double angularRate(const SimTK::State& s) const;
  /// The rotation rate (rad/s) about the point's local `axis` (localAxis): about z (2)
  /// is angularRate's; the spatial model's x (twist) and y (out-of-plane bending) too.
  double angularRate(const SimTK::State& s, int axis) const;
  /// Unit vectors of the point's local frame in the world: along the link (x, 0), across
  /// it in the plane of the link's section (y, 1) and along the section's normal (z, 2;
  /// the plane's normal on the planar model). Body-fixed: they twist with the link.
  SimTK::Vec3 localAxis(const SimTK::State& s, int axis) const;
  /// Rows x, y (and z when rows = 3).
  Eigen::MatrixXd translationJacobian(const SimTK::State& s, const std::vector<int>& dofs, int rows = 2) const;
  /// The angular velocity's rows (world x, y, z) per unit rate of `dofs`: the point's
  /// body's, or a station's interpolated one (StationPoint::rotationJacobian).
  Eigen::MatrixXd rotationJacobian(const SimTK::State& s, const std::vector<int>& dofs) const;

 private:
  PointRef(const Model& model, std::string name) : model_(&model), name_(std::move(name)) {}
  const Model* model_;
  std::string name_;
  const NamedPoint* point_ = nullptr;
  std::optional<StationPoint> station_;
};

/// A strain gauge's or film's mean surface strain over a span between stations A and B
/// of one link (sim/scene/stations.hpp StrainSpan; `c_over_span` = c / (x_B - x_A)):
///  - in the plane, on the section's +y face: eps = -c (theta_B - theta_A) / span, theta
///    the rotation about the section's normal (local z; world z on the planar model);
///  - out of the plane (spatial model), on the section's +z face: eps = +c (phi_B - phi_A)
///    / span, phi the rotation about local y (a positive phi tilts the link towards -z).
/// Per unit rate of `dofs` (a linear row, at `s`):
Eigen::RowVectorXd strainRow(const PointRef& a, const PointRef& b, const SimTK::State& s, const std::vector<int>& dofs,
                             double c_over_span, bool out_of_plane);
/// The same of a state, exact for any rotation: B's link direction in A's section frame,
/// its turn about A's local z (in the plane) or y (out of it).
double strainReading(const PointRef& a, const PointRef& b, const SimTK::State& s, double c_over_span, bool out_of_plane);

}  // namespace mmv
