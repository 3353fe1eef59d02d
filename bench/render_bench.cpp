// Off-screen frames as `mmvlab render` draws them: the default article at its
// equilibrium, and one frame of mode 1's animation (the shape prepared once), at
// 1280x720 and 1920x1080 with 3x supersampling.

#include <benchmark/benchmark.h>

#include <cmath>

#include "renders/frame.hpp"
#include "sim/view/article_drawing.hpp"
#include "sim/view/hamsas_drawing.hpp"
#include "sim/view/run_pose.hpp"
#include "sim/io/run_dir.hpp"
#include "sim/io/simulation_report.hpp"
#include "sim/model/article_builder.hpp"

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
  const mmv::ModeFrames frames(scene, solved, mmv::ModeNumber(1), 0.0);
  mmv::Camera c;
  mmv::presetCamera("front", frames.frame(1.0).bounds(), c);
  const mmv::render::FrameOptions o{static_cast<int>(st.range(0)), static_cast<int>(st.range(1)), 3};
  double phase = 0;
  for (auto _ : st) benchmark::DoNotOptimize(mmv::render::renderFrame(frames.frame(std::sin(phase += 0.1)), c, o));
}
BENCHMARK(BM_RenderModeFrame)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

void BM_RenderHamsasFrame(benchmark::State& st) {
  const mmv::HamsasScene scene = mmv::loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  const mmv::HamsasModes modes = mmv::analyseHamsas(scene.isolator);
  const mmv::DrawList d = mmv::drawHamsas(scene, modes);
  mmv::Camera c;
  mmv::presetCamera("iso", d.bounds(), c, d.up);
  const mmv::render::FrameOptions o{static_cast<int>(st.range(0)), static_cast<int>(st.range(1)), 3};
  mmv::render::renderFrame(d, c, o);
  for (auto _ : st) benchmark::DoNotOptimize(mmv::render::renderFrame(d, c, o));
}
BENCHMARK(BM_RenderHamsasFrame)->Args({1280, 720})->Args({1920, 1080})->Unit(benchmark::kMillisecond);

/// One frame of `render --history`: the run's coordinates at a time set on the model,
/// the article drawn, rendered at 60 % of the width, and a panel of two sensor traces.
void BM_RenderHistoryFrame(benchmark::State& st) {
  mmv::ArticleScene scene = mmv::loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml");
  scene.simulation.duration = 1.0;
  const mmv::SimulationResult r = mmv::simulate(scene);
  mmv::RunDir run;
  run.scene = scene;
  run.states = mmv::parseNumericCsv(mmv::simulationHistoryCsv(r.states), "states.csv");
  const auto model = mmv::buildArticleModel(scene);
  SimTK::State s = model->getReferenceState();
  std::vector<mmv::render::Trace> traces(2);
  for (const auto& row : r.record.rows)
    for (int k = 0; k < 2; ++k) traces[k].t.push_back(row[0]), traces[k].v.push_back(row[row.size() - 1 - k]);
  mmv::setRunPose(mmv::rowAt(run.states, 0.0), 0.0, *model, s);
  mmv::Camera c;
  mmv::presetCamera("front", mmv::drawArticle(scene, *model, s).bounds(), c);
  const mmv::render::FrameOptions o{768, 720, 3};
  double t = 0;
  for (auto _ : st) {
    t = std::fmod(t + 1.0 / 30, 1.0);
    mmv::setRunPose(mmv::rowAt(run.states, t), t, *model, s);
    cv::Mat img;
    cv::hconcat(mmv::render::renderFrame(mmv::drawArticle(scene, *model, s), c, o), mmv::render::tracePanel(traces, t, {512, 720}), img);
    benchmark::DoNotOptimize(img);
  }
}
BENCHMARK(BM_RenderHistoryFrame)->Unit(benchmark::kMillisecond);

}  // namespace
