// The table's dwell and random levels held to the article's strength and to a stated
// deflection limit (sim/linear/table_levels.hpp, issue 64), on the shipped table scene:
// where a link's allowable binds, its static stress plus the dwell's amplitude is its
// allowable over its factor exactly; the dwell's stress is `modes`' stress per mm of the
// mode's peak times the dwell's tip motion (two ways of one number); a deflection limit
// binds at the tip's motion it states.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/app/plan_studies.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

ArticleScene tableScene(double carbon_ultimate_pa = 0) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  for (auto& l : s.article.links) l.segments = 8;
  if (carbon_ultimate_pa > 0)
    for (auto& m : s.article.materials)
      if (m.name == "carbon_carbon") m.ultimate_strength = carbon_ultimate_pa, m.yield_strength = 0;
  return s;
}

TableLevels levels(const ArticleScene& s, double max_deflection_m = 0) {
  app::PlacementRequest r;
  r.modes = {1, 2, 3, 4};
  r.max_deflection_m = max_deflection_m;
  const app::PlacementStudyResult p = app::runPlacementStudy(s, r);
  EXPECT_TRUE(p.table_levels.has_value());
  return *p.table_levels;
}

// Carbon/carbon at 40 MPa ultimate (28.6 MPa over 1.4) leaves link 1 about 11 MPa above
// its 17.6 MPa of sag: mode 1's dwell, which the sensors' range would take to 49 MPa of
// bending in link 1, is lowered until link 1 sits at its limit; every other dwell stays
// within it. The shipped allowables (150 MPa) bind nowhere: the range does.
TEST(TableStrength, ALinksAllowableBindsExactly) {
  const TableLevels shipped = levels(tableScene());
  for (const auto& m : shipped.modes) EXPECT_EQ(m.limit, "range") << m.mode.number();
  const TableLevels weak = levels(tableScene(40e6));
  ASSERT_EQ(weak.modes.size(), 4u);
  const auto& m1 = weak.modes[0];
  EXPECT_EQ(m1.limit, "stress");
  EXPECT_EQ(m1.stress_link, "link1");
  EXPECT_NEAR(m1.stress_limit_pa, 40e6 / 1.4, 1e-6);
  EXPECT_NEAR((m1.static_stress_pa + m1.stress_amplitude_pa) / m1.stress_limit_pa, 1.0, 1e-9);
  EXPECT_LT(m1.table_acc, 0.5 * shipped.modes[0].table_acc);
  for (const auto& m : weak.modes) {
    if (m.stress_link.empty()) continue;
    EXPECT_LE(m.static_stress_pa + m.stress_amplitude_pa, m.stress_limit_pa * (1 + 1e-9)) << m.mode.number();
  }
  // The random program (0.99 mm RMS, set by the range) moves link 1 less than a dwell:
  // at 25.5 MPa (0.6 MPa above the sag over 1.4) the crest factor times its RMS stress
  // binds, and the program is lowered.
  EXPECT_EQ(weak.random.limit, "range");
  const TableLevels weaker = levels(tableScene(25.5e6));
  ASSERT_TRUE(weaker.random.program);
  EXPECT_EQ(weaker.random.limit, "stress (link1)");
  EXPECT_LT(weaker.random.rms_m, 0.5 * shipped.random.rms_m);
}

// At resonance the dwell is mode 1's (1 % damping): link 1's stress amplitude is modes'
// stress per mm of mode 1's peak translation (link 3's tip) times the dwell's tip motion
// in mm, within the other modes' share (measured 0.3 %).
TEST(TableStrength, TheDwellsStressIsTheModesStressPerMillimetre) {
  const ArticleScene s = tableScene();
  const TableLevels t = levels(s);
  ModesOptions o;
  o.max_modes = 4;
  const ModesReport modes = runModes(s, o);
  const ModeInfo& mode1 = modes.modes.front();
  ASSERT_FALSE(mode1.stress_per_mm.empty());
  const ModalLinkStress& link1 = mode1.stress_per_mm.front();
  ASSERT_EQ(link1.link, "link1");
  ASSERT_TRUE(link1.recovered);
  const auto& m = t.modes.front();
  ASSERT_EQ(m.stress_link, "link1");
  EXPECT_NEAR(m.stress_amplitude_pa / (link1.equivalent_pa_per_mm * 1e3 * m.tip_amplitude_m), 1.0, 0.02);
  EXPECT_NEAR(m.static_stress_pa / modes.static_stress.front().peak.stress.equivalent, 1.0, 1e-9);
}

// A stated deflection limit binds at the tip motion it states, and the stress shown is
// the lowered dwell's.
TEST(TableStrength, AStatedDeflectionLimitBinds) {
  const ArticleScene s = tableScene();
  const TableLevels free = levels(s), held = levels(s, 0.02);
  EXPECT_GT(free.modes[0].tip_amplitude_m, 0.5);  // 0.7 m on the 0.76 m rod: what the range alone plans
  const auto& m = held.modes[0];
  EXPECT_EQ(m.limit, "deflection");
  EXPECT_NEAR(m.tip_amplitude_m, 0.02, 1e-12);
  EXPECT_NEAR(m.stress_amplitude_pa / free.modes[0].stress_amplitude_pa, m.table_acc / free.modes[0].table_acc, 1e-9);
  for (const auto& x : held.modes) EXPECT_LE(x.tip_amplitude_m, 0.02 * (1 + 1e-12)) << x.mode.number();
}

}  // namespace
}  // namespace mmv
