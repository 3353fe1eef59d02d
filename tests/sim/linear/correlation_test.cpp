// The correlation measures against closed forms, and mode pairing against cases where
// a greedy order matters.
#include "sim/linear/correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mmv {
namespace {

TEST(Correlation, MacIsScaleAndPhaseInvariantAndZeroForOrthogonalShapes) {
  Eigen::VectorXcd a(4), b(4);
  a << 1.0, -2.0, 0.5, 3.0;
  b = std::complex<double>(0.0, -2.5) * a;  // a complex mode: same shape, rotated and scaled
  EXPECT_NEAR(modalAssurance(a, b), 1.0, 1e-15);
  Eigen::VectorXcd c(4);
  c << 2.0, 1.0, 0.0, 0.0;  // a^T c = 0
  EXPECT_NEAR(modalAssurance(a, c), 0.0, 1e-15);
  // Closed form for a partly correlated pair: (a.d)^2 / (|a|^2 |d|^2).
  Eigen::VectorXcd d(4);
  d << 1.0, 0.0, 0.0, 0.0;
  EXPECT_NEAR(modalAssurance(a, d), 1.0 / a.squaredNorm(), 1e-15);
  // A zero shape has no direction: its MAC is undefined, not "uncorrelated" (before: 0).
  EXPECT_TRUE(std::isnan(modalAssurance(a, Eigen::VectorXcd::Zero(4))));
  EXPECT_TRUE(std::isnan(modalAssurance(Eigen::VectorXcd::Zero(4), Eigen::VectorXcd::Zero(4))));
}

// Pairing honours a window (the frequency window of correlate) and never pairs NaN.
TEST(Correlation, PairingStaysInsideTheWindowAndSkipsUndefinedMacs) {
  Eigen::MatrixXd mac(2, 2);
  mac << 0.99, 0.80,
         std::numeric_limits<double>::quiet_NaN(), 0.95;
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> window(2, 2);
  window << false, true,  // test 1's best MAC is outside its window
            true, true;
  const std::vector<ModePair> p = pairByMac(mac, 0.7, window);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].test, 1);
  EXPECT_EQ(p[0].model, 1);  // test 1 cannot take model 1 (test 2 has it, MAC 0.95 > 0.80)
}

TEST(Correlation, FracOfAScaledResponseIsOneAndOfAShiftedResonanceLess) {
  auto h = [](double f, double fn) {
    const double w = 2 * M_PI * f, wn = 2 * M_PI * fn;
    return std::complex<double>(1.0) / std::complex<double>(wn * wn - w * w, 2 * 0.02 * wn * w);
  };
  std::vector<std::complex<double>> a, b, c, d;
  for (int k = 1; k <= 400; ++k) {
    const double f = 0.05 * k;
    a.push_back(h(f, 5.0));
    b.push_back(3.0 * h(f, 5.0));
    c.push_back(h(f, 5.5));
    d.push_back(-h(f, 5.0));  // opposite sign: the same shape, FRAC ignores a constant factor
  }
  EXPECT_NEAR(frequencyResponseAssurance(a, b), 1.0, 1e-12);
  EXPECT_NEAR(frequencyResponseAssurance(a, d), 1.0, 1e-12);
  const double shifted = frequencyResponseAssurance(a, c);
  EXPECT_LT(shifted, 0.5);  // a 10 % shift of a 2 %-damped resonance: the peaks no longer overlap
  EXPECT_GT(shifted, 0.0);
}

TEST(Correlation, PairingTakesTheLargestMacFirstAndEachModeOnce) {
  Eigen::MatrixXd mac(3, 3);
  mac << 0.80, 0.95, 0.10,  // test 1 is closest to model 2 ...
         0.75, 0.90, 0.20,  // ... so test 2 cannot have model 2 and takes model 1
         0.05, 0.10, 0.65;  // below the threshold: no pair
  const std::vector<ModePair> p = pairByMac(mac, 0.7);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].test, 0);
  EXPECT_EQ(p[0].model, 1);
  EXPECT_EQ(p[1].test, 1);
  EXPECT_EQ(p[1].model, 0);
  EXPECT_NEAR(p[1].mac, 0.75, 1e-15);
}

}  // namespace
}  // namespace mmv
