// Cost of a time run (`mmvlab simulate`) against segments per link and integrator: the
// default MMV article, joint 2 slewing 0 -> 45 deg (cycloidal) in 1.5 s of simulated
// time at accuracy 1e-6, recorded at 50 Hz. Wall time per run; the counters give the
// integrator's steps and right-hand-side evaluations (realizations).
// Figures are recorded in docs/benchmarks.md with the command that produced them.

#include <benchmark/benchmark.h>

#include <cmath>

#include "sim/modes/system_modes.hpp"
#include "sim/time/simulation.hpp"

namespace {

const char* const kIntegrators[] = {"rk_merson", "cpodes", "cvode_bdf", "arkode_dirk"};

void BM_Slew(benchmark::State& st) {
  mmv::ArticleScene s = mmv::loadDefaultScene();
  mmv::overrideSegments(s, static_cast<int>(st.range(0)));
  mmv::SlewSpec slew;
  slew.to = 45 * M_PI / 180;
  s.article.joints[1].slew = slew;
  s.simulation.duration = 1.5;
  s.simulation.sample_rate_hz = 50;
  s.simulation.accuracy = 1e-6;
  s.simulation.integrator = kIntegrators[st.range(1)];
  st.SetLabel(s.simulation.integrator);
  mmv::SimulationResult r;
  for (auto _ : st) r = mmv::simulate(s);
  st.counters["steps"] = r.steps;
  st.counters["evals"] = r.realizations;
}
BENCHMARK(BM_Slew)
    ->ArgsProduct({{4, 8, 16}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace
