#pragma once
/// Commanded joint-angle profiles for the torquers (report: large angular
/// displacements of +-45 deg at up to 70 deg/s, direct-drive torquers). A profile is
/// angle, rate and acceleration as functions of time, reaching its end at rest.
///
///   cycloidal:   theta = theta0 + D (s - sin(2 pi s) / (2 pi)),  s = t/T:
///                peak rate 2 D / T, peak acceleration 2 pi D / T^2, smooth acceleration;
///   trapezoidal: constant acceleration a, cruise at the rate limit, constant
///                deceleration (triangular when the move is too short to cruise).
///
/// makeSlew picks the shortest duration that respects the rate and acceleration
/// limits, and refuses a move outside the joint's range.

#include <string>

namespace mmv::facility {

struct SlewLimits {
  double range = 45 * 3.14159265358979323846 / 180;  ///< rad, +- about zero.
  double max_rate = 70 * 3.14159265358979323846 / 180;  ///< rad/s.
  double max_acceleration = 200 * 3.14159265358979323846 / 180;  ///< rad/s^2.
};

enum class SlewShape { Cycloidal, Trapezoidal };

struct SlewState {
  double angle = 0, rate = 0, acceleration = 0;  ///< rad, rad/s, rad/s^2.
};

class Slew {
 public:
  SlewState at(double t) const;  ///< before 0: at rest at the start; after duration(): at rest at the end.
  double duration() const { return duration_; }
  double peakRate() const;
  double peakAcceleration() const;
  SlewShape shape() const { return shape_; }

 private:
  friend Slew makeSlew(SlewShape, double, double, double, const SlewLimits&);
  SlewShape shape_ = SlewShape::Cycloidal;
  double from_ = 0, delta_ = 0, duration_ = 0;
  double accel_time_ = 0, accel_ = 0, cruise_rate_ = 0;  ///< trapezoidal
};

/// A slew from `from` to `to` (rad) starting at `start_time` (s, informational: at() is
/// relative to the start). Throws std::invalid_argument naming the limit for an end
/// outside +-range or non-positive limits.
Slew makeSlew(SlewShape shape, double from, double to, double start_time, const SlewLimits& limits);

}  // namespace mmv::facility
