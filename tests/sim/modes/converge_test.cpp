#include "sim/modes/converge.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "article/beam_theory.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

// The study on a cantilever: the observed order is 2 and the Richardson value is
// closer to the exact frequency than the finest run (it removes the 1/N^2 term).
TEST(Converge, CantileverOrderAndRichardson) {
  const testing::Beam b;
  const ArticleScene s = testing::cantileverScene(b, 1, 0.0);
  const ConvergenceStudy c = runConvergence(s, 32, 3);
  ASSERT_EQ(c.runs.size(), 6u);  // 1, 2, 4, 8, 16, 32
  EXPECT_EQ(c.runs.back().segments, 32);
  EXPECT_EQ(c.runs.back().num_dofs, 32);
  const auto roots = cantileverTipMassRoots(0.0, 3);
  for (int i = 0; i < 3; ++i) {
    const ConvergenceMode& m = c.modes[i];
    ASSERT_TRUE(m.has_estimate && m.has_observed_order);
    EXPECT_NEAR(m.observed_order, 2.0, 0.1) << "mode " << i + 1;
    const double exact = beamFrequencyHz(roots[i], b.length, b.bendingStiffness(), b.massPerLength());
    EXPECT_LT(std::abs(m.extrapolated_hz - exact), std::abs(m.frequency_hz.back() - exact)) << "mode " << i + 1;
    EXPECT_GT(m.estimated_relative_error, 0.0);
  }
  // N = 1 has one DOF: its column holds mode 1 only.
  EXPECT_TRUE(std::isfinite(c.modes[0].frequency_hz[0]));
  EXPECT_TRUE(std::isnan(c.modes[1].frequency_hz[0]));
}

}  // namespace
}  // namespace mmv
