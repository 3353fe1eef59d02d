// Every shipped scene and the embedded default load, and load to the same content
// twice (the reader keeps no state between files).

#include <gtest/gtest.h>

#include <filesystem>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

TEST(ShippedScenes, EveryOneLoads) {
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(MMVLAB_SOURCE_DIR) + "/scenes")) {
    if (e.path().extension() != ".yaml") continue;
    const Scene a = loadSceneFile(e.path().string());
    const Scene b = loadSceneFile(e.path().string());
    EXPECT_EQ(a.index(), b.index()) << e.path();
    EXPECT_FALSE(sceneName(a).empty()) << e.path();
    EXPECT_EQ(sceneName(a), sceneName(b)) << e.path();
    ++count;
  }
  EXPECT_GE(count, 6);
  const ArticleScene d = loadDefaultScene();
  EXPECT_EQ(d.article.links.size(), 4u);  // links 1, 2 and link 3's two branches
}

}  // namespace
}  // namespace mmv
