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

}  // namespace
}  // namespace mmv
