// The sensors' own masses (place-sensors --sensor-mass, sim/modes/sensor_loading.hpp):
// a station mass is the point mass it says it is, small masses shift the modes as
// first-order perturbation theory says, heavy ones are flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/modes/place_sensors.hpp"
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

}  // namespace
}  // namespace mmv
