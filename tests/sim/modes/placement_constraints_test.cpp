// Placement constraints (place-sensors --min-separation, --keep-out, --channels): over a
// seeded set of random requests, no chosen pair of stations is closer than the
// separation (one station's directions excepted) and no chosen station lies in a
// keep-out stretch, for every method; a request that cannot be met is an OptionError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <random>
#include <set>

#include "sim/core/text.hpp"

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

// The scene's own accelerometers (--keep-scene-sensors) over seeded random requests:
// every one kept by every method, in its own direction (uniaxial) or as its station's
// block (triaxial, every other request), counted in the count; the
// separation and the keep-outs hold for every other chosen station (two of the user's
// may be closer, and one may sit in a keep-out: they are on the article already).
TEST(PlacementConstraints, TheScenesSensorsAreAlwaysKept) {
  ArticleScene base = loadDefaultScene();
  overrideSegments(base, 4);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* const axes[] = {"axial", "transverse"};
  int runs = 0;
  for (int trial = 0; trial < 30; ++trial) {
    ArticleScene scene = base;
    const int own = 1 + trial % 3;
    for (int k = 0; k < own; ++k) {
      const auto& l = scene.article.links[static_cast<std::size_t>(unit(rng) * scene.article.links.size())];
      // On the 0.1 m grid, off it, or at the tip.
      const double x = k == 0 ? l.length : k == 1 ? std::min(std::round(10 * unit(rng) * l.length) / 10, l.length) : unit(rng) * l.length;
      char target[64];
      std::snprintf(target, sizeof target, "%s@%.6fm", l.name.c_str(), std::max(x, 1e-3));
      scene.sensors.push_back({"own" + std::to_string(k), "accelerometer", target, static_cast<int>(unit(rng) * 2), 0, 1, "test"});
    }
    PlacementOptions o;
    o.method = static_cast<PlacementMethod>(trial % 3);
    o.count = own + 4 + static_cast<int>(unit(rng) * 8);
    o.modes = modeNumbers({1, 2, 3, 4});
    o.min_separation_m = unit(rng) < 0.3 ? 0.0 : 0.05 + 0.2 * unit(rng);
    o.keep_scene_sensors = true;
    o.triaxial = trial % 2 == 1;  // a triaxial block at each of the scene's stations
    PlacementStudy s;
    try {
      s = runPlacement(scene, o);
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "--min-separation") << e.what();
      continue;
    }
    ++runs;
    std::vector<char> kept(s.candidates.size(), 0);
    for (int b : s.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
    int fixed = 0;
    for (std::size_t b = 0; b < s.candidates.size(); ++b) {
      const auto& c = s.candidates[b];
      if (!c.fixed) continue;
      ++fixed;
      EXPECT_TRUE(kept[b]) << "trial " << trial << ": the scene's " << c.station << " " << c.axis << " dropped";
    }
    // Each of the scene's sensors is one fixed direction, at its place along its axis
    // (two at one station and axis are one).
    std::set<std::string> distinct;
    for (const auto& sensor : scene.sensors) {
      const double x = std::strtod(sensor.target.c_str() + sensor.target.find('@') + 1, nullptr);
      const std::string link = sensor.target.substr(0, sensor.target.find('@'));
      distinct.insert(link + strf("%.6f", x) + (o.triaxial ? "triaxial" : axes[sensor.axis]));
      EXPECT_TRUE(std::any_of(s.candidates.begin(), s.candidates.end(), [&](const PlacementCandidate& c) {
        return c.fixed && c.link == link && std::abs(c.x_m - x) < 1e-9 && c.axis == (o.triaxial ? "triaxial" : axes[sensor.axis]);
      })) << "trial " << trial << ": " << sensor.target;
    }
    EXPECT_EQ(fixed, static_cast<int>(distinct.size())) << "trial " << trial;
    EXPECT_LE(static_cast<int>(s.result.kept_blocks.size()), o.count);
    if (o.min_separation_m == 0) EXPECT_EQ(static_cast<int>(s.result.kept_blocks.size()), o.count);
    for (int a : s.result.kept_blocks)
      for (int b : s.result.kept_blocks) {
        const auto &p = s.candidates[static_cast<std::size_t>(a)], &q = s.candidates[static_cast<std::size_t>(b)];
        if (p.fixed && q.fixed) continue;
        const double d = std::hypot(p.world_x - q.world_x, p.world_y - q.world_y, p.world_z - q.world_z);
        if (d > 1e-9) EXPECT_GE(d, o.min_separation_m) << "trial " << trial << ": " << p.station << " and " << q.station;
      }
  }
  EXPECT_GE(runs, 20);
  std::printf("[constraints] %d of 30 requests with the scene's sensors placed\n", runs);
}

}  // namespace
}  // namespace mmv
