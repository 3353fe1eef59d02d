// The plausibility rules (sim/scene/plausibility.hpp), each at its bound and one past it,
// with the key's position in the scene file and the likely slip named.
#include "sim/scene/plausibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "article/section.hpp"

namespace mmv {
namespace {

ArticleScene defaultWith(const std::vector<std::string>& sets) {
  return std::get<ArticleScene>(parseScene(defaultSceneYaml(), "mmv.yaml", sets));
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

TEST(Plausibility, TheDefaultSceneIsPlausible) { EXPECT_TRUE(scenePlausibility(loadDefaultScene()).empty()); }

TEST(Plausibility, EachRuleAtItsBoundAndOnePast) {
  using namespace plausible;
  struct Case {
    std::string set_at_bound, set_past, says;
  };
  const std::vector<Case> cases = {
      {"materials.s_glass_epoxy.youngs_modulus=1e8", "materials.s_glass_epoxy.youngs_modulus=0.99e8", "softer than rubber: GPa or MPa written as Pa?"},
      {"materials.s_glass_epoxy.youngs_modulus=1.2e12", "materials.s_glass_epoxy.youngs_modulus=1.21e12", "stiffer than diamond"},
      {"materials.carbon_carbon.density=25000", "materials.carbon_carbon.density=25001", "above any metal's"},
      {"materials.carbon_carbon.density=100", "materials.carbon_carbon.density=99", "given in g/cm^3"},
      {"links.link1.length=20", "links.link1.length=20.01", "longer than a lab can hold"},
      {"gravity=[0,-9.9,0]", "gravity=[0,-9.91,0]", "not a laboratory's"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.set_past);
    EXPECT_EQ(joined(scenePlausibility(defaultWith({c.set_at_bound}))), "");
    const std::vector<std::string> w = scenePlausibility(defaultWith({c.set_past}));
    ASSERT_EQ(w.size(), 1u) << joined(w);
    EXPECT_NE(w[0].find(c.says), std::string::npos) << w[0];
    EXPECT_EQ(w[0].rfind("--set " + c.set_past + ": ", 0), 0u) << w[0];  // an override's position is the override
  }
  // In the file, the key's line and column.
  std::string text = defaultSceneYaml();
  const std::string was = "youngs_modulus: 61.0e9";
  const auto at = text.find(was);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, was.size(), "youngs_modulus: 61");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const std::vector<std::string> w = scenePlausibility(std::get<ArticleScene>(parseScene(text, "mmv.yaml")));
  ASSERT_EQ(w.size(), 1u) << joined(w);
  EXPECT_EQ(w[0].rfind("mmv.yaml:" + std::to_string(line) + ":", 0), 0u) << w[0];
  EXPECT_NE(w[0].find("youngs_modulus 61 Pa is softer than rubber"), std::string::npos) << w[0];
}

// The tip mass over the link's own mass (link 3's branch: 0.762 m of a 2.54 mm S-glass
// rod, 8.2 g): 100 times is the bound; 20 kg, the case, is 2400 times.
TEST(Plausibility, ATipMassGramsWrittenAsKilograms) {
  const ArticleScene s = loadDefaultScene();
  const LinkSpec& branch = *std::find_if(s.article.links.begin(), s.article.links.end(), [](const LinkSpec& l) { return l.name == "link3a"; });
  const double mass = s.article.findMaterial(branch.material)->density * sectionArea(*s.article.findSection(branch.section)) * branch.length;
  EXPECT_NEAR(mass, 0.00815, 2e-4);
  const auto at = [&](double m) { return scenePlausibility(defaultWith({"links.link3.tip_mass.mass=" + std::to_string(m)})); };
  EXPECT_TRUE(at(plausible::kMaxTipMassRatio * mass * (1 - 1e-9)).empty());
  const std::vector<std::string> w = at(20.0);
  ASSERT_EQ(w.size(), 2u) << joined(w);  // both branches carry it
  char expected[96];
  std::snprintf(expected, sizeof expected, "tip_mass 20 kg is %.0f times the link's own", 20.0 / mass);
  EXPECT_NE(w[0].find(expected), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("grams written as kg?"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace mmv
