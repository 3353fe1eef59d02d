// The sensors' own masses (place-sensors --sensor-mass, sim/modes/sensor_loading.hpp):
// a station mass is the point mass it says it is, small masses shift the modes as
// first-order perturbation theory says, heavy ones are flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/modes/place_sensors.hpp"
#include "sim/modes/sensor_loading.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

ArticleScene article(int segments) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, segments);
  return s;
}

// A station mass at a link's tip is a tip mass of the same size: the same modes, the
// tip mass's model being checked against the cantilever's closed form elsewhere
// (tests/article/flexible_link_test.cpp).
TEST(SensorLoading, AStationMassAtTheTipIsATipMass) {
  ArticleScene station = article(8), tip = article(8);
  auto link = [](ArticleScene& s) -> LinkSpec& {
    return *std::find_if(s.article.links.begin(), s.article.links.end(), [](const LinkSpec& l) { return !l.tip_mass && !l.rigid; });
  };
  link(station).station_masses.push_back({link(station).length, 0.75});
  link(tip).tip_mass = LumpedMass{0.75, 0, {0, 0}};
  const SolvedScene a = solveScene(station, {}, 8), b = solveScene(tip, {}, 8), bare = solveScene(article(8), {}, 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(a.modes.frequencyHz(i) / b.modes.frequencyHz(i), 1.0, 1e-9) << "mode " << i + 1;
  }
  EXPECT_GT(std::abs(a.modes.frequencyHz(1) / bare.modes.frequencyHz(1) - 1), 1e-3);  // and it is felt
  // Halfway along, on a piece between hinges: less felt by the first mode than at the tip.
  ArticleScene mid = article(8);
  link(mid).station_masses.push_back({0.5 * link(mid).length, 0.75});
  const SolvedScene c = solveScene(mid, {}, 8);
  EXPECT_LT(bare.modes.frequencyHz(0) - c.modes.frequencyHz(0), bare.modes.frequencyHz(0) - a.modes.frequencyHz(0));
  EXPECT_GT(bare.modes.frequencyHz(0) - c.modes.frequencyHz(0), 0.0);
}

TEST(SensorLoading, SmallMassesShiftAsFirstOrderTheorySays) {
  PlacementOptions o;
  o.count = 12;
  o.sensor_mass_kg = 1e-6;  // a milligram: the 8 g branches of link 3 feel it at 1e-4
  // With gravity the sensors' weight also changes the geometric stiffness (a few % of
  // the shift here), which the inertial first-order formula leaves out.
  ArticleScene weightless = article(16);
  weightless.gravity = {0, 0, 0};
  const PlacementStudy p = runPlacement(weightless, o);
  ASSERT_TRUE(p.loading.has_value());
  EXPECT_EQ(p.loading->sensors, 12);
  for (const auto& m : p.loading->modes) {
    EXPECT_LT(m.shift, 0.0) << "mode " << m.mode.number();  // added mass lowers every frequency
    EXPECT_NEAR(m.shift, m.first_order, 0.01 * std::abs(m.first_order) + 1e-12) << "mode " << m.mode.number();
    EXPECT_FALSE(m.beyond_first_order);
    EXPECT_EQ(m.loaded_mode, m.mode);
    EXPECT_GT(m.mac, 0.9999);
  }
}

TEST(SensorLoading, HeavySensorsAreFlagged) {
  PlacementOptions o;
  o.count = 24;
  o.sensor_mass_kg = 0.005;  // 5 g accelerometers: link 3's branches weigh 8.2 g each
  const PlacementStudy p = runPlacement(article(16), o);
  ASSERT_TRUE(p.loading.has_value());
  int heavy = 0;
  for (const auto& m : p.loading->modes) heavy += m.beyond_first_order || m.shared;
  EXPECT_GE(heavy, 4);
}

// The scene's own sensors weigh what their instrument says, in every analysis: a 20 g
// accelerometer at link 3a's tip (read from the scene) gives the modes of a 20 g tip
// mass on that branch (set in the model) to 1e-9.
TEST(SensorLoading, TheScenesInstrumentMassIsOnTheModel) {
  std::string text = defaultSceneYaml();
  text += "\ninstruments:\n  accelerometer: {mass_kg: 0.02}\nsensors:\n"
          "  - {name: a, type: accelerometer, point: link3a.tip, axis: transverse}\n";
  ArticleScene read = std::get<ArticleScene>(parseScene(text, "s.yaml"));
  overrideSegments(read, 8);
  ArticleScene tip = article(8);
  LinkSpec& branch = *std::find_if(tip.article.links.begin(), tip.article.links.end(), [](const LinkSpec& l) { return l.name == "link3a"; });
  ASSERT_FALSE(branch.tip_mass.has_value());
  branch.tip_mass = LumpedMass{0.02, 0, {0, 0}};
  const SolvedScene a = solveScene(read, {}, 8), b = solveScene(tip, {}, 8), bare = solveScene(article(8), {}, 8);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(a.modes.frequencyHz(i) / b.modes.frequencyHz(i), 1.0, 1e-9) << "mode " << i + 1;
  double felt = 0;
  for (int i = 0; i < 8; ++i) felt = std::max(felt, std::abs(a.modes.frequencyHz(i) / bare.modes.frequencyHz(i) - 1));
  EXPECT_GT(felt, 0.05);  // 20 g on an 8 g branch
}

std::vector<std::string> chosen(const PlacementStudy& p) {
  std::vector<std::string> out;
  for (int b : p.result.kept_blocks) out.push_back(p.candidates[static_cast<std::size_t>(b)].station + " " + p.candidates[static_cast<std::size_t>(b)].axis);
  std::sort(out.begin(), out.end());
  return out;
}

// --iterate-loaded: a set that settles carries itself: placed once more (without
// iterating) on the model that carries it, the same set comes back. And with a
// milligram the first pass keeps the bare model's set.
TEST(SensorLoading, AnIteratedSetCarriesItself) {
  PlacementOptions o;
  o.count = 8;
  o.modes = modeNumbers({1, 2, 3, 4});
  o.sensor_mass_kg = 0.01;  // 10 g: the first loaded pass moves a sensor, the second settles
  o.iterate_loaded = true;
  const ArticleScene bare = article(8);
  const PlacementStudy p = runPlacement(bare, o);
  ASSERT_TRUE(p.loading.has_value());
  ASSERT_FALSE(p.loading->iterations.empty());
  const LoadedIteration& last = p.loading->iterations.back();
  ASSERT_TRUE(last.settled) << "pass " << last.pass << ": " << last.changed << " changed";
  EXPECT_GE(p.loading->iterations.size(), 2u);  // the loop ran
  EXPECT_GT(p.loading->iterations.front().changed, 0);
  PlacementOptions once = o;
  once.sensor_mass_kg = 0;
  once.iterate_loaded = false;
  const ArticleScene carrying = sceneWithSensors(bare, p, o.sensor_mass_kg);
  EXPECT_EQ(chosen(runPlacement(carrying, once)), chosen(p));
  // The loading reported is the set's on the bare article: the sensors counted once each.
  EXPECT_EQ(p.loading->sensors, 8);
  std::printf("[iterate] 10 g sensors: %zu passes, first changed %d\n", p.loading->iterations.size(),
              p.loading->iterations.front().changed);

  o.sensor_mass_kg = 1e-9;
  const PlacementStudy light = runPlacement(bare, o);
  ASSERT_EQ(light.loading->iterations.size(), 1u);
  EXPECT_TRUE(light.loading->iterations[0].settled);
  once.sensor_mass_kg = 0;
  EXPECT_EQ(chosen(light), chosen(runPlacement(bare, once)));
}

// Passes that cycle stop at the first repeated set and say so: 24 sensors of 5 g at
// least 0.15 m apart on the default article alternate between sets.
TEST(SensorLoading, IteratedPassesThatCycleStopAndSaySo) {
  PlacementOptions o;
  o.count = 24;
  o.min_separation_m = 0.15;
  o.sensor_mass_kg = 0.005;
  o.iterate_loaded = true;
  const PlacementStudy p = runPlacement(article(16), o);
  const auto& it = p.loading->iterations;
  ASSERT_FALSE(it.empty());
  EXPECT_LT(static_cast<int>(it.size()), kMaxLoadedIterations);
  EXPECT_TRUE(it.back().repeats);
  EXPECT_FALSE(it.back().settled);
  for (std::size_t k = 0; k + 1 < it.size(); ++k) EXPECT_FALSE(it[k].repeats || it[k].settled) << "pass " << k + 1;
}

}  // namespace
}  // namespace mmv
