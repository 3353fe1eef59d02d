#include "facility/slews.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace mmv::facility {

Slew makeSlew(SlewShape shape, double from, double to, double, const SlewLimits& lim) {
  if (!(lim.range > 0) || !(lim.max_rate > 0) || !(lim.max_acceleration > 0))
    throw std::invalid_argument("slew: range, rate and acceleration limits must be > 0");
  for (double a : {from, to})
    if (std::abs(a) > lim.range * (1 + 1e-12))
    {
      char what[160];
      std::snprintf(what, sizeof what, "slew: angle %.6g deg is outside the joint's +-%.6g deg range", a * 180 / M_PI,
                    lim.range * 180 / M_PI);
      throw std::invalid_argument(what);
    }
  Slew s;
  s.shape_ = shape;
  s.from_ = from;
  s.delta_ = to - from;
  const double d = std::abs(s.delta_);
  if (d == 0) return s;
  if (shape == SlewShape::Cycloidal) {
    // Shortest T with 2 d / T <= max_rate and 2 pi d / T^2 <= max_acceleration.
    s.duration_ = std::max(2 * d / lim.max_rate, std::sqrt(2 * M_PI * d / lim.max_acceleration));
  } else {
    s.accel_ = lim.max_acceleration;
    const double t_to_rate = lim.max_rate / s.accel_;
    if (s.accel_ * t_to_rate * t_to_rate >= d) {  // triangular: never reaches the rate limit
      s.accel_time_ = std::sqrt(d / s.accel_);
      s.cruise_rate_ = s.accel_ * s.accel_time_;
      s.duration_ = 2 * s.accel_time_;
    } else {
      s.accel_time_ = t_to_rate;
      s.cruise_rate_ = lim.max_rate;
      s.duration_ = 2 * t_to_rate + (d - s.accel_ * t_to_rate * t_to_rate) / lim.max_rate;
    }
  }
  return s;
}

Slew makeSpinUp(double from, double rate, double ramp) {
  if (!std::isfinite(rate) || rate == 0) throw std::invalid_argument("spin-up: the rate must be a non-zero number");
  if (!(ramp > 0) || !std::isfinite(ramp)) throw std::invalid_argument("spin-up: the ramp must be > 0 s (a step in rate has no acceleration to give)");
  Slew s;
  s.shape_ = SlewShape::SpinUp;
  s.from_ = from;
  s.cruise_rate_ = rate;
  s.duration_ = ramp;
  return s;
}

Slew makeAngleProgram(double from, std::shared_ptr<const TableProgram> angles, double scale, double range) {
  if (!angles) throw std::invalid_argument("angle program: no program");
  Slew s;
  s.shape_ = SlewShape::Program;
  s.from_ = from;
  s.program_ = std::move(angles);
  s.program_scale_ = scale;
  s.duration_ = s.program_->duration();
  const auto deg = [](double rad) { return rad * 180 / M_PI; };
  // Started from `from`: the samples' shift from their first (none where the scene's
  // angle is the program's first, which the reader requires; a held-angle study that
  // sets another angle moves the program with it, as it moves a slew's start).
  s.program_offset_ = from - scale * s.program_->position(0);
  // Every angle within the range, between the samples too (a cubic may overshoot them):
  // 20 points per period of the samples' Nyquist frequency, at least 2000.
  const double span = s.duration_;
  const int n = static_cast<int>(std::min(2e6, std::max(2000.0, std::ceil(20 * s.program_->maxFrequencyHz() * span) + 1)));
  for (int k = 0; k <= n; ++k) {
    const double t = span * k / n, a = s.program_offset_ + scale * s.program_->position(t);
    if (std::abs(a) > range * (1 + 1e-12)) {
      char what[200];
      std::snprintf(what, sizeof what, "angle program: %.6g deg at %.6g s is outside the joint's +-%.6g deg range", deg(a), t, deg(range));
      throw std::invalid_argument(what);
    }
    s.program_peak_angle_ = std::max(s.program_peak_angle_, std::abs(a));
    s.program_peak_rate_ = std::max(s.program_peak_rate_, std::abs(scale * s.program_->velocity(t)));
    s.program_peak_acceleration_ = std::max(s.program_peak_acceleration_, std::abs(scale * s.program_->acceleration(t)));
  }
  return s;
}

SlewState Slew::at(double t) const {
  if (shape_ == SlewShape::SpinUp) {
    const double W = cruise_rate_, T = duration_;
    if (t <= 0) return {from_, 0, 0};
    if (t >= T) return {from_ + W * (t - T / 2), W, 0};
    const double w = 2 * M_PI / T, c = T / (2 * M_PI);
    return {from_ + W / T * (t * t / 2 + c * c * (std::cos(w * t) - 1)), W / T * (t - c * std::sin(w * t)), W / T * (1 - std::cos(w * t))};
  }
  if (shape_ == SlewShape::Program)
    return {program_offset_ + program_scale_ * program_->position(t), program_scale_ * program_->velocity(t),
            program_scale_ * program_->acceleration(t)};
  const double sign = delta_ < 0 ? -1.0 : 1.0, d = std::abs(delta_);
  if (t <= 0 || duration_ == 0) return {from_, 0, 0};
  if (t >= duration_) return {from_ + delta_, 0, 0};
  if (shape_ == SlewShape::Cycloidal) {
    const double T = duration_, s = t / T, w = 2 * M_PI / T;
    return {from_ + delta_ * (s - std::sin(2 * M_PI * s) / (2 * M_PI)), delta_ / T * (1 - std::cos(w * t)),
            delta_ / T * w * std::sin(w * t)};
  }
  const double ta = accel_time_, T = duration_;
  double p, v, a;
  if (t < ta) {
    p = 0.5 * accel_ * t * t, v = accel_ * t, a = accel_;
  } else if (t <= T - ta) {
    p = 0.5 * accel_ * ta * ta + cruise_rate_ * (t - ta), v = cruise_rate_, a = 0;
  } else {
    const double r = T - t;
    p = d - 0.5 * accel_ * r * r, v = accel_ * r, a = -accel_;
  }
  return {from_ + sign * p, sign * v, sign * a};
}

double Slew::peakRate() const {
  if (shape_ == SlewShape::SpinUp) return std::abs(cruise_rate_);
  if (shape_ == SlewShape::Program) return program_peak_rate_;
  if (duration_ == 0) return 0;
  return shape_ == SlewShape::Cycloidal ? 2 * std::abs(delta_) / duration_ : cruise_rate_;
}

double Slew::largestAngle() const {
  if (shape_ == SlewShape::SpinUp) return INFINITY;
  if (shape_ == SlewShape::Program) return program_peak_angle_;
  return std::max(std::abs(from_), std::abs(from_ + delta_));
}

double Slew::bandHz() const {
  if (shape_ == SlewShape::Program) return program_->maxFrequencyHz();
  if (duration_ == 0 || (shape_ != SlewShape::SpinUp && delta_ == 0)) return 0;
  return shape_ == SlewShape::Trapezoidal ? INFINITY : 2 / duration_;
}

double Slew::peakAcceleration() const {
  if (shape_ == SlewShape::SpinUp) return 2 * std::abs(cruise_rate_) / duration_;
  if (shape_ == SlewShape::Program) return program_peak_acceleration_;
  if (duration_ == 0) return 0;
  return shape_ == SlewShape::Cycloidal ? 2 * M_PI * std::abs(delta_) / (duration_ * duration_) : accel_;
}

}  // namespace mmv::facility
