// A front end's dedicated options (--segments, --no-gravity) are patches of the scene
// document that the reader checks as if they were in the file, named by the option.
#include <gtest/gtest.h>

#include <string>

#include "sim/core/errors.hpp"
#include "sim/core/integrators.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

SceneFlags segments(int n) {
  SceneFlags f;
  f.segments = n;
  f.segments_label = "--segments " + std::to_string(n);
  return f;
}

ArticleScene read(const std::vector<std::string>& sets, const SceneFlags& flags, std::vector<std::string>* notes = nullptr) {
  return std::get<ArticleScene>(parseScene(defaultSceneYaml(), "<default scene>", sets, flags, notes));
}

std::string usageMessage(const std::vector<std::string>& sets, const SceneFlags& flags) {
  try {
    read(sets, flags);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SceneFlags, SegmentsReachEveryFlexibleLinkAndTheBoundIsTheReaders) {
  const ArticleScene a = read({}, segments(limits::kMaxSegments));  // at the bound: accepted
  for (const auto& l : a.article.links)
    if (!l.rigid) EXPECT_EQ(l.segments, limits::kMaxSegments) << l.name;
  const std::string past = std::to_string(limits::kMaxSegments + 1);
  EXPECT_EQ(usageMessage({}, segments(limits::kMaxSegments + 1)),
            "--segments " + past + ": links[0].segments must be an integer from 1 to " +
                std::to_string(limits::kMaxSegments) + " or 'rigid' (got " + past + ")");
  EXPECT_EQ(read({}, segments(1)).article.links[0].segments, 1);  // the lower bound
  EXPECT_NE(usageMessage({}, segments(0)).find("--segments 0: links[0].segments must be"), std::string::npos);
  EXPECT_NE(usageMessage({}, segments(-2)).find("--segments -2: links[0].segments must be"), std::string::npos);
}

TEST(SceneFlags, ARigidLinkStaysRigidAndTheOptionComesAfterTheSets) {
  const ArticleScene a = read({"links.link1.segments=rigid", "links.link2.segments=8"}, segments(16));
  EXPECT_TRUE(a.article.links[0].rigid);
  EXPECT_EQ(a.article.links[1].segments, 16);  // --set's 8, then --segments' 16
  // The error names the first flexible link, not the rigid one.
  EXPECT_NE(usageMessage({"links.link1.segments=rigid"}, segments(0)).find("--segments 0: links[1].segments"),
            std::string::npos);
}

TEST(SceneFlags, FewerHingesThanModesLowerTheModesWithANote) {
  std::vector<std::string> notes;
  const ArticleScene a = read({"links.link1.modes=3"}, segments(2), &notes);
  EXPECT_EQ(a.article.links[0].segments, 2);
  EXPECT_EQ(a.article.links[0].modes, 2);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "link link1 in 2 segments keeps 2 of the 3 modes its `modes:` asks (a link has one hinge per segment)");
  notes.clear();
  EXPECT_EQ(read({"links.link1.modes=3"}, segments(3), &notes).article.links[0].modes, 3);  // enough hinges: kept
  EXPECT_TRUE(notes.empty());
  // Without the option the reader refuses the same modes with the patch's position.
  try {
    read({"links.link1.segments=2", "links.link1.modes=3"}, {});
    ADD_FAILURE() << "modes above the hinges accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("--set links.link1.modes=3: links[0].modes must be 1 to the link's 2 hinges"),
              std::string::npos)
        << e.what();
  }
}

TEST(SceneFlags, NoGravityIsTheZeroGravityPatch) {
  SceneFlags f;
  f.no_gravity = true;
  f.gravity_label = "--no-gravity";
  const ArticleScene a = read({}, f);
  EXPECT_EQ(a.gravity, (std::array<double, 3>{0, 0, 0}));
  EXPECT_NE(read({}, {}).gravity[1], 0.0);  // the default scene has gravity: the patch made the zero
}

TEST(SceneFlags, AnIsolatorRefusesThemByName) {
  const std::string hamsas = std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml";
  try {
    loadSceneFile(hamsas, {}, segments(4));
    ADD_FAILURE() << "--segments accepted on HAM-SAS";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--segments 4: does not apply to a HAM-SAS scene", 0), 0u) << e.what();
  }
  SceneFlags g;
  g.no_gravity = true;
  g.gravity_label = "no_gravity=True";
  EXPECT_THROW(loadSceneFile(hamsas, {}, g), UsageError);
  EXPECT_NO_THROW(loadSceneFile(hamsas, {}, {}));
  // simulation.fidelity (docs/scene-format.md: article scenes only) is an error at its key,
  // not a setting the isolator's run would ignore; the article takes it.
  try {
    loadSceneFile(hamsas, {"simulation.fidelity=segments"});
    ADD_FAILURE() << "simulation.fidelity accepted on HAM-SAS";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("simulation.fidelity chooses how an article's links are carried; the isolator has "
                                         "none"),
              std::string::npos)
        << e.what();
  }
  const Scene article = loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml", {"simulation.fidelity=segments"});
  EXPECT_EQ(std::get<ArticleScene>(article).simulation.fidelity, SimulationSpec::Fidelity::Segments);
}

}  // namespace
}  // namespace mmv
