#include "facility/sensors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mmv::facility {
namespace {

TEST(Sensors, SaturationClipsAtRangeAndIsCounted) {
  Sensor gyro(rateGyroSpec(), 1000.0);
  const double range = 70 * M_PI / 180;
  int above = 0;
  for (int k = 0; k < 2000; ++k) {
    const double truth = 2 * range * std::sin(2 * M_PI * 1.0 * k / 1000.0);  // twice the range, 1 Hz
    const double y = gyro.sample(truth);
    EXPECT_LE(std::abs(y), range + 1e-12);
    above += std::abs(truth) > range;
  }
  // The 100 Hz low-pass barely touches 1 Hz, so the clipped samples are those above range.
  EXPECT_NEAR(gyro.saturatedSamples(), above, 4);
  EXPECT_GT(gyro.saturatedSamples(), 0);
}

TEST(Sensors, QuantizationStep) {
  SensorSpec s = encoderSpec();
  Sensor enc(s, 500.0);
  std::vector<double> seen;
  for (int k = 0; k < 500; ++k) {
    const double y = enc.sample(2e-7 * k);  // a slow ramp: one step about every 24 samples
    const double steps = y / s.resolution;
    EXPECT_NEAR(steps, std::round(steps), 1e-6);  // every output is a whole number of steps
    seen.push_back(y);
  }
  // The smallest non-zero change between samples is one step.
  double smallest = INFINITY;
  for (std::size_t k = 1; k < seen.size(); ++k)
    if (seen[k] != seen[k - 1]) smallest = std::min(smallest, std::abs(seen[k] - seen[k - 1]));
  EXPECT_NEAR(smallest / s.resolution, 1.0, 1e-6);
  EXPECT_EQ(enc.saturatedSamples(), 0);
}

// White noise: mean 0 and standard deviation sigma within the sampling bounds for N
// samples (5 standard errors, so a pass is not luck), reproducible for a seed and
// different for another.
TEST(Sensors, NoiseStatistics) {
  SensorSpec s{"test", 100.0, 0.0, 0, 0, 0.02, 42};
  const int n = 200000;
  auto run = [&](std::uint64_t seed) {
    s.seed = seed;
    Sensor sensor(s, 1000.0);
    std::vector<double> v(n);
    for (double& x : v) x = sensor.sample(0.0);
    return v;
  };
  const std::vector<double> a = run(42), b = run(42), c = run(43);
  double mean = 0, var = 0;
  for (double x : a) mean += x / n;
  for (double x : a) var += (x - mean) * (x - mean) / (n - 1);
  EXPECT_NEAR(mean, 0.0, 5 * 0.02 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(var), 0.02, 5 * 0.02 / std::sqrt(2.0 * n));
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

// Band limits: a sine's steady-state amplitude through the accelerometer's 0.1-50 Hz
// band equals the filters' analytic gain (1 % tolerance: the amplitude is read from
// the last cycles' extremes, sampled at 2 kHz), and the corners are -3 dB.
TEST(Sensors, BandLimitsFollowTheButterworthGain) {
  SensorSpec s = accelerometerSpec();
  s.resolution = 0;
  const double fs = 2000.0;
  for (double f : {1.0, 10.0, 50.0, 200.0}) {
    Sensor acc(s, fs);
    double peak = 0;
    const int n = static_cast<int>(40 * fs / std::min(f, 10.0));
    for (int k = 0; k < n; ++k) {
      const double y = acc.sample(std::sin(2 * M_PI * f * k / fs));
      if (k > n - static_cast<int>(4 * fs / f)) peak = std::max(peak, std::abs(y));
    }
    EXPECT_NEAR(peak / acc.bandGain(f), 1.0, 0.01) << f << " Hz";
  }
  Sensor acc(s, fs);
  EXPECT_NEAR(acc.bandGain(50.0), std::sqrt(0.5), 0.01);   // low-pass corner (times a tiny high-pass loss)
  EXPECT_NEAR(acc.bandGain(0.1), std::sqrt(0.5), 0.01);    // high-pass corner
  EXPECT_LT(acc.bandGain(500.0), 0.02);
}

TEST(Sensors, BadSpecsAreRefused) {
  SensorSpec s = rateGyroSpec();
  EXPECT_THROW(Sensor(s, 150.0), std::invalid_argument);  // 100 Hz corner above Nyquist
  s.range = 0;
  EXPECT_THROW(Sensor(s, 1000.0), std::invalid_argument);
}

}  // namespace
}  // namespace mmv::facility
