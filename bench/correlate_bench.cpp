// Cost of `correlate`'s parts (sim/linear/correlation.hpp): reading the measured UFF
// file, the whole correlation against the table scene by segments per link, and the
// modal damping ratios `modes` adds on a damped scene. Figures are recorded in
// docs/benchmarks.md with the command that produced them.

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "sim/io/correlation_report.hpp"
#include "sim/io/uff_read.hpp"
#include "sim/linear/correlation.hpp"
#include "sim/modes/damping.hpp"
#include "sim/modes/system_modes.hpp"

namespace {

const std::string& measuredText() {
  static const std::string text = [] {
    std::ifstream in(std::string(MMVLAB_SOURCE_DIR) + "/docs/figures/correlate/measured.uff");
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
  }();
  return text;
}

mmv::ArticleScene tableScene(int segments) {
  mmv::ArticleScene s =
      std::get<mmv::ArticleScene>(mmv::loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml"));
  mmv::overrideSegments(s, segments);
  return s;
}

void BM_UffRead(benchmark::State& st) {  // 16 FRFs of 537 points, 12 modes at 76 nodes
  for (auto _ : st) benchmark::DoNotOptimize(mmv::uff::read(measuredText()));
  st.SetBytesProcessed(static_cast<int64_t>(st.iterations() * measuredText().size()));
}
BENCHMARK(BM_UffRead)->Unit(benchmark::kMillisecond);

void BM_Correlate(benchmark::State& st) {
  const mmv::ArticleScene scene = tableScene(static_cast<int>(st.range(0)));
  const mmv::MeasuredSet test = mmv::measuredSet(mmv::uff::read(measuredText()), "measured.uff");
  mmv::CorrelateOptions o;
  o.model_modes = 12;
  o.damping = *scene.damping;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::correlate(scene, test, o));
}
BENCHMARK(BM_Correlate)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

void BM_ModalDamping(benchmark::State& st) {  // 12 modes, every mode of the model in the basis
  const mmv::ArticleScene scene = tableScene(static_cast<int>(st.range(0)));
  const mmv::SolvedScene s = mmv::solveScene(scene);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::modalDamping(*s.model, s.linearized, s.modes, *scene.damping, 12));
  st.counters["basis_modes"] = static_cast<double>(s.modes.shapes.cols());
}
BENCHMARK(BM_ModalDamping)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
