// mmvlab as a user runs it, for stations, sensor placement and renders: the
// commands' files, and bad input refused with nothing written.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace {
using namespace mmv::cli_testing;
}  // namespace

namespace {

// Stations name points of the physical article: the same station gives the same
// answer on two meshes (within the discretization error), where a hinge name moves.
TEST_F(Cli, ModesAndFrfAcceptStations) {
  const Result a = run("modes --json --modes 1 --segments 16 --points link1@1.83m");
  const Result b = run("modes --json --modes 1 --segments 32 --points link1@1.83m");
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const double ya = nlohmann::json::parse(a.out)["modes"][0]["at_points"][0]["uy_per_modal_unit"].get<double>();
  const double yb = nlohmann::json::parse(b.out)["modes"][0]["at_points"][0]["uy_per_modal_unit"].get<double>();
  EXPECT_NEAR(ya, yb, 2e-3 * std::abs(yb));  // O(h^2): 16 -> 32 segments changes the shape by ~0.1 %
  const Result bad = run("modes --points link1@3m");
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.err.find("--points: station 'link1@3m': 3m is outside link1 (0 to 2.44 m)"), std::string::npos) << bad.err;
  EXPECT_EQ(bad.out, "");
  const fs::path out = dir_ / "frf";
  const Result f = run("frf " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml").string() +
                       " --input table_x --output link1@0.5:x --points 20 --out " + out.string());
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_TRUE(fs::exists(out / "frf_link1_0.5_x__table_x.csv"));
  EXPECT_NE(slurp(out / "frf.uff").find("link1@0.5:x / table_x"), std::string::npos);
  EXPECT_EQ(run("frf --output link1@2:x").code, 64);
}

// A scene's accelerometer may sit at a station.
TEST_F(Cli, SensorAtAStation) {
  std::string text = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml");
  const auto at = text.find("point: link1.tip");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 16, "point: link1@0.9");
  const fs::path scene = dir_ / "station.yaml";
  std::ofstream(scene) << text;
  const Result r = run("simulate --duration 0.1 --segments 2 --json " + scene.string());
  ASSERT_EQ(r.code, 0) << r.err;
  text.replace(text.find("point: link1@0.9"), 16, "point: link1@1.9");
  std::ofstream(scene) << text;
  const Result bad = run("simulate --duration 0.1 --segments 2 " + scene.string());
  EXPECT_EQ(bad.code, 65);
  EXPECT_NE(bad.err.find("station.yaml:"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("fraction 1.9 is outside 0 to 1"), std::string::npos) << bad.err;
}

}  // namespace

namespace {

// mmvlab place-sensors on the default article: the modes below 50 Hz, EfI, files
// written once and nothing on bad input.
TEST_F(Cli, PlaceSensorsOnTheDefaultArticle) {
  const fs::path out = dir_ / "place";
  const Result r = run("place-sensors --count 10 --json --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "place-sensors");
  EXPECT_EQ(j["chosen"].size(), 10u);
  for (const auto& f : j["target_frequencies_hz"]) EXPECT_LT(f.get<double>(), 50.0);
  EXPECT_GE(j["target_modes"].size(), 6u);
  EXPECT_GT(j["fisher_determinant"].get<double>(), 0.0);
  for (const char* f : {"placement.json", "candidates.csv", "automac.csv", "automac.png", "review_sensors.png", "review_modes.png", "summary.png"})
    EXPECT_TRUE(isPng(out / f) || std::string(f).find(".png") == std::string::npos) << f;
  const std::string csv = slurp(out / "candidates.csv");
  EXPECT_EQ(csv.rfind("station,link,x_along_link_m,axis,world_x_m,world_y_m,world_z_m,chosen,score,fixed\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + static_cast<long>(j["candidates"].get<int>()));
  // Triaxial blocks and the other rankings run too.
  EXPECT_EQ(run("place-sensors --count 5 --triaxial").code, 0);
  EXPECT_EQ(run("place-sensors --count 5 --method dpr --modes 1-4").code, 0);
}

TEST_F(Cli, PlaceSensorsOnHamsas) {
  const fs::path out = dir_ / "hamsas";
  const Result r = run("place-sensors " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                       " --below-hz 5 --count 12 --json --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["target_modes"].size(), 9u);
  EXPECT_EQ(j["candidates"].get<int>(), 270);  // 10 moving bodies x 9 points x 3 axes
  EXPECT_LT(j["max_offdiagonal_automac"].get<double>(), 0.1);
  for (const char* f : {"review_sensors.png", "review_modes.png", "automac.png", "summary.png"}) EXPECT_TRUE(isPng(out / f)) << f;
}

TEST_F(Cli, PlaceSensorsBadInput) {
  const Result big = run("place-sensors --count 1000 --out " + (dir_ / "x").string());
  EXPECT_EQ(big.code, 64);
  EXPECT_NE(big.err.find("--count 1000: there are 114 candidate sensors"), std::string::npos) << big.err;
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  EXPECT_EQ(run("place-sensors --modes 0-3").code, 64);
  const Result none = run("place-sensors --modes 999");
  EXPECT_EQ(none.code, 64);
  EXPECT_NE(none.err.find("mode 999 does not exist"), std::string::npos) << none.err;
  EXPECT_EQ(run("place-sensors --method best").code, 64);
  EXPECT_EQ(run("place-sensors --count 2 --modes 1-8").code, 64);  // EfI needs one direction per mode
  EXPECT_EQ(run("place-sensors " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string()).code, 64);
  const Result ro = run("place-sensors --out /proc/mmvlab-placement");
  EXPECT_EQ(ro.code, 73);
  EXPECT_EQ(ro.out, "");
}

}  // namespace

namespace {

// mmvlab render: a PNG of the article, a mode, a contact sheet; bad input refused with
// nothing written.
TEST_F(Cli, RenderWritesFramesAndRefusesBadInput) {
  ::unsetenv("DISPLAY");
  const fs::path png = dir_ / "article.png", sheet = dir_ / "sheet.png";
  ASSERT_EQ(run("render --size 320x240 --out " + png.string()).code, 0);
  EXPECT_TRUE(isPng(png));
  const Result again = run("render --size 320x240 --out " + png.string());
  EXPECT_EQ(again.code, 73);  // would replace a file
  EXPECT_EQ(run("render --size 320x240 --out " + png.string() + " --force --mode 2 --view iso").code, 0);
  ASSERT_EQ(run("render --size 200x150 --mode 1-4 --out " + sheet.string()).code, 0);
  EXPECT_TRUE(isPng(sheet));
  const fs::path isolator = dir_ / "hamsas.png";
  ASSERT_EQ(run("render " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() + " --mode 2 --size 320x240 --out " +
                isolator.string()).code, 0);
  EXPECT_TRUE(isPng(isolator));
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  EXPECT_EQ(run("render " + slew + " --view sensor:acc_link2_tip --size 320x240 --out " + (dir_ / "close.png").string()).code, 0);
  const Result nosensor = run("render " + slew + " --view sensor:acc9 --out " + (dir_ / "v.png").string());
  EXPECT_EQ(nosensor.code, 64);
  EXPECT_NE(nosensor.err.find("no sensor 'acc9' in the scene (known: "), std::string::npos) << nosensor.err;
  // A camera pose the scene names (views:).
  std::string withview = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml");
  withview += "views:\n  close: {eye: [2.5, -3, 2], target: [2.5, -3, 0], fov_deg: 40}\n";
  const fs::path vs = dir_ / "views.yaml";
  std::ofstream(vs) << withview;
  EXPECT_EQ(run("render " + vs.string() + " --view close --size 320x240 --out " + (dir_ / "close2.png").string()).code, 0);
  const Result unknown_view = run("render " + vs.string() + " --view far --out " + (dir_ / "v.png").string());
  EXPECT_EQ(unknown_view.code, 64);
  EXPECT_NE(unknown_view.err.find("sensor:NAME, close)"), std::string::npos) << unknown_view.err;
  EXPECT_EQ(run("render --view underneath --out " + (dir_ / "v.png").string()).code, 64);
  EXPECT_EQ(run("render --mode 999 --out " + (dir_ / "m.png").string()).code, 64);
  EXPECT_EQ(run("render --out " + (dir_ / "m.gif").string()).code, 64);
  EXPECT_EQ(run("render --size 10x10 --out " + (dir_ / "s.png").string()).code, 64);
  EXPECT_EQ(run("render --out " + (dir_ / "no" / "such" / "dir.png").string()).code, 73);
  for (const char* f : {"v.png", "m.png", "m.gif", "s.png"}) EXPECT_FALSE(fs::exists(dir_ / f)) << f;
  for (const auto& e : fs::directory_iterator(dir_)) EXPECT_EQ(e.path().filename().string().rfind(".mmvlab-", 0), std::string::npos);
}

}  // namespace
