#pragma once
/// Static equilibrium of the article under gravity with the torquers holding their
/// commanded angles: find the free coordinates x (hinges, free and servo joints) and,
/// for closed loops, the closure forces lambda (sim/statics/closures.hpp) with
///
///     f_x(q) + G_x(q)^T lambda = 0,    Phi(q) = 0,
///
/// f = gravity + loads + springs (Model::calcAppliedForces), held joints fixed at
/// their commanded angles. Newton's method on the KKT system
///
///     [ -(K + K_lambda)  G^T ] [dx]        [ f_x + G^T lambda ]
///     [        G          0  ] [dlambda] = -[ Phi              ]
///
/// with the tangent stiffness K = -df/dq and the closure forces' stiffness K_lambda
/// (sim/statics/linearize.hpp), and a backtracking line search on the residual. Closures are
/// checked for redundancy first (checkClosureRank: a SceneError names the culprit).
///
/// If Newton fails from the unbent shape, gravity is ramped from 0 to its full value
/// in adaptive steps, each solve starting from the previous equilibrium (natural
/// continuation). If the ramp stalls, the equilibrium path has a limit
/// or bifurcation point there (the article buckles or snaps through, e.g. a closure
/// compresses a slender link);
/// the failure says at what fraction of g. Converged when ||f_x||_inf <= force_tolerance * force_scale, where
/// force_scale is the larger of the largest generalized force in the unbent shape and
/// the largest moment gravity could exert about any joint axis (any pin if the model
/// has no joint), max_k sum m_i |g| |p_i - o_k| (so the test is relative to the loads present, even where they happen to balance). The torque a locked torquer holds is
/// tau = -f_joint at the solution (the torque the torquer applies to its child link,
/// counter-clockwise positive).

#include <string>
#include <vector>

#include "sim/core/errors.hpp"
#include "sim/model/model.hpp"

namespace mmv {

struct EquilibriumOptions {
  int max_iterations = 50;  ///< per Newton solve (each continuation step is one).
  double force_tolerance = 1e-10;  ///< relative to the force scale (dimensionless).
  bool continuation = true;        ///< ramp gravity if Newton fails from the unbent shape.
};

struct EquilibriumResult {
  bool converged = false;
  std::string failure;     ///< why it did not converge (empty when converged).
  int iterations = 0;      ///< Newton iterations, over all continuation steps.
  int continuation_steps = 0;  ///< 0: solved directly; else the gravity steps taken.
  double residual = 0;     ///< ||f_x||_inf at the end, N*m.
  double force_scale = 0;  ///< N*m, see above.
  double closure_error = 0;  ///< ||Phi||_inf at the end, m.
  Eigen::VectorXd closure_multipliers;  ///< lambda, N, one per closure row.
  SimTK::State state;      ///< the equilibrium (or last iterate), realized to Position.
  Eigen::VectorXd q;       ///< all coordinates, rad.
  Eigen::VectorXd generalized_force;  ///< f at the solution, N*m (non-zero at held joints).
};

EquilibriumResult solveEquilibrium(const Model& model, const EquilibriumOptions& options = {});

/// What a converged equilibrium means for a start at rest there: the number of
/// directions of negative tangent stiffness (on the closures' tangent space; 0: stable,
/// > 0: the article rests there only until round-off grows, e.g. an inverted
/// pendulum), and every free or servo joint that settled more than 0.5 deg away from
/// its scene angle ("joint 'elbow' settled at 90.0 deg, 10.0 deg from its scene angle
/// 80.0 deg"). Empty notes and 0: the start is the stable equilibrium the scene asked for.
struct EquilibriumAssessment {
  int unstable_directions = 0;
  std::vector<std::string> moved_joints;
};
EquilibriumAssessment assessEquilibrium(const Model& model, const EquilibriumResult& equilibrium);

}  // namespace mmv
