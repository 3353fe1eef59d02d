// Building the article's linear model (sim/linear/state_space.hpp): damping, base
// coupling, inputs and outputs over the closure-admissible coordinates.
#include <cmath>
#include <optional>

#include "sim/core/linalg.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/statics/link_stress.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/damping.hpp"

namespace mmv {
namespace {

/// The damping matrix over the admissible coordinates (Z^T C Z) and, for proportional
/// damping, the modes that diagonalise it with Phi^T C Phi = diag(c) known exactly
/// (modal: 2 zeta omega; Rayleigh: alpha + beta omega^2), the responses' modal path.
struct Damping {
  Eigen::MatrixXd C;
  ModalSolution modes;   ///< proportional damping only
  Eigen::VectorXd c;     ///< per mode (proportional damping only)
};

Damping dampingMatrix(const LinearModel& lm, const Model& model, const std::vector<int>& dofs,
                      const DampingSpec& damping) {
  const Eigen::MatrixXd& Z = lm.Z;
  Damping d;
  if (damping.kind == DampingSpec::Kind::HingeViscous) {
    const Eigen::VectorXd c = hingeDampers(model, dofs, damping.hinge_beta);
    d.C = Z.rows() == Z.cols() && Z.isIdentity(0.0) ? Eigen::MatrixXd(c.asDiagonal())  // an open tree
                                                     : Eigen::MatrixXd(Z.transpose() * c.asDiagonal() * Z);
    symmetrize(d.C);
    return d;
  }
  Eigen::MatrixXd MPhi;  // M Phi, as solveModes' checks formed it
  d.modes = solveModes(lm.Mz, lm.Kz, 0, &MPhi);
  const Eigen::VectorXd& w2 = d.modes.omega2;
  if (damping.kind == DampingSpec::Kind::Rayleigh) {
    d.C = damping.alpha * lm.Mz + damping.beta * lm.Kz;
    d.c = Eigen::VectorXd::Constant(w2.size(), damping.alpha) + damping.beta * w2;
    symmetrize(d.C);
  } else {
    // C = (M Phi) diag(c) (M Phi)^T = W W^T with W = M Phi diag(sqrt(c)), c >= 0: one
    // symmetric rank-n update (half a product), symmetric by construction.
    d.c = 2 * damping.modal_ratio * w2.cwiseMax(0.0).cwiseSqrt();
    MPhi = MPhi * d.c.cwiseSqrt().asDiagonal();
    d.C = Eigen::MatrixXd::Zero(MPhi.rows(), MPhi.rows());
    d.C.selfadjointView<Eigen::Lower>().rankUpdate(MPhi);
    for (Eigen::Index j = 1; j < d.C.cols(); ++j) d.C.col(j).head(j) = d.C.row(j).head(j).transpose();
  }
  return d;
}

/// The Jacobian row of a named point's (or a station's) translation along world axis
/// `axis` (0..2), or its rotation about world axis axis - 3 (3..5), over the DOFs.
Eigen::RowVectorXd pointRow(const ArticleScene& scene, const Model& model, const SimTK::State& st,
                            const std::vector<int>& dofs, const std::string& point, int axis, const std::string& what) {
  std::string error;
  const std::optional<PointRef> p = PointRef::resolve(model, scene.article, point, error);
  if (!p) throw SceneError(scene.source + ": " + what + ": " + error);
  if (isRotationAxis(axis)) return Eigen::RowVectorXd(p->rotationJacobian(st, dofs).row(axis - 3));
  return Eigen::RowVectorXd(p->translationJacobian(st, dofs, 3).row(axis));
}

/// The generalized force over the DOFs per unit of input `in`.
Eigen::VectorXd inputForce(const ArticleScene& scene, const Model& model, const SimTK::State& st,
                           const std::vector<int>& dofs, const Eigen::MatrixXd& Mqb, const InputSpec& in) {
  const int n = static_cast<int>(dofs.size());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  switch (in.kind) {
    case InputKind::BaseAcceleration: return -Mqb.col(in.axis);
    case InputKind::PointForce:
      if (in.axis < 0) {  // along a direction: the rows' combination
        for (int a = 0; a < 3; ++a)
          if (in.direction[static_cast<std::size_t>(a)] != 0)
            g += in.direction[static_cast<std::size_t>(a)] * pointRow(scene, model, st, dofs, in.target, a, "input " + in.name).transpose();
        return g;
      }
      [[fallthrough]];
    case InputKind::PointMoment:  // J_v^T f, or J_w^T m
      return pointRow(scene, model, st, dofs, in.target, in.axis, "input " + in.name).transpose();
    case InputKind::JointTorque: {
      int row = -1;
      for (int a = 0; a < n; ++a)
        if (model.getCoordinates()[dofs[a]].name == in.target) row = a;
      if (row < 0) {
        bool exists = false;
        for (const auto& c : model.getCoordinates()) exists = exists || c.name == in.target;
        throw SceneError(scene.source + ": input " + in.name + ": " +
                         (exists ? "joint '" + in.target + "' is locked (hold: locked), so a torque there moves nothing; use hold: free or servo"
                                 : "unknown joint '" + in.target + "'"));
      }
      g[row] = 1.0;
      return g;
    }
  }
  return g;
}

/// Output rows for displacement, velocity and acceleration, and the direct feedthrough of
/// an absolute acceleration from a base-acceleration input.
void outputMatrices(const ArticleScene& scene, const Model& model, const SimTK::State& st, const std::vector<int>& dofs,
                    const Eigen::MatrixXd& Z, const std::vector<InputSpec>& inputs, const std::vector<OutputSpec>& outputs,
                    SecondOrderResponse& so) {
  const Eigen::Index no = outputs.size(), ni = inputs.size(), nz = Z.cols();
  so.Cd = so.Cv = so.Ca = Eigen::MatrixXd::Zero(no, nz);
  so.D = Eigen::MatrixXd::Zero(no, ni);
  bool base_input = false;
  for (const auto& in : inputs) base_input = base_input || in.kind == InputKind::BaseAcceleration;
  for (Eigen::Index r = 0; r < no; ++r) {
    const OutputSpec& out = outputs[r];
    if (out.isStrain()) {  // the mean curvature between two stations, at the face
      MMV_DEMAND(out.kind == OutputKind::Displacement && out.axis == 5 && out.span_m != 0 && out.surface_m > 0);
      std::string error;
      const std::optional<PointRef> a = PointRef::resolve(model, scene.article, out.point, error),
                                    b = PointRef::resolve(model, scene.article, out.span_end, error);
      if (!a || !b) throw SceneError(scene.source + ": output " + out.name + ": " + error);
      so.Cd.row(r) = strainRow(*a, *b, st, dofs, out.surface_m / out.span_m, out.out_of_plane) * Z;
      continue;
    }
    if (out.isStress()) {  // the springs' moment at the station, on the face
      const LinkSpec& l = *scene.article.findLink(out.stress_link);
      const SectionStrength section =
          sectionStrength(*scene.article.findMaterial(l.material), *scene.article.findSection(l.section));
      so.Cd.row(r) = bendingStressRow(model, l, section, out.stress_x_m, out.stress_face, model.getQ(st), dofs) * Z;
      continue;
    }
    const Eigen::RowVectorXd P = pointRow(scene, model, st, dofs, out.point, out.axis, "output " + out.name) * Z;
    if (out.absolute && out.kind != OutputKind::Acceleration && base_input)
      throw SceneError(scene.source + ": output " + out.name +
                       ": an absolute displacement or velocity needs the base's displacement, not its acceleration: use an "
                       "absolute acceleration (transmissibility) or a relative output");
    if (out.kind == OutputKind::Displacement) so.Cd.row(r) = P;
    if (out.kind == OutputKind::Velocity) so.Cv.row(r) = P;
    if (out.kind == OutputKind::Acceleration) {
      so.Ca.row(r) = P;
      if (out.absolute)  // the base's own acceleration
        for (Eigen::Index k = 0; k < ni; ++k)
          if (inputs[k].kind == InputKind::BaseAcceleration && inputs[k].axis == out.axis) so.D(r, k) = 1.0;
    }
  }
}

/// Names and units of the inputs, outputs and states.
void nameSignals(const Model& model, const LinearizedModel& lin, const std::vector<InputSpec>& inputs,
                 const std::vector<OutputSpec>& outputs, StateSpace& ss) {
  const char* in_units[] = {"m/s^2", "N*m", "N", "N*m"};
  for (const auto& in : inputs) {
    ss.input_names.push_back(in.name);
    ss.input_units.push_back(in_units[static_cast<int>(in.kind)]);
  }
  const char* out_units[] = {"m", "m/s", "m/s^2"};
  const char* rotation_units[] = {"rad", "rad/s", "rad/s^2"};
  for (const auto& out : outputs) {
    ss.output_names.push_back(out.name);
    ss.output_units.push_back(out.isStrain() ? "m/m" : out.isStress() ? "Pa" : (isRotationAxis(out.axis) ? rotation_units : out_units)[static_cast<int>(out.kind)]);
  }
  const bool open = lin.G.rows() == 0;
  const int nz = static_cast<int>(lin.Z.cols());
  for (int i = 0; i < nz; ++i)
    ss.state_names.push_back(open ? model.getCoordinates()[lin.dofs[i]].name : "eta" + std::to_string(i + 1));
  for (int i = 0; i < nz; ++i) ss.state_names.push_back(ss.state_names[i] + "_dot");
}

}  // namespace

std::vector<InputSpec> defaultInputs() {
  return {{"table_x", InputKind::BaseAcceleration, "", 0}, {"table_y", InputKind::BaseAcceleration, "", 1}};
}

std::vector<OutputSpec> defaultOutputs(const ArticleScene& scene) {
  std::vector<OutputSpec> out;
  for (const auto& l : scene.article.links)
    for (int a = 0; a < 2; ++a)
      // Named as --output names the same signal (POINT:AXIS, absolute acceleration by default).
      out.push_back({l.name + ".tip:" + (a ? "y" : "x"), OutputKind::Acceleration, l.name + ".tip", a, true});
  return out;
}

LinearModel buildLinearModel(const ArticleScene& scene, const std::vector<InputSpec>& inputs,
                             const std::vector<OutputSpec>& outputs, const DampingSpec& damping,
                             bool prepare_responses) {
  const ProgressStage stage("building the linear model");
  LinearModel lm;
  // The undamped modes serve only the UFF file's first 12 shapes (linear_report.cpp):
  // on large models only those are solved for (shift-invert Lanczos).
  // On a large open tree the lowest modes come from the tree's operators, and the dense
  // matrices the state-space model needs are made from them (O(n^2)).
  lm.solved = solveScene(scene, {}, kLinearModelModes, true);
  addDenseMatrices(lm.solved.linearized);
  lm.inputs = inputs;
  lm.outputs = outputs;
  lm.damping = damping;
  const Model& model = *lm.solved.model;
  const LinearizedModel& lin = lm.solved.linearized;
  const std::vector<int>& dofs = lin.dofs;
  lm.Z = lin.Z;
  if (lm.Z.cols() == 0)  // nothing moves: every link rigid and every joint held (or closed)
    throw SceneError(scene.positions.where("links") +
                     ": the article has no degrees of freedom (every link rigid, every joint held or closed), so it has "
                     "no response to compute: give a link segments or a joint `hold: free` or `servo`");
  const Eigen::MatrixXd& Z = lm.Z;
  std::optional<ProgressStage> step(std::in_place, strf("projecting M and K (%ld DOF)", static_cast<long>(Z.cols())));
  const bool open_tree = Z.rows() == Z.cols() && Z.isIdentity(0.0);  // no products (four n^3 of them)
  lm.Mz = open_tree ? lin.M : Eigen::MatrixXd(Z.transpose() * lin.M * Z);
  lm.Kz = open_tree ? lin.K : Eigen::MatrixXd(Z.transpose() * lin.K * Z);
  symmetrize(lm.Mz);
  symmetrize(lm.Kz);
  // Symmetric by construction, to round-off that grows with the model (M Phi c Phi^T M
  // at 32 segments per link is 1e-12 off): made exact, as M and K are, so the symmetric
  // paths (modal responses, the partial reduction) apply at every size.
  step.emplace("damping matrix");
  Damping damped = dampingMatrix(lm, model, dofs, damping);
  lm.Cz = damped.C;
  step.emplace("inputs and outputs");
  SimTK::State st = lm.solved.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  // Out-of-plane inputs and outputs of a planar model are refused by the study (sim/app).
  for (const auto& in : inputs) MMV_DEMAND(in.kind == InputKind::JointTorque || !leavesThePlane(in.axis) || model.isSpatial());
  for (const auto& out : outputs) MMV_DEMAND(!leavesThePlane(out.axis) || model.isSpatial());
  // Base coupling M_qb e_a = sum_b m_b J_b^T e_a (mass centres), a = x, y, z.
  const Eigen::MatrixXd Mqb = model.calcMassCentreCoupling(st, dofs);
  lm.Bq = Eigen::MatrixXd::Zero(Z.cols(), inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k)
    lm.Bq.col(k) = Z.transpose() * inputForce(scene, model, st, dofs, Mqb, inputs[k]);
  bool armature = false;  // a shaker's armature moves with its point along its force: M + m b b^T
  for (std::size_t k = 0; k < inputs.size(); ++k)
    if (inputs[k].armature_kg > 0) {
      const Eigen::VectorXd b = lm.Bq.col(static_cast<Eigen::Index>(k));
      lm.Mz += inputs[k].armature_kg * b * b.transpose();
      armature = true;
    }
  if (armature) {  // the damping of the article as it is tested: with the armature on it
    symmetrize(lm.Mz);
    damped = dampingMatrix(lm, model, dofs, damping);
    lm.Cz = damped.C;
  }
  SecondOrderResponse& so = lm.second_order;
  outputMatrices(scene, model, st, dofs, Z, inputs, outputs, so);
  so.M = lm.Mz;
  so.C = lm.Cz;
  so.K = lm.Kz;
  so.Bq = lm.Bq;
  if (damped.c.size()) {
    so.setModalBasis(damped.modes.omega2, damped.modes.shapes, damped.c);
    // A rigid-body mode's omega^2 is round-off of either sign: with a singular K the
    // reductions take their modes from the solvers, which decline it by this same test
    // (and residualization then refuses the model), never from a 1 / omega^2 of noise.
    if (EquilibratedLu(lm.Kz).isInvertible())
      lm.proportional = std::make_shared<const ProportionalModes>(
          ProportionalModes{std::move(damped.modes.omega2), std::move(damped.c), std::move(damped.modes.shapes)});
  }
  step.reset();
  if (prepare_responses) so.prepare();
  const ProgressStage ss("state-space model");
  lm.full = secondOrderModel(lm.Mz, lm.Cz, lm.Kz, lm.Bq, so.Cd, so.Cv, so.Ca, so.D);
  nameSignals(model, lin, inputs, outputs, lm.full);
  return lm;
}

}  // namespace mmv
