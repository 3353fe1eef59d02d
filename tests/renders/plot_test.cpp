// What writeLinePlotPng draws of a dense series (renders/plot.hpp, columnEnvelope):
// each pixel column keeps its first, lowest, highest and last point, in order, so a
// 10^5-sample run's curve has the same envelope as every sample drawn.
#include "renders/plot.hpp"
#include "renders/layout.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <thread>

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

/// The layout writeLinePlotPng (or writeBodePng) logs for one figure (renders/layout.hpp).
nlohmann::json layoutOf(const std::function<void(const std::string&)>& draw) {
  const std::string base = (std::filesystem::temp_directory_path() / ("mmvlab_layout_" + std::to_string(getpid()))).string();
  std::filesystem::remove(base + ".jsonl");
  setLayoutLog(base + ".jsonl");
  draw(base + ".png");
  setLayoutLog("");
  std::ifstream in(base + ".jsonl");
  std::string line;
  std::getline(in, line);
  std::filesystem::remove(base + ".jsonl");
  std::filesystem::remove(base + ".png");
  return nlohmann::json::parse(line);
}

// The figure harness's defects, one each (tests/figures/figure_layout.sh runs them on
// every shipped scene): before, torques.png drew gimbal.yaw's capacity over
// gimbal.pitch's (0 pixels of it showed), tips.png hid link3a under link3b, and a
// near-zero trace's ticks ("7.5e-11") ran into the axis title.
TEST(Plot, CoincidentSeriesShareAnEntryAndNearOnesBothShow) {
  const std::vector<double> t{0, 1, 2, 3, 4};
  Series a{"pitch capacity", t, {2, 2, 2, 2, 2}}, b{"yaw capacity", t, {2, 2, 2, 2, 2}};
  a.dashed = b.dashed = true;
  Series c{"link3b", t, {0, 1, 0.5, 1.5, 1}}, d{"link3a", t, {0, 1, 0.5, 1.5, 1.000001}};
  const auto fig = layoutOf([&](const std::string& p) { writeLinePlotPng(p, {a, b, c, d}, "t", "x", "y"); });
  ASSERT_EQ(fig["legend"].size(), 3u);
  EXPECT_EQ(fig["legend"][0][0], "pitch capacity = yaw capacity");
  for (const auto& e : fig["legend"]) EXPECT_GE(e[5].get<long>(), 30) << e;  // every named series shows
  for (const auto& t1 : fig["texts"])
    EXPECT_LE(t1[1].get<int>() + t1[3].get<int>(), fig["width"].get<int>()) << t1;
}

// CI's layout check found trade.png's "arkode_dirk" (two runs) showing 25 pixels: its
// markers lay under other integrators' runs and the Pareto front's rings, and the redraw
// on top (two dots of radius 2) was smaller than what the check asks. Three runs of
// different series on one pixel, under a ring, all show.
TEST(Plot, MarkersUnderOthersMarkersAllShow) {
  Series wide{"wide", {1e-3, 1e-1}, {1e-6, 1e-3}}, a{"a", {1e-2}, {1e-5}}, b{"b", {1.0001e-2}, {1.0001e-5}},
      c{"c", {1.0002e-2}, {0.9999e-5}}, ring{"front", {1e-2}, {1e-5}};
  for (Series* s : {&wide, &a, &b, &c, &ring}) s->markers_only = true;
  ring.hollow = true;
  ring.colour_index = 0;
  c.point_labels = {"1e-05"};
  const auto fig =
      layoutOf([&](const std::string& p) { writeLinePlotPng(p, {wide, a, b, c, ring}, "t", "x", "y", true, true); });
  ASSERT_EQ(fig["legend"].size(), 5u);
  for (const auto& e : fig["legend"]) EXPECT_GE(e[5].get<long>(), 30) << e;
}

// CI's layout check found trade.png's "Pareto front" (a dashed line) drawn with 0 pixels
// when one run dominated all others: a line of one point. Such a series is a marker.
TEST(Plot, ADashedSeriesOfOnePointIsDrawn) {
  Series runs{"runs", {1, 2, 3}, {3, 1, 2}}, front{"front", {2}, {1}};
  runs.markers_only = true;
  front.dashed = true;
  front.colour_index = 0;
  const auto fig = layoutOf([&](const std::string& p) { writeLinePlotPng(p, {runs, front}, "t", "x", "y"); });
  ASSERT_EQ(fig["legend"].size(), 2u);
  for (const auto& e : fig["legend"]) EXPECT_GE(e[5].get<long>(), 10) << e;
}

// Point labels (trade's tolerances) never overprint: CI's slower machine put two trade
// runs a pixel apart and "1e-03" was drawn over "1e-04".
TEST(Plot, PointLabelsOfNearbyPointsDoNotOverlap) {
  Series s{"runs", {1.0, 1.001, 1.002, 2.0}, {1.0, 1.001, 0.999, 2.0}};
  s.markers_only = true;
  s.point_labels = {"1e-03", "1e-04", "1e-05", "1e-06"};
  const auto fig = layoutOf([&](const std::string& p) { writeLinePlotPng(p, {s}, "t", "x", "y"); });
  std::vector<std::array<int, 4>> labels;
  for (const auto& t : fig["texts"])
    if (t[0].get<std::string>().rfind("1e-0", 0) == 0) labels.push_back({t[1], t[2], t[3], t[4]});
  EXPECT_GE(labels.size(), 3u);  // three of the four fit around the cluster, the far one beside itself
  for (std::size_t i = 0; i < labels.size(); ++i)
    for (std::size_t j = i + 1; j < labels.size(); ++j) {
      const auto& a = labels[i];
      const auto& b = labels[j];
      const bool apart = a[0] + a[2] <= b[0] || b[0] + b[2] <= a[0] || a[1] + a[3] <= b[1] || b[1] + b[3] <= a[1];
      EXPECT_TRUE(apart) << i << " " << j;
    }
}

TEST(Plot, TinyTicksAreMultiplesOfAPowerOfTenTheAxisStates) {
  const auto fig = layoutOf(
      [&](const std::string& p) { writeLinePlotPng(p, {Series{"z", {0, 1, 2}, {0, 7.5e-11, 2.5e-10}}}, "t", "time (s)", "d (mm)"); });
  bool titled = false;
  for (const auto& t : fig["texts"]) {
    const std::string text = t[0];
    if (text.rfind("d (mm)", 0) == 0) titled = text == "d (mm) x 1e-10";
    else EXPECT_EQ(text.find("e-"), std::string::npos) << text;  // the ticks: 0, 0.5, ... 2.5
  }
  EXPECT_TRUE(titled);
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

/// Runs `draw` in a child process: true when it exits 0 within `seconds` (a hang is
/// killed and reported false, so the suite does not wait for ctest's timeout).
bool finishesWithin(const std::function<void()>& draw, int seconds) {
  const pid_t pid = fork();
  if (pid == 0) {
    try {
      draw();
    } catch (...) {
      _exit(2);
    }
    _exit(0);
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) && WEXITSTATUS(status) == 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return false;
}

// An axis spanning about one ulp (a sweep over [0.001, 0.0010000000000000002]) looped
// forever adding a tick step smaller than the ulp; a flat series drew the same way.
TEST(Plot, AnAxisOfAFewUlpsIsDrawnAndEnds) {
  const std::string path = (std::filesystem::temp_directory_path() / ("mmvlab_ulp_axis_" + std::to_string(getpid()) + ".png")).string();
  Series s{"one ulp", {0.001, 0.0010000000000000002}, {30.0, 30.000000000000004}};
  s.markers_only = true;
  EXPECT_TRUE(finishesWithin([&] { writeLinePlotPng(path, {s}, "ulp", "x", "y"); }, 20));
  Series big{"huge", {1e300, 1e300}, {-1e-300, -1e-300}};
  EXPECT_TRUE(finishesWithin([&] { writeLinePlotPng(path, {big}, "huge", "x", "y"); }, 20));
  EXPECT_GT(std::filesystem::file_size(path), 1000u);
  std::filesystem::remove(path);
}

// A heat map whose colour range is NaN (every cell missing, or a NaN that reached the
// range) indexed its colour table out of range; every cell is now drawn, NaN as "n/a".
TEST(Plot, AHeatMapWithANaNRangeIsDrawn) {
  const std::string path = (std::filesystem::temp_directory_path() / ("mmvlab_nan_map_" + std::to_string(getpid()) + ".png")).string();
  Eigen::MatrixXd m(2, 2);
  m << 1.0, NAN, 3.0, 4.0;
  EXPECT_TRUE(finishesWithin([&] { writeHeatmapPng(path, m, {"a", "b"}, {"c", "d"}, "nan", "r", "c", NAN, NAN); }, 20));
  EXPECT_GT(std::filesystem::file_size(path), 1000u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mmv::render
