#include "facility/sensors.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace mmv::facility {

namespace {
constexpr double kDeg = M_PI / 180.0;
constexpr double kG = 9.80665;
}  // namespace

SensorSpec encoderSpec() { return {"encoder", 45 * kDeg, kDeg / 3600.0, 0, 0, 0, 1}; }
SensorSpec rateGyroSpec() { return {"rate_gyro", 70 * kDeg, 25e-3 * kDeg, 0, 100.0, 0, 1}; }
SensorSpec accelerometerSpec() { return {"accelerometer", 5 * kG, 0.001 * kG, 0.1, 50.0, 0, 1}; }
SensorSpec strainSpec() { return {"strain", 1e-3, 1e-8, 0.1, 50.0, 0, 1}; }

Biquad::Biquad(bool high_pass, double fc, double fs) : fs_(fs) {
  // Bilinear transform of H(s) = 1 / (s^2/wc^2 + sqrt(2) s/wc + 1) (or s^2/wc^2 over it),
  // prewarped so the corner is exact.
  const double k = std::tan(M_PI * fc / fs), q = std::sqrt(2.0);
  const double norm = 1.0 / (1.0 + q * k + k * k);
  if (high_pass) {
    b0_ = norm;
    b1_ = -2 * norm;
    b2_ = norm;
  } else {
    b0_ = k * k * norm;
    b1_ = 2 * b0_;
    b2_ = b0_;
  }
  a1_ = 2 * (k * k - 1) * norm;
  a2_ = (1 - q * k + k * k) * norm;
}

double Biquad::step(double x) {
  const double y = b0_ * x + b1_ * x1_ + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
  x2_ = x1_;
  x1_ = x;
  y2_ = y1_;
  y1_ = y;
  return y;
}

SensorSpec sensorSpecFor(const std::string& type) {
  return type == "encoder"     ? encoderSpec()
         : type == "rate_gyro" ? rateGyroSpec()
         : type == "strain"    ? strainSpec()
                               : accelerometerSpec();
}

double Biquad::prime(double x) {
  // The DC gain: (b0 + b1 + b2) / (1 + a1 + a2), 1 for a low-pass, 0 for a high-pass.
  const double y = (b0_ + b1_ + b2_) / (1.0 + a1_ + a2_) * x;
  x1_ = x2_ = x;
  y1_ = y2_ = y;
  return y;
}

double Biquad::magnitude(double f) const {
  const std::complex<double> z1 = std::exp(std::complex<double>(0, -2 * M_PI * f / fs_)), z2 = z1 * z1;
  return std::abs((b0_ + b1_ * z1 + b2_ * z2) / (1.0 + a1_ * z1 + a2_ * z2));
}

Sensor::Sensor(const SensorSpec& s, double fs) : spec_(s), rng_(s.seed) {
  if (!(s.range > 0) || s.resolution < 0 || s.noise_sigma < 0 || s.low_cut_hz < 0 || s.high_cut_hz < 0 || !(fs > 0))
    throw std::invalid_argument("sensor " + s.kind + ": range, sample rate > 0 and resolution, noise, corners >= 0 required");
  if (s.high_cut_hz >= 0.5 * fs || s.low_cut_hz >= 0.5 * fs)
    throw std::invalid_argument("sensor " + s.kind + ": a band corner at or above the Nyquist frequency of " +
                                std::to_string(0.5 * fs) + " Hz");
  if (s.high_cut_hz > 0) {
    low_ = Biquad(false, s.high_cut_hz, fs);
    has_low_ = true;
  }
  if (s.low_cut_hz > 0) {
    high_ = Biquad(true, s.low_cut_hz, fs);
    has_high_ = true;
  }
}

double Sensor::sample(double truth) {
  if (count_++ == 0) {  // on long before the run: its filters rest at the first value
    double dc = truth;
    if (has_high_) dc = high_.prime(dc);
    if (has_low_) low_.prime(dc);
  }
  double y = truth;
  if (has_high_) y = high_.step(y);
  if (has_low_) y = low_.step(y);
  if (spec_.noise_sigma > 0) y += spec_.noise_sigma * noise_(rng_);
  if (std::abs(y) > spec_.range) {
    ++saturated_;
    y = std::copysign(spec_.range, y);
  }
  if (spec_.resolution > 0) y = spec_.resolution * std::round(y / spec_.resolution);
  return y;
}

double Sensor::bandGain(double f) const {
  return (has_low_ ? low_.magnitude(f) : 1.0) * (has_high_ ? high_.magnitude(f) : 1.0);
}

}  // namespace mmv::facility
