// The lowest modes by shift-invert Lanczos against the dense solver and against
// pencils with a known spectrum (repeated, zero and negative eigenvalues), and the
// Sturm check that turns a missed mode into the dense fallback.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <variant>
#include <random>

#include "sim/model/article_builder.hpp"
#include "sim/modes/damping.hpp"
#include "sim/modes/modal.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/statics.hpp"
#include "sim/statics/tree_operator.hpp"

namespace mmv {
namespace {

/// A pencil (K, M) of size n with eigenvalues `lambda` (any order): M = B B^T + n I
/// from a seeded random B, V = L^-T Q M-orthonormal (M = L L^T, Q orthogonal), and
/// K = M V diag(lambda) V^T M, so that K V = M V diag(lambda).
struct Pencil {
  Eigen::MatrixXd M, K;
};
Pencil pencilWith(const std::vector<double>& lambda, unsigned seed) {
  const Eigen::Index n = static_cast<Eigen::Index>(lambda.size());
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd B(n, n), A(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) B(i, j) = normal(rng), A(i, j) = normal(rng);
  Pencil p;
  p.M = B * B.transpose() + static_cast<double>(n) * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ();
  const Eigen::LLT<Eigen::MatrixXd> llt(p.M);
  const Eigen::MatrixXd V = llt.matrixU().solve(Q);
  const Eigen::MatrixXd MV = p.M * V;
  p.K = MV * Eigen::Map<const Eigen::VectorXd>(lambda.data(), n).asDiagonal() * MV.transpose();
  p.K = 0.5 * (p.K + p.K.transpose());
  return p;
}

/// The first `count` modes of solveModes against the sorted spectrum, with M-normal
/// shapes that satisfy the pencil.
void expectLowest(const Pencil& p, std::vector<double> lambda, int count, const std::string& what) {
  std::sort(lambda.begin(), lambda.end());
  const ModalSolution sol = solveModes(p.M, p.K, count);
  ASSERT_GE(sol.omega2.size(), count) << what;
  const double scale = std::max(std::abs(lambda.front()), std::abs(lambda.back()));
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(sol.omega2[i], lambda[i], 1e-9 * scale) << what << ", mode " << i + 1;
    // Against the spectrum's scale: a zero eigenvalue has no relative residual.
    const Eigen::VectorXd v = sol.shapes.col(i), mv = p.M * v;
    EXPECT_LT((p.K * v - sol.omega2[i] * mv).norm(), 1e-9 * scale * mv.norm()) << what << ", mode " << i + 1;
  }
  EXPECT_LT(sol.orthogonality_error, 1e-9) << what;
}

TEST(ModalPartial, KnownSpectraWithRepeatedZeroAndNegativeEigenvalues) {
  const int n = 160;  // above kPartialModesMinDofs: the partial path is taken
  ASSERT_GE(n, kPartialModesMinDofs);
  std::vector<double> base(n);
  for (int i = 0; i < n; ++i) base[i] = 10.0 + 3.0 * i + 0.01 * i * i;
  {
    std::vector<double> l = base;  // repeated pairs and a triple inside the 12 kept
    l[1] = l[0];
    l[4] = l[5] = l[3];
    expectLowest(pencilWith(l, 1), l, 12, "repeated");
  }
  {
    std::vector<double> l = base;  // a repeated pair straddling the cut: modes 12 and 13
    l[12] = l[11];
    expectLowest(pencilWith(l, 2), l, 12, "pair at the cut");
  }
  {
    std::vector<double> l = base;  // unstable shapes first, then two rigid-body modes
    l[0] = -40.0, l[1] = -2.5, l[2] = 0.0, l[3] = 0.0;
    expectLowest(pencilWith(l, 3), l, 12, "negative and zero");
  }
}

// A diagonal pencil and a Lanczos start vector with a zero in mode 3's component: the
// Krylov space never contains mode 3 (exact zeros stay zero), so Lanczos misses it and
// only the Sturm count can tell. It must: no answer, and solveModes falls back to the
// dense solver, which finds mode 3.
TEST(ModalPartial, SturmCheckCatchesAMissedMode) {
  const int n = 120, count = 6;
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n), K = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) K(i, i) = 1.0 + i;
  Eigen::VectorXd start = Eigen::VectorXd::Ones(n);
  ASSERT_TRUE(solveLowestModes(M, K, count, &start).has_value());  // the control: complete, accepted
  start[2] = 0.0;
  EXPECT_FALSE(solveLowestModes(M, K, count, &start).has_value());
  const ModalSolution sol = solveModes(M, K, count);
  EXPECT_NEAR(sol.omega2[2], 3.0, 1e-12);
}

// The default article at 64 segments per link (256 DOF): the first 12 modes from
// Lanczos match the dense solution to 1e-10 in frequency and to a MAC of 1 - 1e-10, on
// the formed matrices and on the open tree's O(n) operators (sim/statics/tree_operator.hpp:
// Lanczos on the tree's factorization, the checks' products from the operators too).
TEST(ModalPartial, DefaultArticleMatchesTheDenseSolution) {
  ArticleScene scene = loadDefaultScene();
  overrideSegments(scene, 64);
  const auto model = buildArticleModel(scene);
  const EquilibriumResult eq = solveEquilibrium(*model);
  ASSERT_TRUE(eq.converged) << eq.failure;
  EXPECT_LE(eq.iterations, 4) << "Newton on the tree's factorization converges quadratically";
  const LinearizedModel lin = linearize(*model, eq.state);
  const TreeOperator op(*model, eq.state, lin.dofs);
  const int count = 12;
  const std::optional<ModalSolution> partial = solveLowestModes(lin.M, lin.K, count), tree = solveLowestModes(op, count);
  ASSERT_TRUE(partial.has_value());  // the partial paths are really taken here
  ASSERT_TRUE(tree.has_value());
  const ModalSolution dense = solveModes(lin.M, lin.K), checked = solveModes(op, count);
  for (int i = 0; i < count; ++i)
    for (const ModalSolution* s : {&*partial, &*tree}) {
      EXPECT_NEAR(s->omega2[i] / dense.omega2[i], 1.0, 1e-10) << "mode " << i + 1;
      const double c = s->shapes.col(i).dot(lin.M * dense.shapes.col(i));
      EXPECT_NEAR(c * c, 1.0, 1e-10) << "mode " << i + 1;
      EXPECT_LT(checked.residuals[i], 1e-9) << "mode " << i + 1;
    }
  EXPECT_LT(checked.orthogonality_error, 1e-10);
}

// The operators take over at kTreeOperatorMinDofs DOF, not one below: the default
// article has four flexible links, so 24 segments per link is the bound (96 DOF) and 23
// (92 DOF) keeps the formed matrices; both give the same modes.
TEST(ModalPartial, TheOperatorsStartAtTheirStatedSize) {
  ASSERT_EQ(kTreeOperatorMinDofs, 96);
  ArticleScene at = loadDefaultScene(), below = at;
  overrideSegments(at, 24);
  overrideSegments(below, 23);
  const SolvedScene a = solveScene(at, {}, 6, true), b = solveScene(below, {}, 6, true);
  EXPECT_EQ(a.linearized.dofs.size(), 96u);
  EXPECT_EQ(b.linearized.dofs.size(), 92u);
  EXPECT_TRUE(a.linearized.tree != nullptr);
  EXPECT_TRUE(b.linearized.tree == nullptr);
  const SolvedScene dense = solveScene(at, {}, 6, false);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(a.modes.omega2[i] / dense.modes.omega2[i], 1.0, 1e-10) << i;
}

// runModes keeps a large open tree's M and K as operators (no n x n matrix): its
// frequencies, geometric-stiffness shares and checks equal those from the dense
// matrices of the same equilibrium.
TEST(ModalPartial, ModesOfALargeTreeUseTheOperatorsAndEqualTheDensePath) {
  ArticleScene scene = loadDefaultScene();
  overrideSegments(scene, 48);
  const SolvedScene lean = solveScene(scene, {}, 12, true);
  ASSERT_TRUE(lean.linearized.tree != nullptr);
  EXPECT_EQ(lean.linearized.M.size(), 0);
  EXPECT_EQ(lean.linearized.K.size(), 0);
  const SolvedScene dense = solveScene(scene, {}, 12, false);
  ASSERT_TRUE(dense.linearized.tree == nullptr);
  ModesOptions o;
  o.max_modes = 12;
  const ModesReport rep = runModes(scene, o);
  ASSERT_EQ(rep.modes.size(), 12u);
  for (int i = 0; i < 12; ++i) {
    const Eigen::VectorXd phi = dense.modes.shapes.col(i);
    EXPECT_NEAR(lean.modes.omega2[i] / dense.modes.omega2[i], 1.0, 1e-10) << i;
    EXPECT_NEAR(rep.modes[i].omega2 / dense.modes.omega2[i], 1.0, 1e-10) << i;
    EXPECT_NEAR(rep.modes[i].geometric_stiffness_share,
                phi.dot(dense.linearized.K_geometric * phi) / dense.modes.omega2[i], 1e-8)
        << i;
  }
  EXPECT_LT(rep.eigen_residual, 1e-9);
  EXPECT_LT(rep.orthogonality_error, 1e-10);
  // Damped modes too: the hinges' dampers over the same basis of real modes.
  DampingSpec hinges;
  hinges.kind = DampingSpec::Kind::HingeViscous;
  hinges.hinge_beta = 0.002;
  o.damping = hinges;
  const ModesReport damped = runModes(scene, o);
  const int basis = damped.damping_basis_modes;
  ASSERT_GE(basis, 24);
  const SolvedScene reference = solveScene(scene, {}, basis, false);
  const ModalDamping expect = modalDamping(*reference.model, reference.linearized, reference.modes, hinges, 12);
  for (int i = 0; i < 12; ++i) {
    ASSERT_TRUE(damped.modes[i].has_damping) << i;
    EXPECT_NEAR(damped.modes[i].damping_ratio, expect.ratio[i], 1e-9 * std::max(expect.ratio[i], 1e-3)) << i;
  }
}

// Issue 37's check of the partial solvers: on every shipped article scene at 16 segments
// per link, and on the two-link demo at 512, the lowest 12 modes (a third of the DOF
// where that is fewer: the spin-up beam's 16) by shift-invert Lanczos on the formed M
// and K (a closed tree's projected on the closures' null space, as solveModes does), and
// on an open tree's O(n) operators, against every mode of the dense solver at the same
// equilibrium: frequencies within 1e-9 relative and a MAC above 0.999999. At 16 segments
// runModes itself solves densely (below kPartialModesMinDofs), so the partial paths are
// called here by name.
TEST(ModalPartial, EveryShippedArticleSceneAndTheDemoAt512MatchTheDensePath) {
  std::vector<std::pair<std::string, int>> cases;  // every article scene in scenes/ (HAM-SAS has no links)
  for (const auto& e : std::filesystem::directory_iterator(MMVLAB_SOURCE_DIR "/scenes"))
    if (e.path().extension() == ".yaml" && std::holds_alternative<ArticleScene>(loadSceneFile(e.path().string())))
      cases.push_back({e.path().stem().string(), 16});
  ASSERT_EQ(cases.size(), 6u);
  cases.push_back({"two-link-demo", 512});
  int tree_cases = 0, closed_cases = 0;
  for (const auto& [name, segments] : cases) {
    ArticleScene scene = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR "/scenes/") + name + ".yaml");
    overrideSegments(scene, segments);
    const std::string what = name + " at " + std::to_string(segments) + " segments";
    const SolvedScene dense = solveScene(scene, {}, 0, false);
    const LinearizedModel& lin = dense.linearized;
    const bool closed = !dense.model->getClosures().empty();
    const Eigen::MatrixXd Mr = lin.Z.transpose() * lin.M * lin.Z, Kr = lin.Z.transpose() * lin.K * lin.Z;
    const int count = std::min<int>(12, Mr.rows() / 3);
    ASSERT_GE(count, 5) << what;
    std::vector<std::pair<std::string, ModalSolution>> partial;
    std::optional<ModalSolution> formed = solveLowestModes(Mr, Kr, count);
    ASSERT_TRUE(formed.has_value()) << what;
    formed->shapes = lin.Z * formed->shapes;
    partial.push_back({"Lanczos on M and K", *formed});
    closed_cases += closed;
    if (!closed && TreeOperator::appliesTo(*dense.model)) {
      const TreeOperator op(*dense.model, dense.equilibrium.state, lin.dofs);
      const std::optional<ModalSolution> tree = solveLowestModes(op, count);
      ASSERT_TRUE(tree.has_value()) << what;
      partial.push_back({"the tree's operators", *tree});
      ++tree_cases;
    }
    const double scale = dense.modes.omega2.cwiseAbs().maxCoeff();
    for (const auto& [how, sol] : partial)
      for (int i = 0; i < count; ++i) {
        const std::string mode = what + ", " + how + ", mode " + std::to_string(i + 1);
        const double w2 = dense.modes.omega2[i];
        if (std::abs(w2) > 1e-12 * scale)
          EXPECT_NEAR(std::sqrt(std::abs(sol.omega2[i])) / std::sqrt(std::abs(w2)), 1.0, 1e-9) << mode;
        else
          EXPECT_LT(std::abs(sol.omega2[i]), 1e-10 * scale) << mode;
        const double c = sol.shapes.col(i).dot(lin.M * dense.modes.shapes.col(i));
        EXPECT_GT(c * c, 0.999999) << mode;
      }
  }
  EXPECT_EQ(closed_cases, 1);  // mmv-closed
  EXPECT_EQ(tree_cases, 6);    // every open tree among them
}

// A small model's lowest modes by the dense path, against the same M and K solved in long
// double (Eigen's generalized solver, 64-bit mantissa): the two-link demo at 16 segments
// (33 DOF; omega^2 spans 16 to 2.5e9, a free elbow beside stiff hinges). The dense solver
// alone carries an error of about eps max omega^2, 4e-9 of the first frequency here;
// the refinement (solveLowestModes for a model this small) brings each of the lowest
// third within 1e-11 of itself.
TEST(ModalPartial, ASmallModelsLowestModesAreAccurateRelativeToThemselves) {
  ArticleScene scene = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/two-link-demo.yaml");
  overrideSegments(scene, 16);
  const SolvedScene s = solveScene(scene, {}, 0, false);
  const LinearizedModel& lin = s.linearized;
  const int n = static_cast<int>(lin.M.rows());
  ASSERT_LE(n, 36);  // the refinement's small-model branch
  using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  const MatrixL M = lin.M.cast<long double>(), K = lin.K.cast<long double>();
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixL> exact(0.5L * (K + K.transpose()), 0.5L * (M + M.transpose()));
  ASSERT_EQ(exact.info(), Eigen::Success);
  EXPECT_GT(exact.eigenvalues()[n - 1] / exact.eigenvalues()[0], 1e8);  // the spread that needs the refinement
  const ModalSolution dense = solveModes(lin.M, lin.K);
  for (int i = 0; i < n / 3; ++i)
    EXPECT_NEAR(static_cast<double>(dense.omega2[i] / exact.eigenvalues()[i]), 1.0, 1e-11) << "mode " << i + 1;
}

}  // namespace
}  // namespace mmv
