// sweep-config's tracking over a configuration range (sim/modes/config_sweep.hpp): on the
// closed MMV tree over joint 2, where the old greedy, fixed-step tracking let "track 3"
// jump from 2.38 Hz to 27.1 Hz at MAC 0.15, every track that is followed from one
// reported point to the next keeps its shape (MAC >= 0.5) and its frequency (within 25
// %); the rest are marked lost or restarted, with the reason.
#include "sim/modes/config_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv {
namespace {

TEST(SweepConfig, ClosedTreeTracksNeverJumpTheyRefineOrAreMarkedLost) {
  const ArticleScene scene = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  ConfigSweepOptions o;
  o.axes.push_back({"joint2", -45, 45, 15});
  o.modes = 6;
  const ConfigSweepResult r = runConfigSweep(scene, o);
  EXPECT_GT(r.refined_points, 0);  // the 15 deg step alone cannot follow these shapes
  int followed = 0;
  for (std::size_t i = 1; i < r.points.size(); ++i) {
    const ConfigSweepPoint &a = r.points[i - 1], &b = r.points[i];
    if (!a.solved || !b.solved) continue;
    for (std::size_t k = 0; k < std::min(a.tracks.size(), b.tracks.size()); ++k) {
      const TrackPoint &ta = a.tracks[k], &tb = b.tracks[k];
      if (!tb.state.empty()) {
        EXPECT_TRUE(tb.state.rfind("lost: MAC", 0) == 0 || tb.state.rfind("restarted: no equilibrium", 0) == 0) << tb.state;
        continue;
      }
      EXPECT_GE(tb.mac_to_previous, kLostMac) << "track " << k + 1 << " at " << b.angles_deg[0];
      if (ta.stable && tb.stable) {
        ++followed;
        EXPECT_LT(std::abs(tb.frequency_hz / ta.frequency_hz - 1), 0.25)
            << "track " << k + 1 << " jumps from " << ta.frequency_hz << " to " << tb.frequency_hz << " Hz at " << b.angles_deg[0];
      }
    }
  }
  EXPECT_GT(followed, 50);
  // Each grid point is reported once, refined points lie strictly between grid points.
  int grid = 0;
  for (const auto& p : r.points) grid += !p.refined;
  EXPECT_EQ(grid, 7);
}

}  // namespace
}  // namespace mmv
