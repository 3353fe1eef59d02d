#include "sim/modes/cms.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/linalg.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/statics/closures.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/core/errors.hpp"

namespace mmv {

Eigen::MatrixXd modalAssuranceCriterion(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  MMV_DEMAND(A.rows() == B.rows());
  Eigen::MatrixXd mac(A.cols(), B.cols());
  for (Eigen::Index i = 0; i < A.cols(); ++i)
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      const double d = A.col(i).squaredNorm() * B.col(j).squaredNorm();
      const double ab = A.col(i).dot(B.col(j));
      mac(i, j) = d > 0 ? ab * ab / d : 0.0;
    }
  return mac;
}

Eigen::MatrixXd craigBamptonBasis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& C, int k) {
  const Eigen::Index n = K.rows(), nb = C.rows();
  MMV_DEMAND(M.rows() == n && C.cols() == n);
  // Constraint modes: min 1/2 u^T K u subject to C u = e_b, i.e. [K C^T; C 0][u; mu] = [0; e_b].
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + nb, n + nb);
  kkt.topLeftCorner(n, n) = K;
  kkt.topRightCorner(n, nb) = C.transpose();
  kkt.bottomLeftCorner(nb, n) = C;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + nb, nb);
  rhs.bottomRows(nb) = Eigen::MatrixXd::Identity(nb, nb);
  const EquilibratedLu lu(kkt);
  if (!lu.isInvertible()) throw NumericalError("Craig-Bampton: the component is not restrained once its interface is fixed");
  const Eigen::MatrixXd psi = lu.solve(rhs).topRows(n);
  // Fixed-interface modes: (K, M) on the null space of C.
  const ModalSolution fixed = solveModes(M, K, nullSpace(C, static_cast<int>(n)));
  const int kk = std::min<int>(k, static_cast<int>(fixed.shapes.cols()));
  Eigen::MatrixXd basis(n, nb + kk);
  basis << psi, fixed.shapes.leftCols(kk);
  return basis;
}

ModalSolution ritzModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& T,
                        const Eigen::MatrixXd& G) {
  const Eigen::MatrixXd Mr = T.transpose() * M * T, Kr = T.transpose() * K * T;
  const int nr = static_cast<int>(T.cols());
  const Eigen::MatrixXd Zr = G.rows() ? nullSpace(G * T, nr) : Eigen::MatrixXd::Identity(nr, nr);
  ModalSolution sol = solveModes(0.5 * (Mr + Mr.transpose()), 0.5 * (Kr + Kr.transpose()), Zr);
  sol.shapes = T * sol.shapes;
  return sol;
}

const char* cmsMethodName(CmsMethod m) { return m == CmsMethod::AssumedModes ? "assumed modes" : "Craig-Bampton"; }

std::string synthesisVerdict(double relative_error, double mac, const SynthesisOptions& o) {
  if (mac < o.mac_threshold) return "missed";
  return std::abs(relative_error) <= o.frequency_tolerance ? "predicted" : "shifted";
}

namespace {

/// Craig-Bampton basis of one link over its hinge angles.
Eigen::MatrixXd craigBamptonForLink(const ArticleScene& scene, const std::string& link, int k) {
  const ArticleScene cs = componentScene(scene, link, ComponentBC::ClampedFree, LumpedMass{});
  const auto model = buildArticleModel(cs);
  const SimTK::State& s = model->getReferenceState();
  const std::vector<int>& dofs = model->getDofs();  // the hinges, in order
  const Eigen::MatrixXd M = calcMass(*model, s, dofs);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs.size(), dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) K(i, i) = model->getCoordinates()[dofs[i]].stiffness;
  // The tip is an interface when a joint or a loop closure is attached there.
  bool tip_joint = false;
  for (const auto& j : scene.article.joints) tip_joint = tip_joint || j.parent == link;
  for (const auto& c : scene.article.closures) tip_joint = tip_joint || c.point == link + ".tip" || c.to == link + ".tip";
  if (!tip_joint) {  // interface at the root only: the clamped-free modes
    const ModalSolution sol = solveModes(M, K);
    return sol.shapes.leftCols(std::min<Eigen::Index>(k, sol.shapes.cols()));
  }
  // Interface at the tip: rotation and transverse deflection (the link lies along +x);
  // on a link that bends out of its plane every rotation (the joint's pin transmits twist and
  // out-of-plane bending) and the deflection along z too.
  const NamedPoint* tip = model->findPoint(link + ".tip");
  const Eigen::MatrixXd J = model->calcFrameJacobians(s, {tip->mobod}, {tip->station_B}, dofs);
  const bool out_of_plane = cs.article.bendsOutOfPlane(cs.article.links.front()) && !scene.article.lock_out_of_plane;
  const std::vector<int> rows = out_of_plane ? std::vector<int>{0, 1, 2, 4, 5} : std::vector<int>{2, 4};
  Eigen::MatrixXd C(rows.size(), dofs.size());
  for (std::size_t r = 0; r < rows.size(); ++r) C.row(r) = J.row(rows[r]);  // J: 3 rotations, then 3 translations
  return craigBamptonBasis(M, K, C, k);
}

/// The synthesis basis T: joint DOFs kept, each flexible link's hinges spanned by its
/// component basis (assumed modes or Craig-Bampton).
Eigen::MatrixXd synthesisBasis(const ArticleScene& scene, const Model& model, const std::vector<int>& dofs,
                               const SynthesisOptions& o) {
  const int n = static_cast<int>(dofs.size());
  std::vector<Eigen::MatrixXd> blocks;
  std::vector<std::vector<int>> rows_of_block;
  std::vector<int> joint_rows;
  for (int a = 0; a < n; ++a)
    if (model.getCoordinates()[dofs[a]].kind == CoordinateKind::Joint) joint_rows.push_back(a);
  for (const auto& l : scene.article.links) {
    if (l.rigid) continue;
    std::vector<int> rows;
    for (int a = 0; a < n; ++a) {
      const Coordinate& c = model.getCoordinates()[dofs[a]];
      if (c.kind == CoordinateKind::Hinge && c.part == l.name) rows.push_back(a);
    }
    if (rows.empty()) continue;
    Eigen::MatrixXd B;
    if (o.method == CmsMethod::AssumedModes) {
      ComponentOptions co = o.component;
      co.num_modes = o.modes_per_link;
      B = calcComponentModes(scene, l.name, co).hinge_shapes;
    } else {
      B = craigBamptonForLink(scene, l.name, o.modes_per_link);
    }
    blocks.push_back(B);
    rows_of_block.push_back(rows);
  }
  int cols = static_cast<int>(joint_rows.size());
  for (const auto& b : blocks) cols += static_cast<int>(b.cols());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, cols);
  int c = 0;
  for (int a : joint_rows) T(a, c++) = 1.0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (Eigen::Index j = 0; j < blocks[b].cols(); ++j, ++c)
      for (std::size_t h = 0; h < rows_of_block[b].size(); ++h) T(rows_of_block[b][h], c) = blocks[b](h, j);
  }
  return T;
}

std::string methodDescription(const SynthesisOptions& o) {
  std::ostringstream method;
  method << cmsMethodName(o.method);
  if (o.method == CmsMethod::AssumedModes)
    method << ", " << componentBCName(o.component.bc) << ", tip mass: "
           << (o.component.explicit_tip ? "explicit" : tipMassRuleName(o.component.rule));
  method << ", " << o.modes_per_link << " per link";
  return method.str();
}

}  // namespace

SynthesisResult synthesize(const ArticleScene& scene, const SynthesisOptions& o) {
  SynthesisResult r;
  const SolvedScene full = solveScene(scene);
  const Model& model = *full.model;
  const std::vector<int>& dofs = full.linearized.dofs;
  const Eigen::MatrixXd T = synthesisBasis(scene, model, dofs, o);
  ModalSolution synth = ritzModes(full.linearized.M, full.linearized.K, T, full.linearized.G);
  markRigidBodyModes(synth, full.linearized, scene);  // T keeps the joint coordinates: the same mechanisms
  r.method = methodDescription(o);
  r.full_dofs = static_cast<int>(full.modes.omega2.size());
  r.reduced_dofs = static_cast<int>(synth.omega2.size());

  const int nf = std::min<int>(o.compare_modes, r.full_dofs), ns = std::min<int>(o.compare_modes + 4, r.reduced_dofs);
  SimTK::State st = full.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  const Eigen::MatrixXd P = pointTranslationMatrix(model, st, dofs);
  r.full_point_shapes = P * full.modes.shapes.leftCols(nf);
  r.mac = modalAssuranceCriterion(P * synth.shapes.leftCols(ns), r.full_point_shapes);
  r.full_hz.resize(nf);
  r.synth_hz.resize(ns);
  for (int i = 0; i < nf; ++i) r.full_hz[i] = full.modes.frequencyHz(i);
  for (int j = 0; j < ns; ++j) r.synth_hz[j] = synth.frequencyHz(j);
  for (int i = 0; i < nf; ++i) {
    Eigen::Index best;
    const double mac = r.mac.col(i).maxCoeff(&best);
    SynthesisRow row;
    row.mode = ModeNumber::atIndex(i);
    row.full_hz = r.full_hz[i];
    row.synth_mode = ModeNumber::atIndex(static_cast<int>(best));
    row.synth_hz = r.synth_hz[best];
    // A rigid-body mode (0 Hz) has no relative error: both at ~0 is exact, else the
    // synthesized frequency itself (Hz) stands in, so nothing infinite is reported.
    const double tiny = 1e-9 * std::max(1.0, std::abs(r.full_hz.tail(1)[0]));
    row.relative_error = std::abs(row.full_hz) > tiny ? row.synth_hz / row.full_hz - 1.0 : row.synth_hz;
    row.mac = mac;
    row.verdict = synthesisVerdict(row.relative_error, mac, o);
    row.dominant_link = dominantStrainLink(model, dofs, full.modes.shapes.col(i));
    if (model.isSpatial()) row.family = classifyMode(model, dofs, full.modes.shapes.col(i)).label;
    r.rows.push_back(row);
  }
  return r;
}

}  // namespace mmv
