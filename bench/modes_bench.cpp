// Cost of the `modes` pipeline on the default MMV scene against segments per link:
// model build, static equilibrium, linearization, eigen solution, and all of it.
// Figures are recorded in docs/benchmarks.md with the command that produced them.

#include <benchmark/benchmark.h>

#include "article/article_builder.hpp"
#include "sim/analysis.hpp"
#include "sim/linearize.hpp"
#include "sim/modal.hpp"
#include "sim/statics.hpp"

namespace {

mmv::Scene sceneWith(int segments) {
  mmv::Scene s = mmv::loadDefaultScene();
  mmv::overrideSegments(s, segments);
  return s;
}

void segmentArgs(benchmark::internal::Benchmark* b) {
  for (int n : {4, 8, 16, 32, 64}) b->Arg(n);
  b->Unit(benchmark::kMillisecond);
}

void BM_Build(benchmark::State& st) {
  const mmv::Scene s = sceneWith(static_cast<int>(st.range(0)));
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

void BM_Eigen(benchmark::State& st) {
  const auto model = mmv::buildArticleModel(sceneWith(static_cast<int>(st.range(0))));
  const mmv::EquilibriumResult eq = mmv::solveEquilibrium(*model);
  const mmv::LinearizedModel lin = mmv::linearize(*model, eq.state);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveModes(lin.M, lin.K));
}
BENCHMARK(BM_Eigen)->Apply(segmentArgs);

void BM_ModesPipeline(benchmark::State& st) {
  const mmv::Scene s = sceneWith(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(mmv::solveSceneModes(s));
}
BENCHMARK(BM_ModesPipeline)->Apply(segmentArgs);

}  // namespace
