#pragma once
/// Sensor models of the Ground Test Facility (report, "Measurement and
/// Instrumentation Specifications"; docs/sources.md section 2). A sensor turns the true
/// value of what it measures, sampled at a fixed rate, into what the data system
/// records:
///
///   band limits  ->  + noise (seeded, Gaussian)  ->  range saturation  ->  quantization
///
/// A sensor is on long before the run: its filters start at rest under the first
/// sample's value (an accelerometer's high-pass sees gravity as steady, not as a step).
/// Band limits are second-order Butterworth sections (bilinear transform with
/// prewarping at the corner): a low-pass at the upper band edge and, where the sensor
/// has one (accelerometers: 0.1 Hz), a high-pass at the lower edge. Saturation clips
/// at +-range and is counted; quantization rounds to the resolution. Units are SI
/// (rad, rad/s, m/s^2); the defaults are the report's specifications.

#include <cstdint>
#include <random>
#include <string>

namespace mmv::facility {

struct SensorSpec {
  std::string kind;          ///< "encoder", "rate_gyro", "accelerometer", "strain".
  double range = 0;          ///< full scale, +-, in the measured unit (> 0).
  double resolution = 0;     ///< quantization step (>= 0; 0: none).
  double low_cut_hz = 0;     ///< high-pass corner (0: none).
  double high_cut_hz = 0;    ///< low-pass corner (0: none).
  double noise_sigma = 0;    ///< standard deviation of white noise, measured unit.
  std::uint64_t seed = 1;    ///< noise generator seed (runs are reproducible).
};

/// Incremental optical encoder: +-45 deg range, 1 arcsecond resolution (the report
/// asks for arcminutes to arcseconds); its rate limit (70 deg/s) is checked by the
/// torquer slews, not here.
SensorSpec encoderSpec();
/// Rate gyro: 25e-3 deg/s resolution, +-70 deg/s range, bandwidth above 50 Hz (100 Hz
/// low-pass here).
SensorSpec rateGyroSpec();
/// Accelerometer: 0.001 g resolution, +-5 g range, 0.1-50 Hz band.
SensorSpec accelerometerSpec();

/// Piezoelectric film (or strain gauge) reading the mean bending strain over its span,
/// m/m: the report proposes the film on link 3 without figures, so all of these are
/// ASSUMED: +-1e-3 (1000 microstrain) range, 1e-8 resolution, and a film's charge
/// amplifier band, 0.1-50 Hz (a film does not hold a static strain; a gauge's
/// instrument sets band_hz: [0, ...]).
SensorSpec strainSpec();

/// The spec of a sensor type: "encoder", "rate_gyro", "strain", else the accelerometer's.
SensorSpec sensorSpecFor(const std::string& type);

/// A second-order Butterworth section, low- or high-pass, at sample rate fs.
class Biquad {
 public:
  Biquad() = default;
  Biquad(bool high_pass, double corner_hz, double sample_hz);
  double step(double x);
  /// Sets the section at rest under a constant input x (as if it had seen x forever);
  /// returns its output then (x times the DC gain).
  double prime(double x);
  /// |H(e^{i w T})| at frequency f (Hz).
  double magnitude(double f_hz) const;

 private:
  double b0_ = 1, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0, fs_ = 1;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

class Sensor {
 public:
  /// Throws std::invalid_argument for a non-physical spec or corners above Nyquist.
  Sensor(const SensorSpec& spec, double sample_hz);
  /// The recorded value for the next sample of the true signal.
  double sample(double truth);
  int saturatedSamples() const { return saturated_; }
  int samples() const { return count_; }
  const SensorSpec& spec() const { return spec_; }
  /// Steady-state gain of the band limits at f (Hz): what a sine of that frequency keeps.
  double bandGain(double f_hz) const;

 private:
  SensorSpec spec_;
  Biquad low_, high_;
  bool has_low_ = false, has_high_ = false;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_{0.0, 1.0};
  int saturated_ = 0, count_ = 0;
};

}  // namespace mmv::facility
