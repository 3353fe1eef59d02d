#include "facility/table_programs.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv::facility {
namespace {

// Velocity and acceleration of every program are the derivatives of its position
// (central differences, h = 1e-5 s: agreement to 1e-5 of the peak), before, during
// and after its duration: a time run longer than its program goes on evaluating it (a
// sweep that held its position after T while its velocity went on made a 6.1 s run
// take 80 times a 6 s one).
void checkDerivatives(const TableProgram& p) {
  const double h = 1e-5;
  const ProgramCheck c = checkProgram(p);
  for (int k = 1; k < 200; ++k) {
    const double t = p.duration() * (-0.5 + 2 * (k + 0.31) / 201.0);
    EXPECT_NEAR((p.position(t + h) - p.position(t - h)) / (2 * h), p.velocity(t), 1e-5 * c.peak_acceleration + 1e-9)
        << p.describe() << " t " << t;
    EXPECT_NEAR((p.velocity(t + h) - p.velocity(t - h)) / (2 * h), p.acceleration(t), 1e-4 * c.peak_acceleration + 1e-9)
        << p.describe() << " t " << t;
  }
}

TEST(TablePrograms, DerivativesAreConsistent) {
  checkDerivatives(*sineDwell(0.01, 2.0, 3.0));
  checkDerivatives(*sineSweep(0.01, 0.5, 8.0, 10.0, false));
  checkDerivatives(*sineSweep(0.01, 0.5, 8.0, 10.0, true));
  checkDerivatives(*bandLimitedRandom(0.005, 0.5, 5.0, 4.0, 7, 50));
}

// Sweeps: the instantaneous frequency phi'/(2 pi) = velocity / (A cos phi) at the
// start and end is f0 and f1; for the log sweep it is f0 (f1/f0)^(t/T) in between.
TEST(TablePrograms, SweepFrequencies) {
  const auto lin = sineSweep(1.0, 1.0, 9.0, 8.0, false);
  const auto log = sineSweep(1.0, 1.0, 9.0, 8.0, true);
  EXPECT_NEAR(lin->velocity(0.0), 2 * M_PI * 1.0, 1e-12);  // cos(0) = 1
  EXPECT_NEAR(log->velocity(0.0), 2 * M_PI * 1.0, 1e-12);
  // Half way the linear sweep is at 5 Hz, the log sweep at 3 Hz (sqrt(1 * 9)).
  auto inst = [](const TableProgram& p, double t) {
    // x = sin(phi), x' = phi' cos(phi): phi' = |x'| / sqrt(1 - x^2) for unit amplitude.
    const double x = p.position(t), v = p.velocity(t);
    return std::abs(v) / std::sqrt(std::max(1e-30, 1.0 - x * x)) / (2 * M_PI);
  };
  EXPECT_NEAR(inst(*lin, 4.0), 5.0, 1e-9);
  EXPECT_NEAR(inst(*log, 4.0), 3.0, 1e-9);
}

// Random: RMS as asked over a long record (equal lines at random phases: the sample
// RMS converges as the record covers many beats), reproducible per seed.
TEST(TablePrograms, RandomRmsAndSeed) {
  const auto a = bandLimitedRandom(0.004, 0.5, 10.0, 200.0, 11);
  const auto b = bandLimitedRandom(0.004, 0.5, 10.0, 200.0, 11);
  const auto c = bandLimitedRandom(0.004, 0.5, 10.0, 200.0, 12);
  double ms = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) ms += std::pow(a->position(200.0 * k / n), 2) / n;
  EXPECT_NEAR(std::sqrt(ms), 0.004, 0.004 * 0.02);
  EXPECT_EQ(a->position(3.3), b->position(3.3));
  EXPECT_NE(a->position(3.3), c->position(3.3));
  EXPECT_EQ(a->maxFrequencyHz(), 10.0);
}

TEST(TablePrograms, CsvProfile) {
  const auto p = csvProfile("time_s,x_m\n0,0\n1,0.01\n2,0.03\n3,0.0\n", "p.csv");
  EXPECT_NEAR(p->position(1.0), 0.01, 1e-15);  // through the samples
  EXPECT_NEAR(p->position(2.0), 0.03, 1e-15);
  EXPECT_EQ(p->position(5.0), 0.0);  // at rest after the end
  EXPECT_EQ(p->velocity(-1.0), 0.0);
  checkDerivatives(*p);
  try {
    csvProfile("time_s,x_m\n0,0\n1,abc\n", "p.csv");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "p.csv:3: expected two numbers, time_s,x_m (got 1,abc)");
  }
  EXPECT_THROW(csvProfile("time_s,x_m\n0,0\n0,1\n", "p.csv"), std::invalid_argument);  // times must increase
  EXPECT_THROW(csvProfile("t,x\n0,0\n1,1\n", "p.csv"), std::invalid_argument);
}

// A text is parsed once and its samples shared by every program made from it (each model
// build makes one): a second program is the same function, one made from another text
// differs, and a text that fails is never kept: each call's error names its own source.
TEST(TablePrograms, CsvProfileFromTheSameTextIsTheSameProgram) {
  const std::string text = "time_s,x_m\n0,0\n0.5,0.02\n1.5,-0.01\n2,0\n";
  const auto a = csvProfile(text, "a.csv"), b = csvProfile(text, "b.csv");
  const auto c = csvProfile("time_s,x_m\n0,0\n0.5,0.03\n1.5,-0.01\n2,0\n", "c.csv");
  for (double t : {0.25, 0.7, 1.2, 1.9}) {
    EXPECT_EQ(a->position(t), b->position(t));
    EXPECT_EQ(a->acceleration(t), b->acceleration(t));
  }
  EXPECT_NE(a->position(0.5), c->position(0.5));
  for (const char* source : {"first.csv", "second.csv"}) {
    try {
      csvProfile("time_s,x_m\n0,0\n1,abc\n", source);
      FAIL() << source;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string(source) + ":3: expected two numbers, time_s,x_m (got 1,abc)");
    }
  }
}

TEST(TablePrograms, StrokeAndBandwidthChecks) {
  const ProgramCheck ok = checkProgram(*sineDwell(0.1, 2.0, 5.0));
  EXPECT_TRUE(ok.within_stroke);
  EXPECT_FALSE(ok.above_bandwidth);
  EXPECT_NEAR(ok.peak_displacement, 0.1, 1e-3);
  EXPECT_NEAR(ok.peak_acceleration, 0.1 * std::pow(2 * M_PI * 2.0, 2), 0.02);
  const ProgramCheck stroke = checkProgram(*sineDwell(0.2, 1.0, 5.0));
  EXPECT_FALSE(stroke.within_stroke);
  ASSERT_EQ(stroke.messages.size(), 1u);
  EXPECT_NE(stroke.messages[0].find("exceeds the table's +-0.15 m stroke"), std::string::npos);
  const ProgramCheck fast = checkProgram(*sineSweep(0.001, 1.0, 40.0, 20.0, true));
  EXPECT_TRUE(fast.above_bandwidth);
  EXPECT_TRUE(fast.within_stroke);
}

}  // namespace
}  // namespace mmv::facility

TEST(TablePrograms, SineRampStartsFromRestAndBecomesTheDwell) {
  const auto ramped = mmv::facility::sineDwell(0.002, 3.0, 10.0, 0.5);
  const auto plain = mmv::facility::sineDwell(0.002, 3.0, 10.0);
  EXPECT_EQ(ramped->position(0), 0.0);
  EXPECT_EQ(ramped->velocity(0), 0.0);  // no velocity jump (the plain dwell starts at A w)
  EXPECT_EQ(ramped->acceleration(0), 0.0);
  EXPECT_GT(plain->velocity(0), 0.03);
  // Velocity and acceleration are the derivatives of position (central differences).
  const double h = 1e-6;
  for (double t : {0.05, 0.2, 0.37, 0.49, 0.8}) {
    EXPECT_NEAR(ramped->velocity(t), (ramped->position(t + h) - ramped->position(t - h)) / (2 * h), 1e-7) << t;
    EXPECT_NEAR(ramped->acceleration(t), (ramped->velocity(t + h) - ramped->velocity(t - h)) / (2 * h), 1e-5) << t;
  }
  for (double t : {0.5, 0.7, 2.3}) {
    EXPECT_DOUBLE_EQ(ramped->position(t), plain->position(t));
    EXPECT_DOUBLE_EQ(ramped->acceleration(t), plain->acceleration(t));
  }
}
