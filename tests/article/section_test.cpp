#include "article/section.hpp"

#include <gtest/gtest.h>

namespace mmv {
namespace {

// The MMV report's Table 1 prints A and I to three digits; our formulas must give the
// same numbers from its dimensions (within the printed rounding, 0.5 % of the value).
TEST(Section, ReportTable1Values) {
  Section tube{"t", SectionShape::RectangularTube, 0.0762, 0.0254, 0.0034};
  EXPECT_NEAR(sectionArea(tube), 6.45e-4, 0.005 * 6.45e-4);
  EXPECT_NEAR(sectionSecondMoment(tube), 6.69e-8, 0.005 * 6.69e-8);
  Section bar{"b", SectionShape::Rectangle, 0.0381, 0.0127};
  EXPECT_NEAR(sectionArea(bar), 4.84e-4, 0.005 * 4.84e-4);
  EXPECT_NEAR(sectionSecondMoment(bar), 6.50e-9, 0.005 * 6.50e-9);
  Section rod{"r", SectionShape::RoundRod};
  rod.radius = 0.00127;
  EXPECT_NEAR(sectionArea(rod), 5.07e-6, 0.005 * 5.07e-6);
  EXPECT_NEAR(sectionSecondMoment(rod), 2.04e-12, 0.005 * 2.04e-12);
}

TEST(Section, TubeTendsToSolidWhenWallFillsIt) {
  // A tube whose wall reaches the middle is the solid rectangle: (b-2t)(h-2t) -> 0.
  Section tube{"t", SectionShape::RectangularTube, 0.04, 0.02, 0.01 * (1 - 1e-12)};
  Section bar{"b", SectionShape::Rectangle, 0.04, 0.02};
  EXPECT_NEAR(sectionArea(tube), sectionArea(bar), 1e-12);
  EXPECT_NEAR(sectionSecondMoment(tube), sectionSecondMoment(bar), 1e-18);
}

TEST(Section, ExplicitPassesThrough) {
  Section s;
  s.shape = SectionShape::Explicit;
  s.explicit_area = 2e-4;
  s.explicit_second_moment = 3e-9;
  EXPECT_DOUBLE_EQ(sectionArea(s), 2e-4);
  EXPECT_DOUBLE_EQ(sectionSecondMoment(s), 3e-9);
  EXPECT_DOUBLE_EQ(sectionGyrationSquared(s), 1.5e-5);
}

}  // namespace
}  // namespace mmv
