// A time run read back for renders: its recorded coordinates put the model where the
// run had it (the tips land on the history's tip columns), and bad files are named.
#include <gtest/gtest.h>

#include "sim/core/text.hpp"

#include "sim/io/run_dir.hpp"
#include "sim/io/simulation_report.hpp"
#include "sim/view/run_pose.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "sim/model/article_builder.hpp"

namespace mmv {
namespace {

TEST(RunDir, RecordedCoordinatesPutTheTipsWhereTheRunHadThem) {
  ArticleScene scene = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml");
  overrideSegments(scene, 2);
  scene.simulation.duration = 0.4;
  scene.simulation.sample_rate_hz = 250;
  const SimulationResult r = simulate(scene);
  RunDir run;
  run.dir = "<test>";
  run.scene = scene;
  run.history = parseNumericCsv(simulationHistoryCsv(r.record), "history.csv");
  run.states = parseNumericCsv(simulationHistoryCsv(r.states), "states.csv");
  const auto model = buildArticleModel(scene);
  EXPECT_NO_THROW(checkRunModel(run, *model));
  SimTK::State s = model->getReferenceState();
  int checked = 0;
  for (std::size_t k = 0; k < run.history.rows.size(); k += 10) {
    setRunPose(rowAt(run.states, run.history.rows[k][0]), run.history.rows[k][0], *model, s);
    for (const char* tip : {"link2.tip", "link3a.tip"}) {
      const SimTK::Vec3 x = model->findPointLocation(s, *model->findPoint(tip));
      const int cx = run.history.column(csvColumnName(std::string(tip) + "_x_m")),
                cy = run.history.column(csvColumnName(std::string(tip) + "_y_m"));
      ASSERT_GT(cx, 0);
      EXPECT_NEAR(x[0], run.history.rows[k][static_cast<std::size_t>(cx)], 1e-8) << tip << " at row " << k;
      EXPECT_NEAR(x[1], run.history.rows[k][static_cast<std::size_t>(cy)], 1e-8) << tip << " at row " << k;
      ++checked;
    }
  }
  EXPECT_GE(checked, 20);
  // Between two samples: the coordinates halfway.
  const auto& a = run.states.rows[3], &b = run.states.rows[4];
  setRunPose(rowAt(run.states, 0.5 * (a[0] + b[0])), 0.5 * (a[0] + b[0]), *model, s);
  for (int i = 0; i < model->getNumCoordinates(); ++i)
    EXPECT_NEAR(s.getQ()[model->getQIndex(i)], 0.5 * (a[i + 1] + b[i + 1]), 1e-15);
  // Another mesh is another model: refused.
  ArticleScene finer = scene;
  overrideSegments(finer, 3);
  EXPECT_THROW(checkRunModel(run, *buildArticleModel(finer)), SceneError);
}

// HAM-SAS runs record every body's motion: the optical table's and the base's columns
// are the history's table and ground columns, sample by sample.
TEST(RunDir, IsolatorRunsRecordEveryBody) {
  HamsasScene scene = loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  scene.simulation.duration = 0.1;
  scene.simulation.sample_rate_hz = 100;
  const SimulationResult r = simulate(scene);
  const CsvTable history = parseNumericCsv(simulationHistoryCsv(r.record), "history.csv");
  const CsvTable states = parseNumericCsv(simulationHistoryCsv(r.states), "states.csv");
  ASSERT_EQ(history.rows.size(), states.rows.size());
  EXPECT_EQ(states.columns.size(), 1 + 6 * 11u);
  const int ot = states.column("optical_table_x_m"), ot_h = history.column("optical_table_x_m");
  const int base = states.column("base_x_m"), ground = history.column("ground_x_m");
  ASSERT_GT(ot, 0);
  ASSERT_GT(base, 0);
  double moved = 0;
  for (std::size_t k = 0; k < states.rows.size(); ++k) {
    EXPECT_EQ(states.rows[k][static_cast<std::size_t>(ot)], history.rows[k][static_cast<std::size_t>(ot_h)]);
    EXPECT_EQ(states.rows[k][static_cast<std::size_t>(base)], history.rows[k][static_cast<std::size_t>(ground)]);
    moved = std::max(moved, std::abs(states.rows[k][static_cast<std::size_t>(base)]));
  }
  EXPECT_GT(moved, 0.0);
}

TEST(RunDir, MalformedCsvIsNamedAtItsLineAndColumn) {
  auto message = [](const std::string& text) {
    try {
      parseNumericCsv(text, "h.csv");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("time_s,a\n0,1\n0.1,nan\n"), "h.csv:3:5: nan is not a finite number");
  EXPECT_EQ(message("time_s,a\n0,1\n0.1\n"), "h.csv:3:1: 1 values, the header has 2 columns");
  EXPECT_EQ(message("time_s,a\n0,1\n0,2\n"), "h.csv:3:1: time 0 s does not increase");
  EXPECT_EQ(message("t,a\n0,1\n"), "h.csv:1:1: the first column must be time_s (got t)");
  EXPECT_EQ(message(""), "h.csv:1:1: empty (expected a header row)");
  EXPECT_EQ(message("time_s,a\n0,1\n"), "h.csv: fewer than two rows");
}

}  // namespace
}  // namespace mmv
