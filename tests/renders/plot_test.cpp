// What writeLinePlotPng draws of a dense series (renders/plot.hpp, columnEnvelope):
// each pixel column keeps its first, lowest, highest and last point, in order, so a
// 10^5-sample run's curve has the same envelope as every sample drawn.
#include "renders/plot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace mmv::render {
namespace {

struct Extent {
  int lo = 1 << 30, hi = -(1 << 30);
};

std::map<int, Extent> extents(const std::vector<std::optional<Pixel>>& pts) {
  std::map<int, Extent> out;
  for (const auto& p : pts)
    if (p) out[p->x].lo = std::min(out[p->x].lo, p->y), out[p->x].hi = std::max(out[p->x].hi, p->y);
  return out;
}

TEST(Plot, ADenseCurveKeepsEachColumnsExtentInFewPoints) {
  std::vector<std::optional<Pixel>> pts;
  for (int i = 0; i < 100000; ++i) {  // 10^5 samples over 800 columns: a chirp with noise, and a gap
    const double t = i / 1e5;
    if (i > 40000 && i < 40100) {
      pts.push_back(std::nullopt);
      continue;
    }
    pts.push_back(Pixel{static_cast<int>(800 * t), static_cast<int>(300 + 200 * std::sin(300 * t * t) + (i * 7919 % 13))});
  }
  const auto line = columnEnvelope(pts);
  EXPECT_LE(line.size(), 4u * 800u + 2u);
  const auto full = extents(pts), kept = extents(line);
  ASSERT_EQ(full.size(), kept.size());
  for (const auto& [x, e] : full) {
    EXPECT_EQ(kept.at(x).lo, e.lo) << x;
    EXPECT_EQ(kept.at(x).hi, e.hi) << x;
  }
  EXPECT_TRUE(*line.front() == *pts.front());
  EXPECT_TRUE(*line.back() == *pts.back());
  EXPECT_EQ(std::count(line.begin(), line.end(), std::nullopt), 1);  // the gap, once
  for (std::size_t i = 1; i < line.size(); ++i)  // left to right
    if (line[i - 1] && line[i]) EXPECT_LE(line[i - 1]->x, line[i]->x);
}

TEST(Plot, ASparseCurveIsDrawnPointForPoint) {
  const std::vector<std::optional<Pixel>> pts{Pixel{0, 5}, Pixel{3, 9}, std::nullopt, Pixel{7, 1}, Pixel{9, 4}};
  const auto line = columnEnvelope(pts);
  ASSERT_EQ(line.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_TRUE(line[i] == pts[i]) << i;
}

}  // namespace
}  // namespace mmv::render
