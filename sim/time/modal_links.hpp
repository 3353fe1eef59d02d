#pragma once
/// Links in modal coordinates for time runs (scene `links[i].modes: K`): the reduced
/// flexible body of floating-frame formulations, on our segment model. Each such link's
/// hinge angles are carried by its first K modes,
///
///     theta_link(t) = theta_link(0) + Phi_link q(t),
///
/// the modes of the link at the run's start with its root held and the rest of the
/// article rigid (the hinge block of the system's M and K there: the outboard links
/// load it as rigid bodies, and K includes the geometric stiffness of gravity's preload).
/// Every other free coordinate (free joints, hinges of links without `modes`) stays its
/// own. The equations of motion are the segment model's projected onto that basis
/// (Galerkin):
///
///     T^T [ M(theta) (T a + prescribed) + c(theta, theta') - f(theta, theta', t) ] = 0,
///
/// a = q''. The kinematics stay the segment model's, nonlinear: a link spun up keeps
/// its centrifugal stiffening (which a linear floating-frame body only has when its
/// geometric stiffness is added), and with every mode kept the run is the segment
/// model's run. What is dropped is the truncated modes' motion and so their stiffness:
/// the stiff hinge modes leave the time run, and with them most of its cost.
///
/// The inverse dynamics with a = 0 and the prescribed joints' accelerations as
/// commanded gives the residual forces (O(n)): sim/model/tree_dynamics.hpp's own pass for
/// a tree of pins, sliders and welds (the planar article), else Simbody's from a State
/// realized to Dynamics; T^T M T is summed in closed form over the bodies (parallel
/// pins), else from K of Simbody's products M v. Every free mobilizer carries an acceleration-level Motion
/// (sim/model/reduced_motions.hpp), so at a sample the state is realized with the
/// reduced accelerations, so every output (points, sensors, joint torques, energy
/// books) is the reduced model's. The projected constraint forces do no work
/// (T^T f = 0), so the energy balance holds as for the segment model.

#include <Simbody.h>

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "article/article_spec.hpp"
#include "sim/model/model.hpp"
#include "sim/model/tree_dynamics.hpp"
#include "sim/time/external_stepper.hpp"

namespace mmv {

/// One link's kept modes, for the run's summary.
struct ModalLinkSummary {
  std::string link;
  int modes = 0, hinges = 0;
  double highest_kept_hz = 0;   ///< the last kept mode at the start
  double first_dropped_hz = 0;  ///< the first mode left out (0: none)
  /// A release (LinkSpec::modes_cover_release): the share of the link's static response
  /// to its load at the start that the modes left out carry (stiffness norm).
  std::optional<double> release_share_left;
};

/// Each of a link's modes' share of its static response to the load `f` in the
/// stiffness norm, (phi_j^T f)^2 / lambda_j over sum_j of the same (M-normalized `Phi`,
/// eigenvalues `lambda` ascending; modes of no positive stiffness carry none); all zero
/// when `f` loads none. Their sum before normalizing is f^T K^-1 f.
Eigen::VectorXd staticShares(const Eigen::MatrixXd& Phi, const Eigen::VectorXd& lambda, const Eigen::VectorXd& f);
/// A verification companion's count (LinkSpec::modes_frequency_factor): the modes up to
/// `factor` times the frequency of the run's highest kept (of `kept`, eigenvalues
/// `lambda` = omega^2 ascending) and at least one more, within the hinges; `kept` when
/// `factor` is 1 or less.
int companionModes(const Eigen::VectorXd& lambda, int kept, double factor);
/// A release's rule (sim/time/fidelity.hpp): the fewest modes, at least `at_least`, whose
/// left-out `shares` sum to at most kReleaseStaticShare.
int modesForRelease(const Eigen::VectorXd& shares, int at_least);

class ModalLinks final : public ReducedCoordinates {
 public:
  /// The basis at `start` (realized to Position, the model's reduced motions not enabled
  /// in it: the run's state enables them, see load). Throws NumericalError when a link's held-root mass matrix is not positive
  /// definite.
  ModalLinks(const Model& model, const ArticleSpec& article, const SimTK::State& start);
  int size() const override { return 2 * static_cast<int>(T_.cols()); }
  void project(const SimTK::State& s, double* y) const override;
  /// A right-hand side is evaluated in a State of its own (without the reduced Motions'
  /// work at Dynamics); `s`, the run's state with them enabled, is written only when `full`.
  void load(double t, const double* y, SimTK::State& s, double* ydot, bool full) const override;
  bool jacobian(double t, const double* y, double* J) const override;
  const std::vector<ModalLinkSummary>& summary() const { return summary_; }
  /// T^T M T at (t, y) in closed form (empty unless the free coordinates are parallel
  /// pins) and by Simbody's M v products: the two must agree (a test's check).
  std::pair<Eigen::MatrixXd, Eigen::MatrixXd> massMatrices(double t, const double* y) const;
  /// The free coordinates' basis (rows: freeCoordinates(), columns: reduced coordinates).
  const Eigen::MatrixXd& basis() const { return T_; }
  const std::vector<int>& freeCoordinates() const { return free_; }

 private:
  /// What the mass matrix's closed form and the own inverse dynamics need of the bodies
  /// (and the prescribed coordinates' motions) at `start`.
  void readBodies(const Model& model, const SimTK::State& start);
  /// `load`: the free coordinates' generalized forces at the start (a release's).
  void addLink(const LinkSpec& l, const std::vector<int>& hinges, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K_free,
               const Eigen::VectorXd& load, std::vector<Eigen::VectorXd>& columns);

  /// a_ = q'' at (t, y): by tree_ when `own` and there is one, else evaluated in `s`
  /// (set to t and y, realized to Dynamics).
  void accelerations(double t, const double* y, SimTK::State& s, bool own = true) const;
  /// Sets `s` to time t and y, the prescribed coordinates as commanded, realized to
  /// Position (velocities set).
  void setState(double t, const double* y, SimTK::State& s) const;
  /// tree_'s residual at (t, y) into x_ (the free rows' generalized forces, minus).
  void ownResidual(double t, const double* y) const;
  /// G_ = T^T M T for parallel pins (planar articles), O(bodies k + bodies k^2) flops
  /// without Simbody's k M v products; X(b) is body b's transform in ground.
  template <class BodyTransform>
  void planarMassMatrix(const BodyTransform& X) const;
  /// G_ by K of Simbody's M v products (any mobilizers).
  void productsMassMatrix(const SimTK::State& s) const;

  const Model& model_;
  mutable SimTK::State rhs_;
  std::vector<int> free_;             ///< model coordinates the basis moves
  std::vector<int> free_q_, free_u_;  ///< their Simbody indices
  Eigen::VectorXd start_;             ///< their values at the start
  Eigen::MatrixXd T_;
  Eigen::MatrixXd K_, C_;  ///< T^T K T, T^T C T at the start (the Jacobian's)
  std::vector<ModalLinkSummary> summary_;
  std::vector<std::pair<int, const PrescribedMotion*>> prescribed_;  ///< coordinate, its motion
  // Work space of load() (one run, one thread).
  mutable SimTK::Vector udot_, v_, Mv_, f_;
  mutable Eigen::MatrixXd G_, S_, P_, A_;
  bool parallel_pins_ = false;
  /// What planarMassMatrix needs of each mobilized body (constant over a run).
  struct PinBody {
    int parent = 0;
    int free_row = -1;       ///< row of T for its free pin, -1 if none
    SimTK::Vec3 pin_B{0};    ///< its pin's point (the outboard frame's origin), body frame
    double mass = 0;
    SimTK::Vec3 com_B{0};
    SimTK::Inertia central;  ///< about the mass centre, body frame
  };
  std::vector<PinBody> bodies_;
  SimTK::MobilizedBodyIndex axis_body_;  ///< a free pin's body: the common axis is its
  SimTK::Vec3 axis_M_{0}, axis_{0};      ///< axis in that body's frame; at the start
  mutable Eigen::VectorXd b_, a_, x_;
  /// The own inverse dynamics (null: Simbody's) and its coordinates' work space: every
  /// model coordinate's q, u and udot (the prescribed ones from their motions).
  std::unique_ptr<TreeDynamics> tree_;
  Eigen::VectorXd q_start_;
  mutable Eigen::VectorXd tq_, tu_, tudot_, tr_;
};

}  // namespace mmv
