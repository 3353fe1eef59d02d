// Placement constraints (place-sensors --min-separation, --keep-out, --channels): over a
// seeded set of random requests, no chosen pair of stations is closer than the
// separation (one station's directions excepted) and no chosen station lies in a
// keep-out stretch, for every method; a request that cannot be met is an OptionError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "sim/core/errors.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

TEST(PlacementConstraints, AreNeverViolatedOverRandomRequests) {
  ArticleScene scene = loadDefaultScene();
  overrideSegments(scene, 4);
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int placed = 0, refused = 0;
  for (int trial = 0; trial < 40; ++trial) {
    PlacementOptions o;
    o.method = static_cast<PlacementMethod>(trial % 3);
    o.triaxial = trial % 4 == 3;
    o.count = 4 + static_cast<int>(unit(rng) * 16);
    o.modes = modeNumbers({1, 2, 3, 4});
    o.min_separation_m = unit(rng) < 0.2 ? 0.0 : 0.05 + 0.35 * unit(rng);
    const auto& links = scene.article.links;
    for (int k = 0; k < 2; ++k) {
      const auto& l = links[static_cast<std::size_t>(unit(rng) * links.size())];
      const double a = unit(rng) * 0.8 * l.length;
      o.keep_out.push_back({l.name, a, a + 0.2 * l.length * unit(rng)});
    }
    PlacementStudy s;
    try {
      s = runPlacement(scene, o);
    } catch (const OptionError& e) {  // too few left for the modes: refused, named by the separation
      EXPECT_EQ(e.option(), "--min-separation") << "trial " << trial << ": " << e.what();
      ++refused;
      continue;
    }
    ++placed;
    const auto& kept = s.result.kept_blocks;
    EXPECT_LE(static_cast<int>(kept.size()), o.count);
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const PlacementCandidate& a = s.candidates[static_cast<std::size_t>(kept[i])];
      for (const auto& k : o.keep_out)
        EXPECT_FALSE(a.link == k.link && a.x_m >= k.from_m && a.x_m <= k.to_m) << "trial " << trial << ": " << a.station;
      for (std::size_t j = i + 1; j < kept.size(); ++j) {
        const PlacementCandidate& b = s.candidates[static_cast<std::size_t>(kept[j])];
        const double d = std::hypot(a.world_x - b.world_x, a.world_y - b.world_y, a.world_z - b.world_z);
        if (d > 1e-9) EXPECT_GE(d, o.min_separation_m) << "trial " << trial << ": " << a.station << " and " << b.station;
      }
    }
  }
  EXPECT_GT(placed, 25);
  std::printf("[constraints] %d requests placed, %d refused by --min-separation\n", placed, refused);
}

// The separation spreads the sensors: without it effective independence puts two of 24
// at neighbouring stations (link1 at 2.40 and 2.44 m); with 0.15 m it keeps all 24 apart.
TEST(PlacementConstraints, SeparationKeepsTheCountWhenTheGridAllows) {
  ArticleScene scene = loadDefaultScene();
  overrideSegments(scene, 16);
  PlacementOptions o;
  o.count = 24;
  const auto closest = [](const PlacementStudy& s) {
    double d = INFINITY;
    for (int a : s.result.kept_blocks)
      for (int b : s.result.kept_blocks) {
        const auto &p = s.candidates[static_cast<std::size_t>(a)], &q = s.candidates[static_cast<std::size_t>(b)];
        const double x = std::hypot(p.world_x - q.world_x, p.world_y - q.world_y, p.world_z - q.world_z);
        if (x > 1e-9) d = std::min(d, x);
      }
    return d;
  };
  EXPECT_LT(closest(runPlacement(scene, o)), 0.15);
  o.min_separation_m = 0.15;
  const PlacementStudy s = runPlacement(scene, o);
  EXPECT_EQ(s.result.kept_blocks.size(), 24u);
  EXPECT_GE(closest(s), 0.15);
}

}  // namespace
}  // namespace mmv
