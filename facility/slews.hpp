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
///
/// Two programs are not moves between two angles:
///
///   spin-up:     Kane, Ryan and Banerjee's profile (J. Guidance 10(2), 1987; Simo and
///                Vu-Quoc 1986): theta = theta0 + (W/T) (t^2/2 + (T/2pi)^2 (cos(2pi t/T) - 1))
///                for t < T, then theta0 + W (t - T/2): from rest to the rate W in T with
///                the acceleration (W/T)(1 - cos(2pi t/T)) smooth at both ends, then
///                turning at W for as long as the run lasts (past any angle);
///   program:     angles read from a CSV (time_s,angle_deg), piecewise cubic Hermite
///                through the samples and at rest before and after (csvProfile).

#include <memory>
#include <string>

#include "facility/table_programs.hpp"

namespace mmv::facility {

struct SlewLimits {
  double range = 45 * 3.14159265358979323846 / 180;  ///< rad, +- about zero.
  double max_rate = 70 * 3.14159265358979323846 / 180;  ///< rad/s.
  double max_acceleration = 200 * 3.14159265358979323846 / 180;  ///< rad/s^2.
};

enum class SlewShape { Cycloidal, Trapezoidal, SpinUp, Program };

struct SlewState {
  double angle = 0, rate = 0, acceleration = 0;  ///< rad, rad/s, rad/s^2.
};

class Slew {
 public:
  /// Before 0: at rest at the start; after duration(): at rest at the end (a spin-up:
  /// turning at its rate).
  SlewState at(double t) const;
  double duration() const { return duration_; }  ///< a spin-up's: its ramp
  double peakRate() const;
  double peakAcceleration() const;
  /// The highest frequency its acceleration carries (Hz): a cycloidal move's or a
  /// spin-up's main lobe, 2 / duration (its side lobes fall as 1 / f^2, the acceleration
  /// being continuous); an angle program's samples' Nyquist frequency; a trapezoidal
  /// move's acceleration steps carry every frequency (infinity); 0 for no move.
  double bandHz() const;
  /// The largest |angle| it reaches (rad): a move's larger end, an angle program's
  /// largest (between its samples too), a spin-up's none (infinity).
  double largestAngle() const;
  /// An angle program's first angle as written (rad), before it was moved to start at
  /// the joint's angle; the start angle for the other shapes.
  double writtenStart() const { return from_ - program_offset_; }
  SlewShape shape() const { return shape_; }

 private:
  friend Slew makeSlew(SlewShape, double, double, double, const SlewLimits&);
  friend Slew makeSpinUp(double, double, double);
  friend Slew makeAngleProgram(double, std::shared_ptr<const TableProgram>, double, double);
  SlewShape shape_ = SlewShape::Cycloidal;
  double from_ = 0, delta_ = 0, duration_ = 0;
  double accel_time_ = 0, accel_ = 0, cruise_rate_ = 0;  ///< trapezoidal; spin-up: cruise_rate_ is W
  std::shared_ptr<const TableProgram> program_;  ///< program: its samples as read
  double program_scale_ = 1;                      ///< program: rad per unit read
  double program_offset_ = 0;                     ///< program: rad added (its start moved to `from_`)
  double program_peak_rate_ = 0, program_peak_acceleration_ = 0, program_peak_angle_ = 0;
};

/// A slew from `from` to `to` (rad) starting at `start_time` (s, informational: at() is
/// relative to the start). Throws std::invalid_argument naming the limit for an end
/// outside +-range or non-positive limits.
Slew makeSlew(SlewShape shape, double from, double to, double start_time, const SlewLimits& limits);

/// The spin-up from `from` (rad) to the rate `rate` (rad/s, either sign) over `ramp` s.
/// Throws std::invalid_argument for a zero or non-finite rate or a ramp that is not > 0.
Slew makeSpinUp(double from, double rate, double ramp);

/// An angle program: `angles` (csvProfile's, in units of `scale` rad: pi/180 for
/// time_s,angle_deg) from t = 0, moved to start at `from` (the scene's reader requires
/// the first angle to be the joint's own, so a run follows the samples as written).
/// Every angle, between the samples too, within +-range (infinity: none). Throws
/// std::invalid_argument naming the angle and the time.
Slew makeAngleProgram(double from, std::shared_ptr<const TableProgram> angles, double scale, double range);

}  // namespace mmv::facility
