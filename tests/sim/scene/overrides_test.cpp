// --set KEY=VALUE: any scene key by its path, checked exactly as if it were in the
// file, an error naming the override instead of a line.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

const char* kTwoLinks = R"(name: two links
gravity: [0, -9.81, 0]
materials:
  steel: {density: 7800, youngs_modulus: 2.0e11}
sections:
  bar: {shape: rectangle, b: 0.02, h: 0.01}
joints:
  - name: j1
    parent: base
    angle_deg: 30
  - name: j2
    parent: l1
    hold: free
links:
  - name: l1
    joint: j1
    material: steel
    section: bar
    length: 1.0
    segments: 4
  - name: l2
    joint: j2
    material: steel
    section: bar
    length: 0.5
    segments: 2
)";

ArticleScene withSets(const std::vector<std::string>& sets, const std::string& text = kTwoLinks) {
  return std::get<ArticleScene>(parseScene(text, "s.yaml", sets));
}

std::string overrideErrorOf(const std::vector<std::string>& sets, const std::string& text = kTwoLinks) {
  try {
    withSets(sets, text);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

/// The message after the position ("s.yaml:L:C: " or "--set K=V: ").
std::string afterPosition(const std::string& message, const std::string& position) {
  EXPECT_EQ(message.rfind(position, 0), 0u) << message;
  return message.substr(std::min(message.size(), position.size()));
}

TEST(SceneOverrides, EveryKindOfKey) {
  const ArticleScene s = withSets({"links.l1.length=2.5",                // a list item by its name
                                   "materials.steel.youngs_modulus=7e10",  // a mapping inside a mapping
                                   "joints.1.hold=locked",                 // a list item by its index
                                   "gravity=[0, -1.62, 0]",                // a list value
                                   "name=on the Moon",                     // a top-level scalar
                                   "links.l2.segments=rigid",              // a word
                                   "lab.hole_side_m=1.2",                  // a section the file does not have
                                   "base.gimbal.pitch.angle_deg=10"});     // nested sections it does not have
  EXPECT_EQ(s.article.links[0].length, 2.5);
  EXPECT_EQ(s.article.materials[0].youngs_modulus, 7e10);
  EXPECT_EQ(s.article.joints[1].hold, JointHold::Locked);
  EXPECT_EQ(s.gravity[1], -1.62);
  EXPECT_EQ(s.name, "on the Moon");
  EXPECT_TRUE(s.article.links[1].rigid);
  ASSERT_TRUE(s.lab);
  EXPECT_EQ(s.lab->hole_side, 1.2);
  ASSERT_TRUE(s.article.base.gimbal);
  EXPECT_NEAR(s.article.base.gimbal->pitch.angle, 10 * M_PI / 180, 1e-15);
  EXPECT_EQ(s.overrides.size(), 8u);
  EXPECT_EQ(s.source.rfind("s.yaml --set links.l1.length=2.5 --set materials.steel.youngs_modulus=7e10", 0), 0u) << s.source;
  // The last of two overrides of one key wins; the file is not changed otherwise.
  const ArticleScene t = withSets({"links.l1.length=2", "links.l1.length=3"});
  EXPECT_EQ(t.article.links[0].length, 3.0);
  EXPECT_EQ(t.article.links[1].length, 0.5);
  EXPECT_EQ(withSets({}).source, "s.yaml");
}

TEST(SceneOverrides, ErrorsAreTheFilesWithTheOverrideForThePosition) {
  // The same bad value in the file and from --set: the same message after the position.
  std::string in_file;
  try {
    withSets({}, std::string(kTwoLinks).replace(std::string(kTwoLinks).find("length: 1.0"), 11, "length: -2"));
  } catch (const SceneError& e) {
    in_file = e.what();
  }
  EXPECT_EQ(afterPosition(in_file, "s.yaml:19:13: "), "links[0].length must be > 0 m (got -2)");
  EXPECT_EQ(afterPosition(overrideErrorOf({"links.l1.length=-2"}), "--set links.l1.length=-2: "), "links[0].length must be > 0 m (got -2)");
  EXPECT_EQ(overrideErrorOf({"links.l1.lenght=2"}),
            "--set links.l1.lenght=2: unknown key 'links[0].lenght' (did you mean 'length'?) (allowed: name, joint, material, section, length, "
            "segments, mount_angle_deg, tip_mass, branches, model, modes)");
  EXPECT_EQ(overrideErrorOf({"links.l1.length=abc"}), "--set links.l1.length=abc: links[0].length must be a number (got abc)");
  EXPECT_EQ(overrideErrorOf({"lab.hole_side_m=9"}),
            "--set lab.hole_side_m=9: lab.hole_side_m: the hole (9 m) must be smaller than the platform (6.096 m x 8.8392 m)");
  EXPECT_EQ(overrideErrorOf({"links.l9.length=2"}), "--set links.l9.length=2: no item 'l9' (known: l1, l2)");
  EXPECT_EQ(overrideErrorOf({"links.l1.length=[1"}).rfind("--set links.l1.length=[1: malformed YAML value", 0), 0u);
  EXPECT_EQ(overrideErrorOf({"name.first=x"}), "--set name.first=x: 'name.first' does not name a key of a mapping");
  // The kind of scene is the file's to say (the set fuzzer: the reader then blamed the file's own keys).
  EXPECT_EQ(overrideErrorOf({"hamsas="}), "--set hamsas=: 'adding hamsas' would change the scene's kind; an override changes values within the article scene");
  EXPECT_EQ(overrideErrorOf({"l\"=1"}).rfind("--set l\"=1: ", 0), 0u);  // a quote in a key part stays in it
  // A malformed override is the command line's mistake.
  EXPECT_THROW(withSets({"links.l1.length"}), UsageError);
  EXPECT_THROW(withSets({"links..length=2"}), UsageError);
  EXPECT_THROW(withSets({"=2"}), UsageError);
  // A later error in the file itself still points at the file's line.
  EXPECT_EQ(overrideErrorOf({"links.l1.length=2"}, std::string(kTwoLinks).replace(std::string(kTwoLinks).find("b: 0.02"), 7, "b: -1"))
                .rfind("s.yaml:6:", 0),
            0u);
}

}  // namespace
}  // namespace mmv
