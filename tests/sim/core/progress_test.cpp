// A counting stage's time left (sim/core/progress.hpp): at its pace so far, none before a
// second of it or its first count, none when done.
#include <gtest/gtest.h>

#include "sim/core/progress.hpp"

namespace mmv {
namespace {

TEST(ProgressTimeLeft, IsThePaceSoFarTimesWhatRemains) {
  const auto t0 = std::chrono::steady_clock::now();
  ProgressLevel l{"drawing the run's frames", 10, 181, "frame", t0};
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::seconds(2)), "about 34 s left");  // 2 s / 10 x 171
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::seconds(20)), "about 6 min left");
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::milliseconds(900)), "");  // under a second: no pace yet
  l.done = 0;
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::seconds(5)), "");
  l.done = 181;
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::seconds(5)), "");
  l.done = 180;
  EXPECT_EQ(progressTimeLeft(l, t0 + std::chrono::seconds(5)), "about 1 s left");  // 0.03 s shown as a second
}

}  // namespace
}  // namespace mmv
