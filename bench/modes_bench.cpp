// Cost of the `modes` pipeline on the default MMV scene against segments per link:
// model build, static equilibrium, linearization, eigen solution, and all of it.
// Figures are recorded in docs/benchmarks.md with the command that produced them.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/tree_operator.hpp"
#include "sim/modes/modal.hpp"
#include "sim/core/symmetric_eigen.hpp"
#include "sim/statics/statics.hpp"

namespace {

mmv::ArticleScene sceneWith(int segments) {
  mmv::ArticleScene s = mmv::loadDefaultScene();
  mmv::overrideSegments(s, segments);
  return s;
}

void segmentArgs(benchmark::internal::Benchmark* b) {
  for (int n : {4, 8, 16, 32, 64}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

void BM_Build(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::buildArticleModel(s));
}
BENCHMARK(BM_Build)->Apply(segmentArgs);

void BM_Equilibrium(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveEquilibrium(*model));
  st.counters["dofs"] = static_cast<double>(model->getDofs().size());
}
BENCHMARK(BM_Equilibrium)->Apply(segmentArgs);

void BM_Linearize(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::linearize(*model, eq.state));
}
BENCHMARK(BM_Linearize)->Apply(segmentArgs);

// The same dense M and K from the tree's operators (what the linear model reads).
void BM_LinearizeDenseByTree(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  for (auto _ : st) {
    const mmv::TreeOperator op(*model, eq.state, model->getDofs());
    benchmark::DoNotOptimize(op.denseM());
    benchmark::DoNotOptimize(op.denseK());
  }
}
BENCHMARK(BM_LinearizeDenseByTree)->Apply(segmentArgs);

void BM_Eigen(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  const mmv::LinearizedModel lin = mmv::linearize(*model, eq.state);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveModes(lin.M, lin.K));
}
BENCHMARK(BM_Eigen)->Apply(segmentArgs);

// Every eigenpair of the symmetric L^-1 K L^-T that solveModes forms for all modes (the
// modal damping matrix's): MRRR on the tridiagonal (symmetricEigen) against Eigen's
// implicit QR (symmetricEigenByQr), at 4 x segments DOF.
Eigen::MatrixXd standardProblem(int segments) {
  const auto model = mmv::buildArticleModel(sceneWith(segments));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  const mmv::LinearizedModel lin = mmv::linearize(*model, eq.state);
  const Eigen::LLT<Eigen::MatrixXd> llt(lin.M);
  Eigen::MatrixXd S = lin.K;
  llt.matrixL().solveInPlace<Eigen::OnTheLeft>(S);
  llt.matrixU().solveInPlace<Eigen::OnTheRight>(S);
  return S;
}

void BM_SymmetricEigenMrrr(benchmark::State& st) {
  const Eigen::MatrixXd S = standardProblem(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::symmetricEigen(S));
}
BENCHMARK(BM_SymmetricEigenMrrr)->Apply(segmentArgs)->Arg(128);

void BM_SymmetricEigenQr(benchmark::State& st) {
  const Eigen::MatrixXd S = standardProblem(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::symmetricEigenByQr(S));
}
BENCHMARK(BM_SymmetricEigenQr)->Apply(segmentArgs)->Arg(128);

void BM_ModesPipeline(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveSceneModes(s));
}
BENCHMARK(BM_ModesPipeline)->Apply(segmentArgs)->Arg(128);

// What `mmvlab modes` (12 modes reported) and `converge` solve on fine meshes: the
// lowest 12 modes only (shift-invert Lanczos from 96 DOF on, modal.hpp).
void fineArgs(benchmark::internal::Benchmark* b) {
  for (int n : {16, 32, 64, 128, 256}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

void BM_EigenFirst12(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  const mmv::LinearizedModel lin = mmv::linearize(*model, eq.state);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveModes(lin.M, lin.K, 12));
}
BENCHMARK(BM_EigenFirst12)->Apply(fineArgs);

// From 96 DOF on, an open tree's M and K are O(n) operators (sim/statics/tree_operator.hpp):
// the same 12 modes without forming them, up to 1024 segments per link (4096 DOF).
void treeArgs(benchmark::internal::Benchmark* b) {
  for (int n : {16, 32, 64, 128, 256, 512, 1024}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

void BM_EigenFirst12Tree(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  const mmv::TreeOperator op(*model, eq.state, model->getDofs());
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveModes(op, 12));
}
BENCHMARK(BM_EigenFirst12Tree)->Apply(treeArgs);

// What `modes` and `converge` run: build, equilibrium, linearization (operators from 96
// DOF on) and the 12 lowest modes.
void BM_ModesPipelineFirst12(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveSceneModes(s, {}, 12));
}
BENCHMARK(BM_ModesPipelineFirst12)->Apply(treeArgs);

// Issue 37's growth exponent of the modes pipeline from 256 to 4096 DOF (64 and 1024
// segments per link): each iteration times both, and the counter `exponent` is
// log(t_4096 / t_256) / log(16) from the fastest of each (the target is 1.2 at most).
void BM_ModesPipelineGrowth(benchmark::State& st) {
  const mmv::ArticleScene coarse = sceneWith(64), fine = sceneWith(1024);
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](const mmv::ArticleScene& s) {
    const auto t0 = Clock::now();
    benchmark::DoNotOptimize(mmv::solveSceneModes(s, {}, 12));
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  double t_coarse = 1e300, t_fine = 1e300;
  for (auto _ : st) {
    t_coarse = std::min(t_coarse, seconds(coarse));
    t_fine = std::min(t_fine, seconds(fine));
  }
  st.counters["t_256_dof_ms"] = 1e3 * t_coarse;
  st.counters["t_4096_dof_ms"] = 1e3 * t_fine;
  st.counters["exponent"] = std::log(t_fine / t_coarse) / std::log(16.0);
}
BENCHMARK(BM_ModesPipelineGrowth)->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace

// Linear models and synthesis (issues 3 and 5), at the default 16 segments unless the
// argument says otherwise.
#include "sim/modes/cms.hpp"
#include "sim/linear/state_space.hpp"

namespace {

void BM_LinearModel(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::buildLinearModel(s, mmv::defaultInputs(), mmv::defaultOutputs(s), {}));
}
BENCHMARK(BM_LinearModel)->Apply(segmentArgs);

void BM_ReduceModal(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  const mmv::LinearModel lm = mmv::buildLinearModel(s, mmv::defaultInputs(), mmv::defaultOutputs(s), {});
  mmv::ReductionOptions o;
  o.modes = 8;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::reduceModal(lm.full, o));
}
BENCHMARK(BM_ReduceModal)->Apply(segmentArgs);

void BM_FrfPointFull(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  const mmv::LinearModel lm = mmv::buildLinearModel(s, mmv::defaultInputs(), mmv::defaultOutputs(s), {});
  for (auto _ : st) benchmark::DoNotOptimize(lm.second_order.response(2 * M_PI * 3.3));
}
BENCHMARK(BM_FrfPointFull)->Apply(segmentArgs);

void BM_SynthesisAssumedModes(benchmark::State& st) {
  const mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  mmv::SynthesisOptions o;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::synthesize(s, o));
}
BENCHMARK(BM_SynthesisAssumedModes)->Apply(segmentArgs);

}  // namespace

// HAM-SAS (scenes/hamsas.yaml): linearization with preloads, eigen solution and
// feature identification, stiff springs (0) and ideal joints (1); one 6 x 6
// transmissibility point.
mmv::HamsasSpec hamsasScene(bool ideal) {
  mmv::HamsasSpec h = mmv::loadHamsasSceneFile(MMVLAB_SOURCE_DIR "/scenes/hamsas.yaml").isolator;
  h.ideal_joints = ideal;
  return h;
}

void BM_HamsasModes(benchmark::State& st) {
  const mmv::HamsasSpec h = hamsasScene(st.range(0) != 0);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::analyseHamsas(h));
}
BENCHMARK(BM_HamsasModes)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_HamsasTransmissibilityPoint(benchmark::State& st) {
  const mmv::HamsasModes h = mmv::analyseHamsas(hamsasScene(false));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::spatialTransmissibility(h.model, h.lin, 2 * M_PI * 10.0));
}
BENCHMARK(BM_HamsasTransmissibilityPoint)->Unit(benchmark::kMicrosecond);

namespace {

// `modes --target-error E` (segmentsForTarget): the ladder 1, 2, 4, ... up to the count
// that holds the 12 modes within E (arg: -log10 E), on the default article.
void BM_SegmentsForTarget(benchmark::State& st) {
  const mmv::ArticleScene s = mmv::loadDefaultScene();
  const double target = std::pow(10.0, -static_cast<double>(st.range(0)));
  mmv::SegmentsChoice c;
  for (auto _ : st) c = mmv::segmentsForTarget(s, 12, target, 256);
  st.counters["segments"] = c.segments;
}
BENCHMARK(BM_SegmentsForTarget)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond);

// The spatial article (`modes --set model=spatial`, docs/spatial.md) at N segments per
// link: the report `modes` prints (equilibrium, linearization, every mode through the
// 50 Hz band, families, planarity report) without the discretization estimate.
void BM_SpatialModesReport(benchmark::State& st) {
  mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  s.article.model = mmv::ArticleModel::Spatial;
  mmv::ModesOptions opt;
  opt.max_modes = 12;
  mmv::ModesReport r;
  for (auto _ : st) r = mmv::runModes(s, opt);
  st.counters["dofs"] = r.model.num_dofs;
}
BENCHMARK(BM_SpatialModesReport)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

// The same with links 1 and 2 planar (`links.<name>.model: planar`): only link 3's rods
// bend out of the plane and twist.
void BM_SpatialLink3ModesReport(benchmark::State& st) {
  mmv::ArticleScene s = sceneWith(static_cast<int>(st.range(0)));
  s.article.model = mmv::ArticleModel::Spatial;
  for (auto& l : s.article.links)
    if (l.name == "link1" || l.name == "link2") l.model = mmv::ArticleModel::Planar;
  mmv::ModesOptions opt;
  opt.max_modes = 12;
  mmv::ModesReport r;
  for (auto _ : st) r = mmv::runModes(s, opt);
  st.counters["dofs"] = r.model.num_dofs;
}
BENCHMARK(BM_SpatialLink3ModesReport)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace
