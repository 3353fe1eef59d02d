// Sensor placement as `mmvlab place-sensors` runs it: the default article's modes
// below 50 Hz, candidates every `spacing` along every link (two directions each).
// Arg: candidate count (about); the spacing follows from the article's 5.48 m of links.

#include <benchmark/benchmark.h>

#include "sim/modes/place_sensors.hpp"

namespace {

void BM_PlaceSensorsEfI(benchmark::State& st) {
  const mmv::ArticleScene scene = mmv::loadDefaultScene();
  mmv::PlacementOptions o;
  o.spacing_m = 2 * 5.484 / static_cast<double>(st.range(0));
  o.count = 10;
  std::size_t candidates = 0;
  for (auto _ : st) candidates = mmv::runPlacement(scene, o).candidates.size();
  st.counters["candidates"] = static_cast<double>(candidates);
}
BENCHMARK(BM_PlaceSensorsEfI)->Arg(114)->Arg(500)->Unit(benchmark::kMillisecond);

}  // namespace
