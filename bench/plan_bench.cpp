// `mmvlab check` and `mmvlab sweep` as the commands run them: the check of the default
// article, one sweep point (modes + check), and the 1000-point sizing sweep of the
// default article (Latin hypercube over link 3's radius and length and link 2's
// length; modes + check, no time runs) on 1 and 2 threads, journal and CSV included.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <unistd.h>

#include "sim/app/design_sweep_points.hpp"
#include "sim/plan/check.hpp"
#include "sim/plan/design_sweep.hpp"

namespace {

const char* kSpec =
    "scene: " MMVLAB_SOURCE_DIR "/scenes/mmv.yaml\n"
    "parameters:\n"
    "  - {key: sections.link3_rod.radius, range: {from: 0.001, to: 0.003, samples: 2}}\n"
    "  - {key: links.link3.length, range: {from: 0.5, to: 1.0, samples: 2}}\n"
    "  - {key: links.link2.length, range: {from: 1.2, to: 1.8, samples: 2}}\n"
    "design: {type: latin_hypercube, samples: 1000, seed: 3}\n"
    "outputs: [frequencies, mass, deflection, check]\n";

void BM_CheckDefaultScene(benchmark::State& st) {
  const mmv::ArticleScene scene = mmv::loadDefaultScene();
  for (auto _ : st) benchmark::DoNotOptimize(mmv::runCheck(scene));
}
BENCHMARK(BM_CheckDefaultScene)->Unit(benchmark::kMillisecond);

void BM_SweepPoint(benchmark::State& st) {
  const mmv::DesignSweepContext c = mmv::prepareDesignSweep(mmv::parseSweepSpec(kSpec, "bench", "."));
  long i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::evaluateDesignSweepPoint(c, i++ % 1000));
}
BENCHMARK(BM_SweepPoint)->Unit(benchmark::kMillisecond);

void BM_Sweep1000(benchmark::State& st) {
  const mmv::DesignSweepContext c = mmv::prepareDesignSweep(mmv::parseSweepSpec(kSpec, "bench", "."));
  const std::string dir = std::filesystem::temp_directory_path() / ("mmvlab_bench_sweep_" + std::to_string(::getpid()));
  for (auto _ : st) {
    mmv::DesignSweepRun run;
    run.dir = dir;
    run.fingerprint = c.fingerprint;
    run.header = c.header;
    run.total_points = static_cast<long>(c.points.size());
    run.jobs = static_cast<int>(st.range(0));
    run.evaluate = [&c](long p) { return mmv::evaluateDesignSweepPoint(c, p); };
    benchmark::DoNotOptimize(mmv::runDesignSweep(run, /*restart=*/true));
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_Sweep1000)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
