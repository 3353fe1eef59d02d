#include "sim/modes/tracking.hpp"

#include <gtest/gtest.h>

#include "sim/modes/modal.hpp"

namespace mmv {
namespace {

// Two weakly coupled oscillators whose frequencies cross as t goes from 0 to 1:
// K = diag(1 + 2t, 2 - t) (+ a tiny coupling). Sorted by frequency the modes swap
// at t = 1/3; tracked by shape, mode "A" (mostly DOF 0) must stay mode A throughout.
TEST(Tracking, ModesKeepTheirIdentityThroughACrossing) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd prev;
  std::vector<int> track{0, 1};  // track k -> sorted index at the current step
  bool swapped = false;
  for (int step = 0; step <= 20; ++step) {
    const double t = step / 20.0;
    Eigen::MatrixXd K(2, 2);
    K << 1 + 2 * t, 1e-4, 1e-4, 2 - t;
    const ModalSolution s = solveModes(M, K);
    if (step > 0) {
      const ModeMatch m = matchModes(prev, s.shapes);
      for (int k = 0; k < 2; ++k) EXPECT_GT(m.mac[k], 0.99) << "t " << t;
      track = m.index;
      swapped = swapped || track[0] == 1;
    }
    // Track 0 is the shape that is mostly DOF 0, whatever its rank.
    EXPECT_GT(std::abs(s.shapes(0, track[0])), std::abs(s.shapes(1, track[0]))) << "t " << t;
    Eigen::MatrixXd ordered(2, 2);
    ordered << s.shapes.col(track[0]), s.shapes.col(track[1]);
    prev = ordered;
  }
  EXPECT_TRUE(swapped);  // the ranks did swap: the test went through a real crossing
}

TEST(Tracking, IdenticalSetsMatchThemselves) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  A(1, 0) = 0.2;
  const ModeMatch m = matchModes(A, A);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(m.index[i], i);
    EXPECT_NEAR(m.mac[i], 1.0, 1e-15);
  }
}

// Greedy "most alike pair first" takes a->x (0.9) and leaves b with y (0.1); the best
// assignment is a->y, b->x (0.8 + 0.85).
TEST(Tracking, AssignmentMaximisesTheTotalMacNotTheFirstPair) {
  Eigen::MatrixXd mac(2, 2);
  mac << 0.9, 0.8, 0.85, 0.1;
  const std::vector<int> a = optimalAssignment(Eigen::MatrixXd::Ones(2, 2) - mac);
  EXPECT_EQ(a, (std::vector<int>{1, 0}));
}

TEST(Tracking, AssignmentOfRectangularCostsAgainstBruteForce) {
  // 4 rows into 6 columns: every injective map checked.
  Eigen::MatrixXd c(4, 6);
  unsigned seed = 7;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 6; ++j) c(i, j) = ((seed = seed * 1103515245u + 12345u) >> 8) % 1000 / 1000.0;
  double best = 1e9;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b)
      for (int d = 0; d < 6; ++d)
        for (int e = 0; e < 6; ++e)
          if (a != b && a != d && a != e && b != d && b != e && d != e) best = std::min(best, c(0, a) + c(1, b) + c(2, d) + c(3, e));
  const std::vector<int> x = optimalAssignment(c);
  double total = 0;
  for (int i = 0; i < 4; ++i) total += c(i, x[i]);
  EXPECT_NEAR(total, best, 1e-12);
}

// Strongly coupled oscillators veer instead of crossing: K = [1 + 2t, c; c, 2 - t] with
// c = 0.1. The branches never touch (gap 2c at t = 1/3) and the shapes rotate through
// 90 deg across the veering: tracked in small steps, each track stays on its
// frequency branch (the lower stays lower) while its shape turns from one DOF to the other.
TEST(Tracking, ModesFollowTheirBranchThroughAVeering) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd prev;
  std::vector<int> track{0, 1};
  for (int step = 0; step <= 60; ++step) {
    const double t = step / 60.0;
    Eigen::MatrixXd K(2, 2);
    K << 1 + 2 * t, 0.1, 0.1, 2 - t;
    const ModalSolution s = solveModes(M, K);
    if (step > 0) {
      const ModeMatch m = matchModes(prev, s.shapes);
      track = m.index;
      for (int k = 0; k < 2; ++k) EXPECT_GT(m.mac[k], 0.9) << "t " << t;
    }
    EXPECT_EQ(track, (std::vector<int>{0, 1})) << "t " << t;  // no jump between branches
    Eigen::MatrixXd ordered(2, 2);
    ordered << s.shapes.col(track[0]), s.shapes.col(track[1]);
    prev = ordered;
    if (step == 60) EXPECT_GT(std::abs(s.shapes(1, track[0])), std::abs(s.shapes(0, track[0])));  // the lower branch is now DOF 1
  }
}

}  // namespace
}  // namespace mmv
