// The strength keys (docs/strength.md): allowables, factors of safety (1 is their bound:
// accepted here; 0.99 is refused in reader_test.cpp's bad cases) and an explicit
// section's fibre distances, read as written; without `strength:` the defaults stand,
// marked so.
#include <gtest/gtest.h>

#include <string>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

ArticleScene parse(const std::string& materials, const std::string& extra, const std::string& section) {
  const std::string text = "name: one link\ngravity: [0, -9.81, 0]\n" + extra + "materials:\n  steel: {density: 7800, youngs_modulus: 2.0e11" +
                           materials + "}\nsections:\n  bar: " + section +
                           "\njoints:\n  - {name: j1, parent: base}\nlinks:\n  - {name: l1, joint: j1, material: steel, section: bar, "
                           "length: 1.0, segments: 4}\n";
  return std::get<ArticleScene>(parseScene(text, "s.yaml"));
}

TEST(StrengthKeys, DefaultsWithoutThem) {
  const ArticleScene s = parse("", "", "{shape: rectangle, b: 0.02, h: 0.01}");
  EXPECT_FALSE(s.article.strength.given);
  EXPECT_EQ(s.article.strength.yield_factor, 1.25);
  EXPECT_EQ(s.article.strength.ultimate_factor, 1.4);
  EXPECT_EQ(s.article.materials[0].yield_strength, 0.0);
  EXPECT_EQ(s.article.materials[0].ultimate_strength, 0.0);
  EXPECT_EQ(sectionFibreDistance(s.article.sections[0]), 0.005);  // h / 2
  EXPECT_EQ(sectionFibreDistanceOut(s.article.sections[0]), 0.01);  // b / 2
}

TEST(StrengthKeys, ReadAsWrittenWithAFactorAtItsBound) {
  const ArticleScene s = parse(", yield_strength: 250e6, ultimate_strength: 400e6", "strength: {yield_factor: 1, ultimate_factor: 1.5}\n",
                               "{shape: explicit, area: 1e-4, second_moment: 1e-9, fibre_distance: 0.006}");
  EXPECT_TRUE(s.article.strength.given);
  EXPECT_EQ(s.article.strength.yield_factor, 1.0);
  EXPECT_EQ(s.article.strength.ultimate_factor, 1.5);
  EXPECT_EQ(s.article.materials[0].yield_strength, 250e6);
  EXPECT_EQ(s.article.materials[0].ultimate_strength, 400e6);
  EXPECT_EQ(sectionFibreDistance(s.article.sections[0]), 0.006);
  EXPECT_EQ(sectionFibreDistanceOut(s.article.sections[0]), 0.0);  // not given: an explicit section's out-of-plane stress is not recovered
}

}  // namespace
}  // namespace mmv
