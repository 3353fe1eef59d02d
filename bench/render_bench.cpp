// Off-screen frames as `mmvlab render` draws them: the default article at its
// equilibrium, and one frame of mode 1's animation (the shape prepared once), at
// 1280x720 and 1920x1080 with 3x supersampling.

#include <benchmark/benchmark.h>

#include "renders/frame.hpp"
#include "sim/io/article_drawing.hpp"

namespace {

void BM_RenderArticleFrame(benchmark::State& st) {
  const mmv::ArticleScene scene = mmv::loadDefaultScene();
  const mmv::SolvedScene solved = mmv::solveScene(scene);
  SimTK::State s = solved.equilibrium.state;
  solved.model->getSystem().realize(s, SimTK::Stage::Position);
  const mmv::DrawList d = mmv::drawArticle(scene, *solved.model, s);
  mmv::Camera c;
  mmv::presetCamera("front", d.bounds(), c);
  const mmv::render::FrameOptions o{static_cast<int>(st.range(0)), static_cast<int>(st.range(1)), 3};
  mmv::render::renderFrame(d, c, o);  // the OSMesa context is made once per size, outside the timing
  for (auto _ : st) benchmark::DoNotOptimize(mmv::render::renderFrame(d, c, o));
}
BENCHMARK(BM_RenderArticleFrame)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond);

void BM_RenderModeFrame(benchmark::State& st) {
  const mmv::ArticleScene scene = mmv::loadDefaultScene();
  const mmv::SolvedScene solved = mmv::solveScene(scene);
  const mmv::ModeFrames frames(scene, solved, 0, 0.0);
  mmv::Camera c;
  mmv::presetCamera("front", frames.frame(1.0).bounds(), c);
  const mmv::render::FrameOptions o{static_cast<int>(st.range(0)), static_cast<int>(st.range(1)), 3};
  double phase = 0;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::render::renderFrame(frames.frame(std::sin(phase += 0.1)), c, o));
}
BENCHMARK(BM_RenderModeFrame)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond);

}  // namespace
