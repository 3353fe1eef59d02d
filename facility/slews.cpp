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

SlewState Slew::at(double t) const {
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
  if (duration_ == 0) return 0;
  return shape_ == SlewShape::Cycloidal ? 2 * std::abs(delta_) / duration_ : cruise_rate_;
}

double Slew::peakAcceleration() const {
  if (duration_ == 0) return 0;
  return shape_ == SlewShape::Cycloidal ? 2 * M_PI * std::abs(delta_) / (duration_ * duration_) : accel_;
}

}  // namespace mmv::facility
