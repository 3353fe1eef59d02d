#include "facility/slews.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv::facility {
namespace {

constexpr double kDeg = M_PI / 180;

// Both shapes: exact ends at rest, limits respected, and rate and acceleration the
// derivatives of the angle (central differences, h = 1e-6 s: agreement to 1e-6 of
// the peak is the differences' accuracy away from the trapezoid's corners).
TEST(Slews, EndsLimitsAndDerivatives) {
  const SlewLimits lim;
  for (SlewShape shape : {SlewShape::Cycloidal, SlewShape::Trapezoidal})
    for (double to : {45 * kDeg, -30 * kDeg, 2 * kDeg}) {
      const Slew s = makeSlew(shape, -45 * kDeg, to, 0.0, lim);
      EXPECT_NEAR(s.at(0).angle, -45 * kDeg, 1e-15);
      EXPECT_NEAR(s.at(s.duration()).angle, to, 1e-12);
      EXPECT_EQ(s.at(s.duration()).rate, 0.0);
      EXPECT_LE(s.peakRate(), lim.max_rate * (1 + 1e-12));
      EXPECT_LE(s.peakAcceleration(), lim.max_acceleration * (1 + 1e-12));
      // One of the limits is reached: the slew is as short as the limits allow.
      EXPECT_TRUE(std::abs(s.peakRate() / lim.max_rate - 1) < 1e-9 ||
                  std::abs(s.peakAcceleration() / lim.max_acceleration - 1) < 1e-9);
      const double h = 1e-6;
      for (int k = 1; k < 50; ++k) {
        const double t = s.duration() * (k + 0.37) / 51.0;  // off the corners (midpoint, quarter points)
        const double rate = (s.at(t + h).angle - s.at(t - h).angle) / (2 * h);
        EXPECT_NEAR(rate, s.at(t).rate, 1e-6 * s.peakRate() + 1e-9) << "t " << t;
        if (shape == SlewShape::Cycloidal) {
          const double acc = (s.at(t + h).rate - s.at(t - h).rate) / (2 * h);
          EXPECT_NEAR(acc, s.at(t).acceleration, 1e-5 * s.peakAcceleration()) << "t " << t;
        }
      }
    }
}

// The full +-45 deg swing at the 70 deg/s limit (the report's numbers): the cycloidal
// slew takes 2 x 90 / 70 = 2.571 s unless the acceleration limit is the tighter one.
TEST(Slews, ReportSwingAtTheRateLimit) {
  SlewLimits lim;
  lim.max_acceleration = 1e6;  // rate-limited
  const Slew s = makeSlew(SlewShape::Cycloidal, -45 * kDeg, 45 * kDeg, 0.0, lim);
  EXPECT_NEAR(s.duration(), 2 * 90.0 / 70.0, 1e-12);
  EXPECT_NEAR(s.at(s.duration() / 2).rate, 70 * kDeg, 1e-12);
}

TEST(Slews, OutOfRangeIsRefused) {
  EXPECT_THROW(makeSlew(SlewShape::Cycloidal, 0, 50 * kDeg, 0, {}), std::invalid_argument);
  SlewLimits bad;
  bad.max_rate = 0;
  EXPECT_THROW(makeSlew(SlewShape::Trapezoidal, 0, 10 * kDeg, 0, bad), std::invalid_argument);
}

}  // namespace
}  // namespace mmv::facility
