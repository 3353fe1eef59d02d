#pragma once
/// The Simbody model of a scene plus the names the analyses and reports need:
/// generalized coordinates (what each one is, whether it is held), the parts bodies
/// belong to, and named points. Built by sim/model/article_builder.hpp.
///
/// Mobilizers are planar pins about world z, welds, (for a floating root) planar
/// joints: rotation about z then translations along the ground frame's x and y, or (the
/// spatial article's hinges) gimbals: body-fixed x-y-z rotations. For all of them
/// q' = u, so coordinate i has one q and one u.
/// Units: angles in rad, torques in N*m, lengths in m, masses in kg.
///
/// A Model is built once and then used read-only (const); analyses work on their own
/// SimTK::State copies (Simbody's "const system, mutable state" pattern).

#include <Simbody.h>

#include <Eigen/Dense>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facility/table_programs.hpp"
#include "sim/model/motions.hpp"
#include "sim/model/reduced_motions.hpp"
#include "sim/model/rotation_spring.hpp"

namespace mmv {

enum class CoordinateKind {
  Joint,  ///< an article joint (torquer axis).
  Hinge,  ///< a bending hinge inside a flexible link.
};

enum class CoordinateMotion {
  Rotation,     ///< about an axis through the body origin: world z, or (spatial hinges) the gimbal's axis (rad).
  Translation,  ///< along a ground-fixed direction (m).
};

/// What a hinge coordinate bends (the spatial model has all three; the planar one only
/// InPlane). Joint coordinates count as InPlane.
enum class HingeAxis {
  InPlane,     ///< about z: bending in the plane of motion.
  OutOfPlane,  ///< about the link's in-plane normal: bending out of the plane.
  Torsion,     ///< about the link: twist.
};

struct Coordinate {
  std::string name;  ///< "joint2" or "link1.h3".
  CoordinateKind kind = CoordinateKind::Hinge;
  CoordinateMotion motion = CoordinateMotion::Rotation;
  int mobilizer_q = 0;  ///< which q of its mobilizer (0 for pins).
  HingeAxis axis = HingeAxis::InPlane;
  std::string part;  ///< the link (hinge) or joint (joint) it belongs to.
  SimTK::MobilizedBodyIndex mobod;
  double reference = 0;  ///< rad: commanded joint angle, or 0 for an unbent hinge.
  bool held = false;     ///< locked by its torquer: not a degree of freedom.
  double stiffness = 0;  ///< N*m/rad of the linear spring on this coordinate (0: none).
  double damping = 0;    ///< N*m*s/rad of a viscous damper on it (0: none); no static effect.
  /// A commanded torque on a free or servo joint (N*m over time; time runs; in statics
  /// and modes its value at t = 0, a dead load with no stiffness).
  std::shared_ptr<const facility::TableProgram> input;
};

/// A translation along a slider of part `part` (the table's axes, the shaker's armature):
/// a joint coordinate in metres, free unless the caller holds it.
inline Coordinate sliderCoordinate(const std::string& name, const std::string& part, SimTK::MobilizedBodyIndex mobod) {
  Coordinate c;
  c.name = name;
  c.kind = CoordinateKind::Joint;
  c.motion = CoordinateMotion::Translation;
  c.part = part;
  c.mobod = mobod;
  return c;
}

/// A part: a link (all its pieces), a torquer, a tip mass, or the excitation table.
struct Part {
  std::string name;
  /// Shaker: the extra shaker's armature (time runs with a force program only).
  enum class Kind { Link, Torquer, TipMass, Table, Gimbal, Shaker } kind = Kind::Link;
  /// The link that carries this part: itself for a link, the link a tip mass is on,
  /// the parent link whose tip holds a torquer; empty for a torquer on the base.
  std::string carrier;
};

struct BodyInfo {
  SimTK::MobilizedBodyIndex mobod;
  int part = -1;  ///< index into Model::parts().
  bool grounded = false;  ///< welded to ground: never moves.
};

/// A constant force (dead load) at a station of a body, in the world frame.
struct PointLoad {
  SimTK::MobilizedBodyIndex mobod;
  SimTK::Vec3 station_B;  ///< m, body frame.
  SimTK::Vec3 force_W;    ///< N, world frame.
};

/// A point of a body weighted in a sum: a closure's point A interpolated between mesh
/// nodes is sum w_i p_i over a few of them (sim/model/stations.hpp, StationPoint::
/// weightedPoints), the weights summing to 1.
struct WeightedPoint {
  SimTK::MobilizedBodyIndex mobod;
  SimTK::Vec3 station_B;
  double weight = 1;
};

/// A loop closure: point A (on the article) held to a ground anchor or to point B,
/// in both in-plane directions (pin) or across a line (slider). Its rows are the
/// world directions e_r it holds: constraint e_r . (p_A - p_B) = 0.
struct Closure {
  std::string name;
  std::string where;  ///< "file:line:col" of its scene entry.
  SimTK::MobilizedBodyIndex mobod_a;
  SimTK::Vec3 station_a;
  bool to_ground = true;
  SimTK::MobilizedBodyIndex mobod_b;  ///< when !to_ground.
  SimTK::Vec3 station_b;
  bool has_anchor = false;  ///< else the anchor is A's reference location (set by finalize).
  SimTK::Vec3 anchor_W;     ///< m, when to_ground.
  std::vector<SimTK::Vec3> directions;  ///< unit world directions held (2 for a pin, 1 for a slider).
  /// The spatial model: finalize also holds the point along world z when a free
  /// coordinate can move it there (along z where nothing moves it, it holds nothing).
  bool hold_z_if_free = false;
  /// >= 0: a coordinate that moves point B along the closure's one direction (a slider
  /// along it, m): finalize sets its reference so that the closure holds in the
  /// reference state (the shaker's armature, placed where the stinger meets the article).
  int fit_coordinate = -1;
  /// Non-empty: point A is sum w_i p_i of these (a station interpolated between the mesh
  /// nodes, as the linear models take it), not mobod_a's station_a; only with !to_ground,
  /// one direction, and a point B whose body does not turn (the shaker's armature).
  std::vector<WeightedPoint> points_a;
  /// Point A's weighted points: points_a, or station_a of mobod_a with weight 1.
  std::vector<WeightedPoint> pointsA() const {
    return points_a.empty() ? std::vector<WeightedPoint>{{mobod_a, station_a, 1.0}} : points_a;
  }
};

/// A named point fixed on a body: "link1.tip", "link2.h3", "joint2", ...
struct NamedPoint {
  std::string name;
  SimTK::MobilizedBodyIndex mobod;
  SimTK::Vec3 station_B;  ///< position from the body origin, in the body frame (m).
  bool report_rotation = false;  ///< rotation is meaningful here (roots, tips, joints).
};

/// The mesh points along one link, root to tip, and where they sit on the undeformed
/// link: what a station (sim/model/stations.hpp) is interpolated from. Node k's point
/// is getPoints()[points[k]]; the link lies along the +x axis of each piece's body
/// frame; a hinge node joins the pieces of its neighbours (`left`, `right`; equal at
/// the root and the tip).
struct LinkAxis {
  std::string link;
  double length = 0;  ///< m.
  std::vector<double> x;  ///< m from the root, increasing: 0, hinges, length.
  std::vector<int> points;
  std::vector<SimTK::MobilizedBodyIndex> left, right;
  /// The last node at or before x (m from the root): right[k] is the piece x lies on,
  /// at x - this->x[k] along its frame's x axis (a piece's frame starts at its node).
  std::size_t nodeBefore(double at) const {
    std::size_t k = 0;
    while (k + 2 < x.size() && x[k + 1] <= at) ++k;
    return k;
  }
};

class Model {
 public:
  /// Creates an empty system with uniform gravity g_W (m/s^2, world frame).
  explicit Model(const SimTK::Vec3& g_W);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // --- building (used by builders only) ---------------------------------------
  SimTK::MultibodySystem& updSystem() { return system_; }
  SimTK::SimbodyMatterSubsystem& updMatter() { return matter_; }
  SimTK::GeneralForceSubsystem& updForces() { return forces_; }
  int addPart(const std::string& name, Part::Kind kind, const std::string& carrier);
  void addBody(SimTK::MobilizedBodyIndex mobod, int part, bool grounded);
  /// Registers a coordinate; adds a linear spring if stiffness > 0 and a viscous
  /// damper if damping > 0.
  void addCoordinate(const Coordinate& c);
  /// Registers a spatial hinge's three coordinates (its gimbal's x, y, z angles, in that
  /// order) with one spring on their rotation vector (sim/model/rotation_spring.hpp; each
  /// coordinate's stiffness is its axis's k) in place of a linear spring per angle;
  /// dampers as addCoordinate.
  void addHingeRotation(const std::array<Coordinate, 3>& c);
  /// The springs addHingeRotation installed.
  const std::vector<RotationSpring>& getRotationSprings() const { return *rotation_springs_; }
  /// Installs a viscous damping force f = -C u over a set of coordinates (the scene's
  /// modal or Rayleigh damping in time runs: sim/statics/damping_matrix.hpp); its
  /// matrix is set later by setLinearDamping, once the equilibrium it is formed at is
  /// known (until then the force is zero). Call before finalize. The force vanishes at
  /// rest, so statics and stiffness (closed form included) are unaffected.
  void addLinearDamper();
  struct LinearDamping;  ///< its data, shared with the Simbody force element (model.cpp).
  bool hasLinearDamper() const { return linear_damper_ != nullptr; }
  /// C (symmetric, over `coords`, coordinate indices) of the force addLinearDamper
  /// installed. Changes no Simbody topology: states made before stay valid, but a state
  /// realized to Dynamics before this call must be realized again.
  void setLinearDamping(const std::vector<int>& coords, const Eigen::MatrixXd& C);
  /// The matrix set (empty before setLinearDamping) and its coordinates.
  const Eigen::MatrixXd& getLinearDamping() const;
  const std::vector<int>& getLinearDampingCoordinates() const;
  /// Power dissipated by every viscous damper, sum c_i u_i^2 + u^T C u (W).
  double calcDissipation(const SimTK::State& s) const;
  /// Power the coordinates' commanded torques deliver, sum tau(t) u (W).
  double inputPower(const SimTK::State& s) const;
  void addPoint(const NamedPoint& p);
  void addLinkAxis(const LinkAxis& axis) { link_axes_.push_back(axis); }
  /// Adds a dead load (a constant force with its potential energy, so time runs' energy
  /// balance counts its work) and records it for stiffness.
  void addPointLoad(const PointLoad& load);
  void addClosure(const Closure& c);
  /// Declares that the only forces are uniform gravity, point loads, the coordinates'
  /// linear springs and the hinges' rotation springs, so the closed-form stiffness of sim/statics/linearize.hpp
  /// applies. Builders that add other forces must not call this.
  void setClosedFormForces() { closed_form_forces_ = true; }
  /// Declares rotations about axes other than world z (the spatial article's Gimbal
  /// hinges): the closed-form stiffness then uses every rotation's own axis.
  void setSpatial() { spatial_ = true; }
  /// Time runs in reduced coordinates (sim/time/modal_links.hpp): gives every mobilizer
  /// no Motion drives an acceleration-level one, disabled by default
  /// (sim/model/reduced_motions.hpp). Call before finalize.
  void addReducedMotions();
  /// The motion a one-coordinate mobilizer's Motion prescribes (the builder registers
  /// each Motion's; runs in reduced coordinates use them).
  void setPrescribedMotion(SimTK::MobilizedBodyIndex mobod, PrescribedMotion motion);
  /// Registered for `mobod`, or null.
  const PrescribedMotion* findPrescribedMotion(SimTK::MobilizedBodyIndex mobod) const;
  const ReducedMotions& getReducedMotions() const { return reduced_motions_; }
  /// Realizes topology and builds the reference state. Call once, last.
  void finalize();
  /// Time runs of closed trees: makes every closure a Simbody constraint (a
  /// PointInPlane per held direction; for a closure between two bodies the directions
  /// turn with the second body, as they stand in `at`) so the dynamics hold it. Changes
  /// the topology: states made before are invalid; returns a new state with `at`'s q.
  /// Statics, linearization and modes keep their own treatment of closures.
  SimTK::State addClosureConstraints(const SimTK::State& at);
  /// A time run's start in `s` (time set): the prescribed speeds (a table's program may
  /// start moving), then each fitted coordinate's speed (the shaker's armature) set so that
  /// its closure's point moves with its partner's along the held direction. Without it a
  /// table starting in motion left the armature at rest against a moving stinger: Simbody's
  /// integrators projected the mismatch onto the article (a kick of about 1 mm/s) and
  /// SUNDIALS' drifted off the closure (11 mm over 2 s).
  void startClosureSpeeds(SimTK::State& s) const;

  // --- use ----------------------------------------------------------------------
  const SimTK::MultibodySystem& getSystem() const { return system_; }
  const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }
  const SimTK::Vec3& getGravity() const { return gravity_W_; }
  /// Gravity in state `s` (the scene's, times any continuation scale), m/s^2.
  SimTK::Vec3 getGravity(const SimTK::State& s) const;
  const std::vector<Coordinate>& getCoordinates() const { return coords_; }
  const std::vector<Part>& getParts() const { return parts_; }
  const std::vector<BodyInfo>& getBodies() const { return bodies_; }
  const std::vector<NamedPoint>& getPoints() const { return points_; }
  /// The axis of link `link`, or nullptr.
  const LinkAxis* findLinkAxis(const std::string& link) const;
  const std::vector<PointLoad>& getPointLoads() const { return loads_; }
  const std::vector<Closure>& getClosures() const { return closures_; }
  /// Total number of closure constraint rows.
  int getNumClosureRows() const;
  /// Indices of the coordinates that are degrees of freedom (not held).
  const std::vector<int>& getDofs() const { return dofs_; }
  /// Index of coordinate i's speed in the Simbody state's u vector.
  int getUIndex(int i) const { return uindex_[i]; }
  /// Index of coordinate i in the Simbody state's q vector.
  int getQIndex(int i) const { return qindex_[i]; }
  int getNumCoordinates() const { return static_cast<int>(coords_.size()); }
  /// The state with every coordinate at its reference value, realized to Position.
  const SimTK::State& getReferenceState() const { return reference_state_; }
  /// Total mass of all bodies, and of those that can move (not welded to ground), kg.
  double getTotalMass() const { return total_mass_; }
  double getMovingMass() const { return moving_mass_; }
  const NamedPoint* findPoint(const std::string& name) const;
  int findBody(SimTK::MobilizedBodyIndex mobod) const;  ///< index into getBodies(), -1 if none.
  bool hasClosedFormForces() const { return closed_form_forces_; }
  bool isSpatial() const { return spatial_; }
  /// Coordinates whose motion moves body b (index into getBodies()): its own
  /// mobilizer's coordinate, if any, and those of all its ancestors.
  /// Made on each call (O(depth)): the model stores only each mobilizer's parent.
  std::vector<int> getAncestorCoordinates(int b) const;
  /// f(c) for each of getAncestorCoordinates(b), in that order, with no list made.
  template <class F>
  void forEachAncestorCoordinate(int b, F&& f) const {
    for (int ix = bodies_[b].mobod; ix != SimTK::GroundIndex; ix = parent_mobod_[ix])
      for (int c : coords_of_mobod_[ix]) f(c);
  }
  /// Index into getBodies() of the body that coordinate c's pin moves.
  int getCoordinateBody(int c) const { return coord_body_[c]; }

  /// sum w_i p_i (m, world; Stage::Position) and its velocity (Stage::Velocity).
  SimTK::Vec3 findWeightedLocation(const SimTK::State& s, const std::vector<WeightedPoint>& points) const;
  SimTK::Vec3 findWeightedVelocity(const SimTK::State& s, const std::vector<WeightedPoint>& points) const;

  /// Coordinate values of a state, in coordinate order (rad).
  Eigen::VectorXd getQ(const SimTK::State& s) const;
  /// Sets coordinate values (rad) and zero speeds.
  void setQ(SimTK::State& s, const Eigen::VectorXd& q) const;

  /// Applied generalized forces f(q) in N*m (gravity + springs) at zero speed:
  /// the right-hand side of M q'' = f. Realizes `s` to Dynamics.
  Eigen::VectorXd calcAppliedForces(SimTK::State& s) const;

  /// Frame Jacobians of frames at `stations` (body frame, m) on `bodies`, restricted to
  /// the columns of coordinates `cols`: rows 6t..6t+2 angular velocity (rad/s per unit
  /// coordinate rate), rows 6t+3..6t+5 the station's linear velocity (m/s), world frame.
  Eigen::MatrixXd calcFrameJacobians(const SimTK::State& s, const std::vector<SimTK::MobilizedBodyIndex>& bodies,
                                     const std::vector<SimTK::Vec3>& stations, const std::vector<int>& cols) const;
  /// sum over getBodies() of m_b J_b^T e_a (J_b: the translation Jacobian of b's mass
  /// centre over `cols`), for world axes a = x, y, z: the generalized force per unit of a
  /// uniform acceleration field (the base's coupling), cols x 3. One pass: each body's
  /// mass and first moment summed into its subtree, then each mobility's hinge column.
  Eigen::MatrixXd calcMassCentreCoupling(const SimTK::State& s, const std::vector<int>& cols) const;
  /// calcFrameJacobians(s, bodies, stations, cols) * rates, without the Jacobian: one
  /// O(bodies) pass for rates over `cols` (what a mode shape moves), same row layout.
  Eigen::VectorXd calcFrameVelocities(const SimTK::State& s, const std::vector<SimTK::MobilizedBodyIndex>& bodies,
                                      const std::vector<SimTK::Vec3>& stations, const std::vector<int>& cols,
                                      const Eigen::VectorXd& rates) const;

  /// Scales gravity in state `s` (1 = the scene's g): for load continuation.
  void setGravityScale(SimTK::State& s, double scale) const;

  /// Position of a named point in the world frame (m); `s` realized to Position.
  SimTK::Vec3 findPointLocation(const SimTK::State& s, const NamedPoint& p) const;

 private:
  /// Whether a free coordinate moves closure c's point (relative to its partner) along z.
  bool pointMovesAlongZ(const Closure& c) const;
  /// Sets each closure's fit_coordinate so that its closure holds in `s` (the reference state),
  /// then makes `s` the reference state again.
  void fitClosureCoordinates(SimTK::State& s);
  /// addCoordinate without the spring.
  void registerCoordinate(const Coordinate& c);
  SimTK::MultibodySystem system_;
  SimTK::SimbodyMatterSubsystem matter_;
  SimTK::GeneralForceSubsystem forces_;
  SimTK::Vec3 gravity_W_;
  SimTK::Force::Gravity gravity_;
  std::vector<Coordinate> coords_;
  std::vector<SimTK::QIndex> qindex_;
  std::vector<SimTK::UIndex> uindex_;
  std::vector<Part> parts_;
  std::vector<BodyInfo> bodies_;
  std::vector<NamedPoint> points_;
  std::vector<LinkAxis> link_axes_;
  std::vector<PointLoad> loads_;
  std::vector<Closure> closures_;
  std::vector<int> dofs_;
  SimTK::State reference_state_;
  double total_mass_ = 0, moving_mass_ = 0;
  std::vector<std::vector<int>> coords_of_mobod_;  ///< per mobilized body, its coordinates.
  std::vector<int> parent_mobod_;                  ///< per mobilized body, its parent's index.
  std::vector<int> coord_body_;
  bool closed_form_forces_ = false;
  bool spatial_ = false;
  bool finalized_ = false;
  ReducedMotions reduced_motions_;
  std::shared_ptr<LinearDamping> linear_damper_;
  /// Shared with their Simbody force element, made with the first.
  std::shared_ptr<std::vector<RotationSpring>> rotation_springs_ = std::make_shared<std::vector<RotationSpring>>();
  std::map<SimTK::MobilizedBodyIndex, PrescribedMotion> prescribed_;
};

}  // namespace mmv
