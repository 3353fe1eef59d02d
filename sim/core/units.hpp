#pragma once
/// Units: SI inside, degrees and hertz only where a file or a table says so.

#include <cmath>

namespace mmv {

constexpr double kPi = M_PI;
constexpr double kDegToRad = M_PI / 180.0;  ///< rad per deg (files say angle_deg; radians inside).
constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kStandardGravity = 9.80665;  ///< m/s^2.

}  // namespace mmv
