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

// The spin-up (Kane, Ryan and Banerjee 1987): its rate and acceleration are the
// derivatives of its angle (central differences, to 1e-6 of their scale), it starts and
// reaches its rate at rest in acceleration (smooth at both ends), and after the ramp
// turns at the rate past any angle: theta = W (t - T/2).
TEST(Slews, SpinUpProfileAndItsDerivatives) {
  const double W = 6.0, T = 15.0;  // the published beam: 6 rad/s over 15 s
  const Slew s = makeSpinUp(0.1, W, T);
  EXPECT_EQ(s.shape(), SlewShape::SpinUp);
  const double h = 1e-5;
  for (double t : {0.5, 3.0, 7.5, 11.0, 14.9, 20.0}) {
    const SlewState a = s.at(t), m = s.at(t - h), p = s.at(t + h);
    EXPECT_NEAR(a.rate, (p.angle - m.angle) / (2 * h), 1e-6 * W) << t;
    EXPECT_NEAR(a.acceleration, (p.rate - m.rate) / (2 * h), 1e-6 * W / T) << t;
  }
  EXPECT_EQ(s.at(0).rate, 0.0);
  EXPECT_EQ(s.at(0).acceleration, 0.0);
  EXPECT_NEAR(s.at(T).rate, W, 1e-12);
  EXPECT_NEAR(s.at(T - 1e-9).acceleration, 0.0, 1e-6);
  EXPECT_NEAR(s.at(T / 2).acceleration, 2 * W / T, 1e-12);  // the peak
  EXPECT_NEAR(s.peakAcceleration(), 2 * W / T, 1e-15);
  EXPECT_NEAR(s.at(T).angle, 0.1 + W * T / 2, 1e-12);
  EXPECT_NEAR(s.at(100).angle, 0.1 + W * (100 - T / 2), 1e-9);  // 90 turns on
  EXPECT_NEAR(makeSpinUp(0, -W, T).at(20).angle, -W * (20 - T / 2), 1e-12);  // the other way
  EXPECT_THROW(makeSpinUp(0, 0, T), std::invalid_argument);
  EXPECT_THROW(makeSpinUp(0, W, 0), std::invalid_argument);
  EXPECT_THROW(makeSpinUp(0, W, -1), std::invalid_argument);
}

// An angle program from a CSV in degrees: radians out, the samples hit, at rest after;
// started from another angle it moves with it (as a slew's start does), and it must stay
// within the range between the samples too (the cubic through 0, 40, 40 overshoots 40
// deg: refused at +-40, taken at +-45).
TEST(Slews, AngleProgramFromACsv) {
  const std::string csv = "time_s,angle_deg\n0,10\n1,30\n2,40\n3,40\n";
  const Slew s = makeAngleProgram(10 * kDeg, csvProfile(csv, "p.csv"), kDeg, 45 * kDeg);
  EXPECT_EQ(s.shape(), SlewShape::Program);
  EXPECT_NEAR(s.at(1).angle, 30 * kDeg, 1e-15);
  EXPECT_NEAR(s.at(5).angle, 40 * kDeg, 1e-15);
  EXPECT_EQ(s.at(5).rate, 0.0);
  EXPECT_GT(s.peakRate(), 0.0);
  const Slew moved = makeAngleProgram(-5 * kDeg, csvProfile(csv, "p.csv"), kDeg, 45 * kDeg);
  EXPECT_NEAR(moved.at(0).angle, -5 * kDeg, 1e-15);
  EXPECT_NEAR(moved.at(1).angle, 15 * kDeg, 1e-15);
  EXPECT_EQ(moved.at(0.5).rate, s.at(0.5).rate);
  EXPECT_THROW(makeAngleProgram(20 * kDeg, csvProfile(csv, "p.csv"), kDeg, 45 * kDeg), std::invalid_argument);  // 40 -> 50 deg
  const std::string over = "time_s,angle_deg\n0,0\n1,40\n2,40\n";
  EXPECT_GT(makeAngleProgram(0, csvProfile(over, "o.csv"), kDeg, INFINITY).peakRate(), 0.0);
  double top = 0;
  const Slew o = makeAngleProgram(0, csvProfile(over, "o.csv"), kDeg, 45 * kDeg);
  for (int k = 0; k <= 2000; ++k) top = std::max(top, o.at(2.0 * k / 2000).angle);
  EXPECT_GT(top, 40 * kDeg);  // the overshoot the range check must see
  EXPECT_NEAR(o.largestAngle(), top, 1e-6 * kDeg);
  EXPECT_EQ(o.writtenStart(), 0.0);
  EXPECT_NEAR(moved.writtenStart(), 10 * kDeg, 1e-15);  // as written, before the move to -5 deg
  EXPECT_EQ(makeSpinUp(0, 1, 1).largestAngle(), INFINITY);
  EXPECT_NEAR(makeSlew(SlewShape::Cycloidal, -30 * kDeg, 20 * kDeg, 0, {}).largestAngle(), 30 * kDeg, 1e-15);
  EXPECT_THROW(makeAngleProgram(0, csvProfile(over, "o.csv"), kDeg, 40 * kDeg), std::invalid_argument);
}

}  // namespace
}  // namespace mmv::facility
